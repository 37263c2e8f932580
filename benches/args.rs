//! The command lines of the two programs `scripts/instructions-per-ray` runs under
//! callgrind (`one-frame` and `bvh-frame`): positional numbers, and one line out.

use std::process::ExitCode;

/// Positional argument `i` as a whole number from 1 to 100 000, `default` if it
/// is not there; the error names it `name`.
pub fn number(
    args: &[String],
    i: usize,
    name: &str,
    default: u32,
) -> Result<u32, String> {
    match args.get(i) {
        None => Ok(default),
        Some(s) => s
            .parse()
            .ok()
            .filter(|&n| (1..=100_000).contains(&n))
            .ok_or(format!(
                "{name} must be a whole number from 1 to 100000, not '{s}'"
            )),
    }
}

/// Runs `run` on the program's arguments: its line on standard output and exit
/// code 0, or its error after `program: ` on standard error and exit code 2.
pub fn main(
    program: &str,
    run: impl FnOnce(Vec<String>) -> Result<String, String>,
) -> ExitCode {
    match run(std::env::args().skip(1).collect()) {
        Ok(line) => {
            println!("{line}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{program}: {e}");
            ExitCode::from(2)
        }
    }
}
