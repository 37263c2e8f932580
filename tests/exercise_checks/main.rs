//! The course's checks of the coding exercises, themselves checked (run by the default
//! test suite): in `lessons_*`, each check must pass the crate's reference and an
//! independent answer and fail wrong answers, each with a hint that names the mistake;
//! in `pitfalls_*`, the mistakes each chapter warns about, as a student writes them,
//! must fail; in `harness`, the harness that runs a student's answers (time limits,
//! panics, the summary). The student's own tests are in `tests/exercises.rs`.

#[path = "../common/mod.rs"]
mod common;

mod harness;
mod lessons_01_05;
mod lessons_06_07;
mod lessons_08_09;
mod lessons_10_11;
mod pitfalls_01_05;
mod pitfalls_06_07;
mod pitfalls_08_09;
mod pitfalls_10_11;
