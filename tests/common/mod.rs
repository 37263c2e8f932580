//! Helpers shared by every test crate (`tests/lessons`, `tests/course`, `tests/book`,
//! `tests/exercise_checks`), each defined once here. A crate includes them with
//! `#[path = "../common/mod.rs"] mod common;`.
//!
//! - [`compare`]: `close` (a tolerance, any number of components) and `bits` (bit for
//!   bit, -0 and 0 apart);
//! - [`fixtures`]: rays, shapes, the slides' camera, the reference closest-hit loop;
//! - [`random`]: the crate's random stream for every random case, and `for_cases`,
//!   the loop a property runs its cases in;
//! - [`pixels`]: what a diagram draws, counted by colour;
//! - [`pages`]: the book's pages and the tests' snapshots, read as text;
//! - [`outcomes`]: what a check of a coding exercise answered (`fails_with`, ...).
#![allow(dead_code, unused_imports)]

pub mod compare;
pub mod fixtures;
pub mod outcomes;
pub mod pages;
pub mod pixels;
pub mod random;

pub use compare::{assert_close, bits, close};
pub use fixtures::{
    cube, ray, reference_closest, slide_camera, slide_film, unit_sphere,
};
pub use outcomes::{fails_hinting, fails_with, panicked};
pub use pixels::{blue_pixels, red_pixels};
pub use random::{Rng, for_cases};
