//! The renderer's errors as the user typed them: a parameter that is one of the
//! lesson's flags is written as the flag.

use super::command_line::typed_flag;
use crate::error::{Error, Problem};

/// The renderer's error `e` as the user typed it: where the parameter it names is
/// one of the lesson's flags (`screen distance` for `--screen-distance`), the flag
/// in its place, so that "screen distance must ..." reads "--screen-distance must
/// ...". See `typed`.
pub fn as_typed(e: &Error) -> String {
    typed(e, typed_flag)
}

/// [`as_typed`] with `flag_for`, the lesson's flag for a parameter's name. Read
/// off the error's fields, never its text, and the error itself is left as it is:
/// a value or a request whose parameter is a flag reads "{flag} {what}"; the others
/// (files, and parameters that are no flag) read as the renderer wrote them.
fn typed(e: &Error, flag_for: impl Fn(&str) -> Option<&'static str>) -> String {
    match e {
        Error::Value { param, .. } | Error::Machine { param, .. } => {
            match flag_for(param) {
                Some(flag) => format!("{flag} {}", e.what()),
                None => e.to_string(),
            }
        }
        Error::File { .. } => e.to_string(),
    }
}

/// For `map_err`: an error reading the file given after `flag` (`--mesh`) names the
/// flag too: "--mesh torus.obj, line 3: ...".
pub fn flag(flag: &'static str) -> impl Fn(Error) -> Error {
    move |e| match e {
        Error::File {
            path,
            line,
            message,
        } => Error::File {
            path: format!("{flag} {path}"),
            line,
            message,
        },
        Error::Value {
            problem: Problem::Invalid { reason },
            ..
        } => Error::Value {
            param: flag,
            problem: Problem::Invalid { reason },
        },
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Shortfall;

    /// A lesson with the flags `--screen-distance`, `--up` and `--threads`.
    fn flag_for(param: &str) -> Option<&'static str> {
        ["--screen-distance", "--up", "--threads"]
            .into_iter()
            .find(|flag| flag[2..] == param.replace(' ', "-"))
    }

    #[test]
    fn an_error_names_the_flag_the_user_typed() {
        let typed = |e: Error| typed(&e, flag_for);
        let distance = Error::Value {
            param: "screen distance",
            problem: Problem::NotPositive { value: -1.0 },
        };
        assert_eq!(
            typed(distance),
            "--screen-distance must be greater than 0 (got -1)"
        );
        assert_eq!(
            typed(Error::Value {
                param: "up",
                problem: Problem::UpParallelToDirection
            }),
            "--up must not be parallel to direction: no camera frame can be built"
        );
        let pool = Error::Machine {
            param: "threads",
            shortfall: Shortfall::ThreadPool {
                threads: 3,
                message: "no".into(),
            },
        };
        assert_eq!(
            typed(pool),
            "--threads asks for 3 worker threads, which the system would not start (no)"
        );
        // A parameter that is no flag of the lesson, and an error that names none.
        let focus = Error::Value {
            param: "focus",
            problem: Problem::NotFinite,
        };
        assert_eq!(typed(focus), "focus must be a finite number");
        let pixel = Error::Value {
            param: "pixel",
            problem: Problem::NonFinitePixel { x: 1, y: 2 },
        };
        assert_eq!(typed(pixel.clone()), pixel.to_string());
    }
}
