//! Lesson 11 and the course as a whole: the speed-against-accuracy charts (what
//! numerics fix, never a time), the numbers the book quotes from them (measured again
//! in release: `cargo test --release --test course -- --ignored`), the BVH against
//! the plain list, the closest-hit fast paths, The Ray Tracer Challenge's tests
//! ported, and the core's architecture (dependencies flow one way).
//!
//! The lessons' own claims are in `tests/lessons/`; the checks of the book's text in
//! `tests/book/`.

#[path = "../common/mod.rs"]
mod common;
mod examples;

mod architecture;
mod bvh;
mod bvh_builds;
mod lesson_11_book_numbers;
mod lesson_11_fast_paths;
mod lesson_11_geometry_charts;
mod lesson_11_lessons_chart;
mod lesson_11_rendering_charts;
mod lesson_11_scaling;
mod mesh_shape;
mod porting;
mod porting_shapes;
