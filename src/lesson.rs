//! What every lesson's example shares: where it writes its pictures, and how it
//! reports bad input (one line on stderr, exit code 2, never a panic).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::error::Result;

/// The flag every lesson accepts: the folder its images go to.
#[derive(clap::Args, Clone, Debug)]
pub struct Output {
    /// Folder for the lesson's PNG files.
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
}

impl Output {
    /// The path of the file `name` in the output folder.
    pub fn file(&self, name: &str) -> PathBuf {
        self.out.join(name)
    }
}

/// Runs a lesson's body: on error, prints `error: ...` and exits with code 2.
pub fn run(body: impl FnOnce() -> Result<()>) -> ExitCode {
    match body() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

/// Prints where a file was written.
pub fn wrote(path: &Path) {
    println!("wrote {}", path.display());
}
