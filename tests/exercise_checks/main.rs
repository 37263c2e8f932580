//! The course's checks of the coding exercises, themselves checked (run by the
//! default test suite, without the `exercises` feature): each check must pass the
//! crate's reference and an independent answer and fail the wrong answers its chapter
//! warns about, each with a hint that names the mistake; and the harness that runs a
//! student's answers (time limits, panics, the summary). The student's own tests are
//! in `tests/exercises.rs`.

mod common;

mod harness;
mod lessons_01_05;
mod lessons_06_07;
mod lessons_08_09;
mod lessons_10_11;
