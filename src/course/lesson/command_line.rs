//! Reading a lesson's flags from the command line: negative values, a writable
//! `--out`, and the list of flags that errors name.

use std::ffi::OsString;
use std::path::{Path, PathBuf};

/// The long flags of the command [`parse`] read (`--width`), to name them in errors.
static FLAGS: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();

/// The lesson's flag for the parameter `param` (`--screen-distance` for `screen
/// distance`), if the command [`parse`] read has one of that name.
pub(super) fn typed_flag(param: &str) -> Option<&'static str> {
    let flag = format!("--{}", param.replace(' ', "-"));
    FLAGS
        .get()?
        .iter()
        .find(|f| **f == flag)
        .map(String::as_str)
}

/// The lesson's flags from the command line, checked before any work:
///
/// - a flag's value may start with a minus sign (`--point -1,-2,-3`,
///   `--angle -inf`): it is the value, never taken for another flag;
/// - `--out` must be a folder this program can write to (it is created if missing),
///   so that a bad folder is reported before minutes of rendering, not after.
///
/// On bad input it prints a one-line error naming the flag and exits with code 2,
/// as clap does.
pub fn parse<A: clap::Parser>() -> A {
    let command = A::command();
    let flags = command.get_arguments().filter_map(|a| a.get_long());
    let _ = FLAGS.set(flags.map(|long| format!("--{long}")).collect());
    let args = negative_values(&command, std::env::args_os().collect());
    let matches = command.get_matches_from(args);
    if let Some(out) = matches.try_get_one::<PathBuf>("out").ok().flatten()
        && let Err(message) = writable(out)
    {
        eprintln!("error: --out {}: {message}", out.display());
        std::process::exit(2);
    }
    A::from_arg_matches(&matches).unwrap_or_else(|e| e.exit())
}

/// The command line with `--flag -value` written `--flag=-value` wherever `--flag`
/// takes a value and the next word starts with one minus sign (`-1,-2,-3`, `-inf`),
/// so that clap reads it as the value and not as an unknown short flag.
fn negative_values(command: &clap::Command, args: Vec<OsString>) -> Vec<OsString> {
    let takes_value = |word: &str| {
        word.strip_prefix("--").is_some_and(|name| {
            command
                .get_arguments()
                .any(|a| a.get_long() == Some(name) && a.get_action().takes_values())
        })
    };
    let mut out: Vec<OsString> = Vec::with_capacity(args.len());
    let mut words = args.into_iter().peekable();
    while let Some(word) = words.next() {
        let next_is_negative = words
            .peek()
            .and_then(|n| n.to_str())
            .is_some_and(|n| n.starts_with('-') && !n.starts_with("--") && n.len() > 1);
        match word.to_str() {
            Some(flag) if takes_value(flag) && next_is_negative => {
                let mut joined = OsString::from(flag);
                joined.push("=");
                joined.push(words.next().unwrap_or_default());
                out.push(joined);
            }
            _ => out.push(word),
        }
    }
    out
}

/// `Ok` if `dir` is (or can be made) a folder in which a file can be written.
fn writable(dir: &Path) -> std::result::Result<(), String> {
    if dir.as_os_str().is_empty() {
        return Err("must name a folder".to_string());
    }
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("cannot create the folder ({e})"))?;
    if !dir.is_dir() {
        return Err("is not a folder".to_string());
    }
    tempfile::Builder::new()
        .prefix(".write-test")
        .tempfile_in(dir)
        .map(drop)
        .map_err(|e| format!("cannot write in it ({e})"))
}
