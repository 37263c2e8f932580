//! The path tracer: radiance estimated along random paths, summed into an image.
//!
//! Lesson 10: Monte Carlo path tracing, an estimator of Kajiya's rendering equation
//! (Lecture 2), one idea per file, on the shared
//! [`crate::scene::Scene`] (objects with a [`crate::material::Material`] and emission,
//! the background sky, the point light):
//!
//! - [`light`]: choosing points on lights (area, cone), each strategy beside its
//!   density, and the strategies each light's shape allows;
//! - [`settings`]: the sampling strategy, path length, Russian roulette, offset;
//! - [`estimator`]: the path, vertex by vertex, and the sum of its light;
//! - [`next_event`]: light samples with shadow rays, and the point light's;
//! - [`mis`]: the power heuristic that combines light and BRDF samples;
//! - [`roulette`]: Russian roulette;
//! - [`progressive`]: sample passes accumulated into an image.

pub mod estimator;
pub mod light;
pub mod mis;
pub mod next_event;
pub mod progressive;
pub mod roulette;
pub mod settings;

pub use estimator::{At, Path, Vertex, radiance};
pub use light::{LightShape, SphereSampling};
pub use progressive::{Accumulator, Passes, PixelSampling};
pub use settings::{Sampling, Settings};

use crate::camera::Camera;
use crate::error::Result;
use crate::framebuffer::Framebuffer;
use crate::scene::Intersect;

/// The whole image in one call: `spp` samples per pixel with the default
/// [`Settings`] (MIS, depth 8, Russian roulette), independent pixel samples and seed
/// 1. The lessons write the steps out: an [`Accumulator`] and its passes.
pub fn path_trace(
    scene: &impl Intersect,
    camera: &Camera,
    spp: u32,
) -> Result<Framebuffer> {
    let mut sums = Accumulator::new(camera, 1);
    sums.render_pass(
        scene,
        camera,
        &Settings::default(),
        PixelSampling::Independent,
        spp,
    )
}
