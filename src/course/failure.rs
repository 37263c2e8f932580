//! What can stop a lesson that is not the renderer's business: a student's exercise
//! that does not pass, Ctrl-C, a name on the command line that matches nothing. The
//! renderer's own errors ([`crate::Error`]) say what went wrong in rendering; this
//! type carries them too, so that a lesson's body can use `?` on both.

use std::fmt;

/// Why a lesson stopped.
#[derive(Clone, Debug, PartialEq)]
pub enum Failure {
    /// The renderer refused (its error names the parameter at fault).
    Render(crate::Error),
    /// A student's coding exercise did not pass its check (the report says why).
    Exercise {
        /// The check's report.
        report: String,
    },
    /// The user pressed Ctrl-C; the work finished so far was kept.
    Interrupted,
    /// A name given for the flag `param` matches none of the `choices`.
    NoMatch {
        /// The flag.
        param: &'static str,
        /// The name given.
        value: String,
        /// The names it may take.
        choices: Vec<String>,
    },
}

/// What a lesson's steps return.
pub type LessonResult<T> = std::result::Result<T, Failure>;

impl From<crate::Error> for Failure {
    fn from(e: crate::Error) -> Failure {
        Failure::Render(e)
    }
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Failure::Render(e) => write!(f, "{e}"),
            Failure::Exercise { report } => write!(f, "{report}"),
            Failure::Interrupted => write!(f, "interrupted (Ctrl-C)"),
            Failure::NoMatch {
                param,
                value,
                choices,
            } => write!(
                f,
                "{param} '{value}' matches none of: {}",
                choices.join(", ")
            ),
        }
    }
}

impl std::error::Error for Failure {}
