//! Lesson 10's variance figure: where the noise of the Cornell box comes from, one
//! sample's standard deviation in every pixel, smallpt's estimator beside MIS
//! (`course::measure::variance`). The bench prints the same analysis as a table:
//!
//!     cargo bench -p render-benches --bench path_tracing -- equal-time

use render_lessons::Result;
use render_lessons::course::lesson::Output;
use render_lessons::course::measure::variance::pixel_variance;
use render_lessons::framebuffer::Framebuffer;
use render_lessons::pathtrace::{Sampling, Settings, SphereSampling};
use render_lessons::scenes::path_tracing::{self, Staged};

/// The figure's size per panel and its samples per pixel.
const WIDTH: u32 = 256;
const HEIGHT: u32 = 192;
const SPP: u32 = 32;

/// Writes `10_variance.png`: sigma / (sigma + 1) per pixel, cosine sampling (left)
/// and MIS (right), the lesson's default settings otherwise.
pub fn figures(out: &Output) -> Result<()> {
    let Staged { scene, camera } = path_tracing::cornell(WIDTH, HEIGHT)?;
    let panel = |sampling| -> Result<Framebuffer> {
        let settings = Settings {
            sampling,
            sphere_lights: SphereSampling::Cone,
            max_depth: Some(8),
            russian_roulette: true,
            ..Settings::default()
        };
        pixel_variance(&scene, &camera, &settings, SPP, 1)?.image()
    };
    let panels = [panel(Sampling::Cosine)?, panel(Sampling::Mis)?];
    out.image(
        "10_variance.png",
        &Framebuffer::beside(&[&panels[0], &panels[1]], 8)?,
    )
}
