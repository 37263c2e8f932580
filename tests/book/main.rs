//! Static checks of the book's text (`chapters/`) against the code, read as text:
//! every include resolves (`includes`), every name in backticks exists (`names`),
//! every number the book states comes from a source (`numbers`), every quantified
//! claim names its test and every test the book names by path is there (`claims`),
//! and the words and quoted numbers of the early chapters (`notation`).
//!
//! Standard library, glam and the crate only. The lessons' own claims are in
//! `tests/lessons/`; lesson 11 and the course as a whole in `tests/course/`.

mod markdown;

mod claims;
mod includes;
mod names;
mod notation;
mod numbers;
