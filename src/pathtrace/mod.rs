//! Lesson 10: Monte Carlo path tracing, an estimator of Kajiya's rendering equation
//! (Lecture 2), one idea per file, on the shared
//! [`crate::scene::Scene`] (objects with a [`crate::material::Material`] and emission):
//!
//! - [`rng`]: one deterministic random stream per pixel;
//! - [`light`]: choosing points on lights (area, cone);
//! - [`settings`]: the sampling strategy, path length, Russian roulette, offset;
//! - [`estimator`]: the path loop;
//! - [`next_event`]: light samples with shadow rays;
//! - [`mis`]: the power heuristic that combines light and BRDF samples;
//! - [`roulette`]: Russian roulette;
//! - [`lens`]: the thin-lens camera;
//! - [`progressive`]: sample passes accumulated into an image;
//! - [`pfm`]: the floating-point image file;
//! - [`scenes`]: the Cornell box, the furnaces, the two-light scene.

pub mod estimator;
pub mod lens;
pub mod light;
pub mod mis;
pub mod next_event;
pub mod pfm;
pub mod progressive;
pub mod rng;
pub mod roulette;
pub mod scenes;
pub mod settings;

pub use estimator::radiance;
pub use lens::LensCamera;
pub use light::SphereSampling;
pub use progressive::{Accumulator, PixelSampling};
pub use rng::Rng;
pub use settings::{Sampling, Settings};
