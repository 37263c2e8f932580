//! Chart 6: the whole renderer, image error against wall time.
//!
//! Lesson 10's Cornell box, rendered progressively with each of its four sampling
//! strategies, pass after pass, and compared after every pass with a reference: a
//! long MIS render with its own seed. What counts for a user is not the error per
//! sample but the error per second: next event estimation takes longer per sample
//! (a shadow ray at every diffuse vertex) and wins anyway, because its samples are
//! so much less noisy. The findings read off the chart how long each strategy needs
//! to reach the error that cosine sampling (smallpt's way) has when it stops.

use std::time::Instant;

use super::{Measured, Quality};
use crate::camera::Camera;
use crate::course::chart::{Chart, Scale};
use crate::course::report::{BookNumbers, Quoted};
use crate::error::{Error, Problem, Result};
use crate::framebuffer::Framebuffer;
use crate::pathtrace::progressive::rmse;
use crate::pathtrace::{Accumulator, PixelSampling, Sampling, Settings};
use crate::scene::Scene;
use crate::scenes::path_tracing::{Staged, cornell};

/// The four strategies of lesson 10, worst first, with their names in the legend.
pub const TECHNIQUES: [(Sampling, &str); 4] = [
    (Sampling::UniformHemisphere, "uniform hemisphere"),
    (Sampling::Cosine, "cosine (smallpt)"),
    (Sampling::NextEvent, "next event"),
    (Sampling::Mis, "MIS"),
];

/// The seed of the compared renders (lesson 10's default); the reference uses
/// [`REFERENCE_SEED`].
pub const SEED: u64 = 1;

/// The reference's seed (lesson 10's: the seed plus 0x9e37_79b9): its noise must
/// not be the compared renders' noise.
pub const REFERENCE_SEED: u64 = SEED + 0x9e37_79b9;

/// What to render: the image size, the reference's samples per pixel, and the
/// samples of each pass of the compared renders.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Samples per pixel of the MIS reference.
    pub reference_spp: u32,
    /// Samples per pixel added by each pass, in order.
    pub passes: Vec<u32>,
}

impl Plan {
    /// Passes of 1, 1, 2, 4, ...: the sample count doubles with each pass, up to
    /// `max_spp` (a power of two).
    pub fn doubling(width: u32, height: u32, reference_spp: u32, max_spp: u32) -> Plan {
        let mut passes = vec![1];
        let mut total = 1;
        while total * 2 <= max_spp {
            passes.push(total);
            total *= 2;
        }
        Plan {
            width,
            height,
            reference_spp,
            passes,
        }
    }
}

/// The path tracer's settings of lesson 10 with `sampling`: cone-sampled spheres,
/// depth 8, Russian roulette.
fn settings(sampling: Sampling) -> Settings {
    Settings {
        sampling,
        ..Settings::default()
    }
}

/// The reference image: MIS, `spp` samples per pixel, its own seed.
pub fn reference(scene: &Scene, camera: &Camera, spp: u32) -> Result<Framebuffer> {
    let mut acc = Accumulator::new(camera, REFERENCE_SEED);
    let s = settings(Sampling::Mis);
    acc.render_pass(scene, camera, &s, PixelSampling::Independent, spp)
}

// ANCHOR: error_curve
/// (seconds since the start, RMSE against `reference`) after every pass of
/// `passes`, rendering with `sampling`. Only the passes are timed, not the RMSE.
pub fn error_curve(
    scene: &Scene,
    camera: &Camera,
    sampling: Sampling,
    reference: &Framebuffer,
    passes: &[u32],
) -> Result<Vec<(f64, f64)>> {
    let s = settings(sampling);
    let mut acc = Accumulator::new(camera, SEED);
    let mut seconds = 0.0;
    let mut curve = Vec::new();
    for &spp in passes {
        let start = Instant::now();
        let image =
            acc.render_pass(scene, camera, &s, PixelSampling::Independent, spp)?;
        seconds += start.elapsed().as_secs_f64();
        curve.push((seconds, rmse(&image, reference)));
    }
    Ok(curve)
}
// ANCHOR_END: error_curve

/// The time `curve` needs to reach `target`: interpolated on the log-log chart
/// between the passes around it, or extrapolated with RMSE ~ t^-1/2 from its first
/// or last pass if it is already below at the first or never gets there. `true` if
/// extrapolated.
pub fn time_to_reach(curve: &[(f64, f64)], target: f64) -> Option<(f64, bool)> {
    let &(t0, e0) = curve.first()?;
    if e0 <= target {
        return Some((t0 * (e0 / target).powi(2), e0 < target));
    }
    for pair in curve.windows(2) {
        let ((ta, ea), (tb, eb)) = (pair[0], pair[1]);
        if eb <= target {
            if ea <= eb {
                return Some((tb, false));
            }
            let f = (ea / target).ln() / (ea / eb).ln();
            return Some(((ta.ln() + f * (tb / ta).ln()).exp(), false));
        }
    }
    let &(tn, en) = curve.last()?;
    Some((tn * (en / target).powi(2), true))
}

/// The chart and its findings for `plan`.
pub fn chart(plan: &Plan) -> Result<Measured> {
    if plan.passes.is_empty() {
        return Err(Error::Value {
            param: "passes",
            problem: Problem::TooFew { value: 0, min: 1 },
        });
    }
    let Staged { scene, camera } = cornell(plan.width, plan.height)?;
    let reference = reference(&scene, &camera, plan.reference_spp)?;
    let total: u32 = plan.passes.iter().sum();
    let mut chart = Chart::new(
        "The whole renderer: image error against wall time",
        ("wall time (s)", Scale::Log),
        (
            &format!(
                "RMSE against a {}-spp MIS reference (radiance)",
                plan.reference_spp
            ),
            Scale::Log,
        ),
    );
    let mut curves = Vec::new();
    for (sampling, name) in TECHNIQUES {
        let curve = error_curve(&scene, &camera, sampling, &reference, &plan.passes)?;
        chart = chart.with(name, curve.clone());
        curves.push((name, curve));
    }
    let cosine = &curves[1].1;
    let &(cosine_time, target) = cosine.last().ok_or(Error::Value {
        param: "passes",
        problem: Problem::TooFew { value: 0, min: 1 },
    })?;
    let mut times = Vec::new();
    let mut rmse_table = Quoted::new(
        "rmse",
        false,
        &["technique", &format!("RMSE after {total} spp")],
    );
    let mut time_table = Quoted::new(
        "times",
        true,
        &[
            "technique",
            &format!("s for {total} spp"),
            "s to reach cosine's final RMSE",
            "x as fast as cosine",
        ],
    );
    for (name, curve) in &curves {
        let &(t, e) = curve.last().unwrap_or(&(f64::NAN, f64::NAN));
        rmse_table = rmse_table.row(vec![name.to_string(), format!("{e:.4}")]);
        let reach = time_to_reach(curve, target);
        let (to_reach, speed) = match reach {
            Some((r, extrapolated)) => (
                format!(
                    "{r:.2}{}",
                    if extrapolated { " (extrapolated)" } else { "" }
                ),
                format!("{:.1}", cosine_time / r),
            ),
            None => ("-".into(), "-".into()),
        };
        time_table =
            time_table.row(vec![name.to_string(), format!("{t:.2}"), to_reach, speed]);
    }
    // Both tables side by side, for the chapter (timed: a test compares `rmse`).
    let mut summary = Quoted::new(
        "summary",
        true,
        &[
            "technique",
            &format!("RMSE after {total} spp"),
            "s for them",
            "s to reach cosine's final RMSE",
            "x as fast as cosine",
        ],
    );
    for (exact, timed) in rmse_table.rows.iter().zip(&time_table.rows) {
        let mut cells = exact.clone();
        cells.extend(timed[1..].iter().cloned());
        summary = summary.row(cells);
    }
    let quoted = BookNumbers::default()
        .table(rmse_table)
        .table(time_table)
        .table(summary);
    for (name, curve) in curves.iter().filter(|(name, _)| *name != TECHNIQUES[1].1) {
        if let Some((t, extrapolated)) = time_to_reach(curve, target) {
            times.push(format!(
                "{name} {t:.2} s{} ({:.1}x as fast)",
                if extrapolated { ", extrapolated" } else { "" },
                cosine_time / t
            ));
        }
    }
    let finals: Vec<String> = curves
        .iter()
        .filter_map(|(name, c)| {
            c.last().map(|(t, e)| format!("{name} {e:.4} in {t:.2} s"))
        })
        .collect();
    let findings = vec![
        format!(
            "Cornell box {} x {}, {total} spp in {} passes, RMSE at the end: {}",
            plan.width,
            plan.height,
            plan.passes.len(),
            finals.join(", ")
        ),
        format!(
            "to reach cosine's final RMSE {target:.4} (cosine: {cosine_time:.2} s): {}",
            times.join(", ")
        ),
    ];
    Ok(Measured {
        chart,
        findings,
        quoted,
    })
}

/// The chart of the lesson, timed on this machine.
pub fn measure(quality: Quality) -> Result<Measured> {
    let plan = match quality {
        Quality::Quick => Plan::doubling(96, 72, 512, 64),
        Quality::Full => Plan::doubling(160, 120, 4096, 256),
    };
    chart(&plan)
}
