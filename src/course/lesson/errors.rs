//! The renderer's errors as the user typed them: a parameter that is one of the
//! lesson's flags is written as the flag.

use super::command_line::typed_flag;
use crate::error::Error;

/// The renderer's error `e` as the user typed it: where the parameter it names is
/// one of the lesson's flags (`screen distance` for `--screen-distance`), the flag
/// in its place, so that "screen distance must ..." reads "--screen-distance must
/// ...". See [`typed`].
pub fn as_typed(e: &Error) -> String {
    typed(e, typed_flag)
}

/// [`as_typed`] with `flag_for`, the lesson's flag for a parameter's name. Matched
/// on the error's fields, never on its text: an error with a `param` field gets the
/// flag in that field; the others (files, pixels, triangles) name no flag and stay
/// as they are.
fn typed(e: &Error, flag_for: impl Fn(&str) -> Option<&'static str>) -> String {
    let mut typed = e.clone();
    if let Some(param) = typed.param_field()
        && let Some(flag) = flag_for(param)
    {
        *param = flag;
    }
    typed.to_string()
}

/// For `map_err`: an error reading the file given after `flag` (`--mesh`) names the
/// flag too: "--mesh torus.obj, line 3: ...".
pub fn flag(flag: &'static str) -> impl Fn(Error) -> Error {
    move |e| match e {
        Error::Obj {
            path,
            line,
            message,
        } => Error::Obj {
            path: format!("{flag} {path}"),
            line,
            message,
        },
        Error::Io { path, message } => Error::Io {
            path: format!("{flag} {path}"),
            message,
        },
        Error::Invalid { reason, .. } => Error::Invalid {
            param: flag,
            reason,
        },
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A lesson with the flags `--screen-distance`, `--up` and `--threads`.
    fn flag_for(param: &str) -> Option<&'static str> {
        ["--screen-distance", "--up", "--threads"]
            .into_iter()
            .find(|flag| flag[2..] == param.replace(' ', "-"))
    }

    #[test]
    fn an_error_names_the_flag_the_user_typed() {
        let typed = |e: Error| typed(&e, flag_for);
        let distance = Error::NotPositive {
            param: "screen distance",
            value: -1.0,
        };
        assert_eq!(
            typed(distance),
            "--screen-distance must be greater than 0 (got -1)"
        );
        assert_eq!(
            typed(Error::UpParallelToDirection { param: "up" }),
            "--up must not be parallel to direction: no camera frame can be built"
        );
        let pool = Error::ThreadPool {
            param: "threads",
            threads: 3,
            message: "no".into(),
        };
        assert_eq!(
            typed(pool),
            "--threads: could not start 3 worker threads (no)"
        );
        // A parameter that is no flag of the lesson, and an error that names none.
        let focus = Error::NotFinite { param: "focus" };
        assert_eq!(typed(focus), "focus must be a finite number");
        let pixel = Error::NonFinitePixel { x: 1, y: 2 };
        assert_eq!(typed(pixel.clone()), pixel.to_string());
    }
}
