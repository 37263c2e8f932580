//! # render-lessons
//!
//! The shared core of a course on image synthesis, from a 4x4 matrix to a path
//! tracer. Each module is one idea of the lectures, named after it; each lesson's
//! example (`examples/NN_*.rs`) builds on these modules, and the book includes their
//! code by anchor.
//!
//! Dependencies flow one way: `transform`, `ray`, `basis` -> `camera`, `shapes` ->
//! `scene` (and `bvh`, the same questions through a tree) -> renderers (`raycast`,
//! `render`) -> output (`framebuffer`, `diagram`).

pub mod basis;
pub mod bvh;
pub mod camera;
pub mod course;
pub mod error;
pub mod framebuffer;
pub mod lighting;
pub mod material;
pub mod offset;
pub mod output;
pub mod pathtrace;
pub mod raster;
pub mod ray;
pub mod raycast;
pub mod render;
pub mod sampling;
pub mod scene;
pub mod shapes;
pub mod transform;

pub use error::{Error, Result};
