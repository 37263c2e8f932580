//! Static checks of the book's text (`chapters/`) against the code, read as text:
//! every include resolves (`includes`), every name in backticks exists (`names`),
//! every number the book states comes from a source (`numbers`, `sources`) and every
//! number it quotes from lesson 11 is the fragment's (`quotes`), every quantified
//! claim names its test and every test the book names by path is there (`claims`),
//! the stability cases linked where a page first names them (`case_links`),
//! the words of the book (`notation`), the numbers its early chapters quote
//! (`early_numbers`) and what lesson 10 says of its error-against-time run
//! (`error_time`).
//!
//! Standard library, glam and the crate only. The lessons' own claims are in
//! `tests/lessons/`; lesson 11 and the course as a whole in `tests/course/`.

#[path = "../common/mod.rs"]
mod common;
mod markdown;

mod case_links;
mod claims;
mod early_numbers;
mod error_time;
mod includes;
mod names;
mod notation;
mod numbers;
mod printed;
mod quotes;
mod sources;
