//! Ctrl-C: a long lesson stops after its current step and keeps every file it has
//! written whole.

use crate::course::failure::{Failure, LessonResult};

/// Set by Ctrl-C once [`stop_on_ctrl_c`] has been called.
static INTERRUPTED: std::sync::atomic::AtomicBool =
    std::sync::atomic::AtomicBool::new(false);

/// From now on Ctrl-C does not kill the lesson: it asks it to stop at the next
/// [`check_interrupt`], so that a long render ends with every finished image saved
/// (each written whole, never half) and says which are complete. For lessons whose
/// work comes in steps (lesson 10's passes, lesson 11's charts).
pub fn stop_on_ctrl_c() {
    let _ = ctrlc::set_handler(|| {
        INTERRUPTED.store(true, std::sync::atomic::Ordering::SeqCst);
        eprintln!("\nCtrl-C: stopping after the current step, keeping what is done");
    });
}

/// `Err(Failure::Interrupted)` once Ctrl-C was pressed (see [`stop_on_ctrl_c`]);
/// [`run`](super::run) then exits with code 130, the shell's code for an interrupt.
pub fn check_interrupt() -> LessonResult<()> {
    if INTERRUPTED.load(std::sync::atomic::Ordering::SeqCst) {
        Err(Failure::Interrupted)
    } else {
        Ok(())
    }
}
