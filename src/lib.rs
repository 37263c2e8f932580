//! # render-lessons
//!
//! The shared core of a course on image synthesis, from a 4x4 matrix to a path
//! tracer. Each module is one idea of the lectures, named after it; each lesson's
//! example (`examples/NN_*.rs`) builds on these modules, and the book includes their
//! code by anchor.
//!
//! ## The renderer, in layers
//!
//! Dependencies flow one way, up this list; a module uses only the layers below
//! it (`tests/course/architecture.rs` checks this, and that no two files import each
//! other):
//!
//! 1. `error`, `float`: the one typed error, naming the parameter at fault, and the
//!    floating-point tools (rounding-error bounds);
//! 2. `limits`, `transform`, `ray`, `basis`, `rng`, `sampling`, `material`, `files`,
//!    `progress`: what the machine can give, the maths of Lectures 3 and 4, one
//!    deterministic random stream per pixel and the samplers that use it, writing
//!    files whole, progress bars;
//! 3. `quadratic`, `spawn`, `bvh`, `texture`: the roots of a t^2 + b t + c = 0,
//!    shared by the sphere and the quadrics; where a spawned ray starts, and where a
//!    shadow ray ends; the bounding volume hierarchy, a tree of boxes that knows its
//!    primitives by their boxes alone; an image read as a surface's albedo;
//! 4. `camera`, `shapes`: rays from pixels, and where rays cross surfaces (a
//!    triangle mesh among them, one shape with a tree of its own);
//! 5. `scene`, `framebuffer`: a list of objects with one closest-hit loop, the same
//!    questions through a tree, and an image in memory with its two files (PNG,
//!    PFM);
//! 6. `lighting`, `render`, `mesh`: the one Lambert formula, one ray per pixel in
//!    parallel, triangle meshes (read, made from shapes, placed);
//! 7. `raycast`, `raster`, `pathtrace`: the three renderers;
//! 8. `scenes`: the lessons' scenes, shared by several lessons;
//! 9. `prelude`: the renderer's front door, one `use` for a program of your own
//!    (`examples/library.rs`).
//!
//! ## The course's tools
//!
//! [`course`] sits on top: diagrams, charts, tables, the lessons' flags, lesson
//! 11's measurements and the exercises. Nothing in the renderer imports it.

#![warn(missing_docs)]

pub mod basis;
pub mod bvh;
pub mod camera;
pub mod course;
pub mod error;
pub mod files;
pub mod float;
pub mod framebuffer;
pub mod lighting;
pub mod limits;
pub mod material;
pub mod mesh;
pub mod pathtrace;
pub mod prelude;
pub mod progress;
pub mod quadratic;
pub mod raster;
pub mod ray;
pub mod raycast;
pub mod render;
pub mod rng;
pub mod sampling;
pub mod scene;
pub mod scenes;
pub mod shapes;
pub mod spawn;
pub mod texture;
pub mod transform;

pub use error::{Error, Result};
pub use glam;
