//! What a long step shows while it runs: a bar or a spinner on stderr (indicatif).
//! indicatif draws nothing when stderr is not a terminal, so tests and pipes see
//! nothing; small work gets no bar at all, so a quick run does not flicker.

use indicatif::{ProgressBar, ProgressStyle};

/// Files smaller than this are read without a bar.
pub const PROGRESS_BYTES: u64 = 8 << 20;

/// A bar counting the bytes of a file of `total` bytes as they are read (wrap the
/// reader with [`ProgressBar::wrap_read`]); hidden below [`PROGRESS_BYTES`].
pub fn bytes(total: u64) -> ProgressBar {
    if total < PROGRESS_BYTES {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(total);
    let template = "{bar:40} {bytes}/{total_bytes} read, {eta} left";
    if let Ok(style) = ProgressStyle::with_template(template) {
        bar.set_style(style);
    }
    bar
}

/// Runs `work` under a spinner that says `message` and the time so far; the spinner
/// is cleared when the work ends. For steps that cannot count their progress (a
/// BVH build, a subdivision).
pub fn spinner<T>(message: String, work: impl FnOnce() -> T) -> T {
    let bar = ProgressBar::new_spinner();
    if let Ok(style) = ProgressStyle::with_template("{spinner} {msg} ({elapsed})") {
        bar.set_style(style);
    }
    bar.set_message(message);
    bar.enable_steady_tick(std::time::Duration::from_millis(100));
    let result = work();
    bar.finish_and_clear();
    result
}
