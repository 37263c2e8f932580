//! What every lesson's example shares, one job per file: reading its flags
//! ([`command_line`]), checking their values and running a lesson that renders
//! images ([`budget`](mod@budget)), where its files go and what it prints ([`output`]),
//! Ctrl-C ([`interrupt`]), and the renderer's errors written with the flags the user
//! typed ([`errors`]). Bad input is reported in one line on stderr with exit code 2,
//! never a panic.

pub mod budget;
pub mod command_line;
pub mod errors;
pub mod interrupt;
pub mod output;

use std::process::ExitCode;

use crate::course::failure::{Failure, LessonResult};

pub use budget::{CheckedImage, ImageFlags, budget, extent};
pub use command_line::parse;
pub use errors::flag;
pub use interrupt::{check_interrupt, stop_on_ctrl_c};
pub use output::{Output, print, wrote};

/// Runs a lesson's body: on error, prints `error: ...` and exits with code 2; on
/// Ctrl-C ([`check_interrupt`]) with code 130. In the body, `?` turns the
/// renderer's errors into a [`Failure`].
pub fn run(body: impl FnOnce() -> LessonResult<()>) -> ExitCode {
    match body() {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Interrupted) => {
            eprintln!("interrupted (Ctrl-C): every file written so far is whole");
            ExitCode::from(130)
        }
        Err(Failure::Render(e)) => {
            eprintln!("error: {}", errors::as_typed(&e));
            ExitCode::from(2)
        }
        Err(other) => {
            eprintln!("error: {other}");
            ExitCode::from(2)
        }
    }
}
