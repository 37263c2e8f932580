//! Chart 5: Monte Carlo error against the number of samples (STABILITY S18, S19).
//!
//! The setup is S19's: a white Lambertian floor point under a spherical light of
//! radius [`RADIUS`] and radiance 1 whose centre is at height 1. The light it
//! reflects is exactly R^2, so every estimate's error is known without a reference.
//! Each estimator of lesson 10 (the path tracer's own [`radiance`], depth 1) is asked
//! for the mean of N independent samples, many times over; the root mean square of
//! (mean - R^2) falls as N^-1/2 for all of them, but from very different heights.
//! A variance 100 times smaller is worth 100 times more samples: that is what
//! efficiency, 1 / (variance x time per sample), measures.
//!
//! One more line shows what independence costs: the light-cone estimator again, its
//! uniform numbers jittered (one in each cell of a grid over the unit square, as
//! lesson 10's jittered pixel samples). Seen from the point straight below, the
//! cone's samples vary smoothly (linearly in the first number), and stratified
//! samples of a smooth integrand converge as N^-1, not N^-1/2.

use glam::{Vec2, Vec3};
use rayon::prelude::*;

use super::{Measured, Quality, ns_per_call};
use crate::course::chart::{Chart, Scale, log_log_slope};
use crate::course::report::{BookNumbers, Quoted};
use crate::error::Result;
use crate::material::Material;
use crate::pathtrace::light::{LightShape, SphereSampling};
use crate::pathtrace::radiance;
use crate::pathtrace::settings::{Sampling, Settings};
use crate::ray::Ray;
use crate::rng::Rng;
use crate::sampling::strata;
use crate::scene::{Object, Scene};
use crate::shapes::{Plane, Shape, Sphere};

/// The light's radius R: the floor point reflects exactly R^2 = 0.0625.
pub const RADIUS: f32 = 0.25;

/// The exact value every estimator estimates: R^2 (in f64).
pub fn exact() -> f64 {
    f64::from(RADIUS) * f64::from(RADIUS)
}

/// The direct-light estimators of lesson 10 (and one of them jittered).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Estimator {
    /// A direction uniform over the hemisphere: counts if it hits the light.
    UniformHemisphere,
    /// A cosine-weighted direction (smallpt's way).
    Cosine,
    /// Next event estimation, a point uniform over the sphere's whole area.
    LightArea,
    /// Next event estimation, a direction uniform in the cone the sphere subtends.
    LightCone,
    /// Area light samples and cosine directions, combined by the power heuristic.
    MisArea,
    /// Cone light samples and cosine directions, combined by the power heuristic
    /// (the path tracer's default).
    MisCone,
    /// The light-cone estimator with jittered uniform numbers.
    LightConeJittered,
}

impl Estimator {
    /// The estimators of independent samples, worst first.
    pub const INDEPENDENT: [Estimator; 6] = [
        Estimator::UniformHemisphere,
        Estimator::Cosine,
        Estimator::LightArea,
        Estimator::MisArea,
        Estimator::LightCone,
        Estimator::MisCone,
    ];

    /// The name in the chart's legend.
    pub fn name(self) -> &'static str {
        match self {
            Estimator::UniformHemisphere => "uniform hemisphere",
            Estimator::Cosine => "cosine",
            Estimator::LightArea => "light area",
            Estimator::LightCone => "light cone",
            Estimator::MisArea => "MIS (area + cosine)",
            Estimator::MisCone => "MIS (cone + cosine)",
            Estimator::LightConeJittered => "light cone, jittered",
        }
    }

    /// The path tracer's settings for it: one bounce, no Russian roulette.
    fn settings(self) -> Settings {
        let (sampling, sphere_lights) = match self {
            Estimator::UniformHemisphere => {
                (Sampling::UniformHemisphere, SphereSampling::Cone)
            }
            Estimator::Cosine => (Sampling::Cosine, SphereSampling::Cone),
            Estimator::LightArea => (Sampling::NextEvent, SphereSampling::Area),
            Estimator::LightCone | Estimator::LightConeJittered => {
                (Sampling::NextEvent, SphereSampling::Cone)
            }
            Estimator::MisArea => (Sampling::Mis, SphereSampling::Area),
            Estimator::MisCone => (Sampling::Mis, SphereSampling::Cone),
        };
        Settings {
            sampling,
            sphere_lights,
            max_depth: Some(1),
            russian_roulette: false,
            ..Settings::default()
        }
    }
}

/// S19's scene and the ray that looks straight down at the floor point below the
/// light's centre.
struct Setup {
    scene: Scene,
    ray: Ray,
    light: Shape,
}

impl Setup {
    fn new() -> Result<Setup> {
        let floor = Object::new(
            Shape::Plane(Plane::new(Vec3::ZERO, Vec3::Y)?),
            Material::diffuse(Vec3::ONE)?,
        );
        let light = Shape::Sphere(Sphere::new(Vec3::Y, RADIUS)?);
        let bulb = Object::emitting(light.clone(), Material::BLACK, Vec3::ONE);
        let scene = Scene::new(vec![floor, bulb], Vec3::ZERO)?;
        let ray = Ray::new(Vec3::new(0.0, 0.5 * (1.0 - RADIUS), 0.0), -Vec3::Y)?;
        Ok(Setup { scene, ray, light })
    }

    /// One sample of `estimator` (independent kinds only), by the path tracer.
    fn sample(&self, settings: &Settings, rng: &mut Rng) -> f64 {
        f64::from(radiance(&self.scene, self.ray, rng, settings).x)
    }

    /// One light-cone sample from the floor point with the uniform numbers `u`:
    /// f_r L_e cos / pdf, with f_r = 1/pi (white Lambert) and L_e = 1. Nothing can
    /// block a ray from the floor up to the light, so no shadow ray is needed.
    fn cone_sample(&self, u: Vec2) -> f64 {
        let p = Vec3::ZERO;
        let cone = LightShape::new(&self.light, SphereSampling::Cone);
        let Some(y) = cone.and_then(|l| l.sample(p, u)) else {
            return 0.0;
        };
        let cos = Vec3::Y.dot((y.point - p).normalize_or_zero()).max(0.0);
        f64::from(cos) / (std::f64::consts::PI * f64::from(y.pdf))
    }

    /// The mean of `n` samples of `estimator`.
    fn estimate(&self, estimator: Estimator, n: u32, rng: &mut Rng) -> f64 {
        let sum: f64 = if estimator == Estimator::LightConeJittered {
            // A grid as square as n allows, more columns than rows, along the
            // number the cone's samples vary with.
            let grid = strata(n);
            (0..n)
                .map(|i| self.cone_sample(grid.point(i, rng.next_vec2())))
                .sum()
        } else {
            let settings = estimator.settings();
            (0..n).map(|_| self.sample(&settings, rng)).sum()
        };
        sum / f64::from(n.max(1))
    }
}

// ANCHOR: rmse_curve
/// (N, RMSE) for each N of `ns`: the root mean square of (mean of N samples - R^2)
/// over `reps` independent estimates, each from its own random stream (seeded from
/// (`seed`, repetition, N)), so the curve is the same on any number of threads.
pub fn rmse_curve(
    estimator: Estimator,
    ns: &[u32],
    reps: u32,
    seed: u64,
) -> Result<Vec<(f64, f64)>> {
    let setup = Setup::new()?;
    let exact = exact();
    Ok(ns
        .iter()
        .map(|&n| {
            let squares: Vec<f64> = (0..reps)
                .into_par_iter()
                .map(|rep| {
                    let mut rng = Rng::for_pixel(seed, rep, n);
                    (setup.estimate(estimator, n, &mut rng) - exact).powi(2)
                })
                .collect();
            let mse = squares.iter().sum::<f64>() / f64::from(reps.max(1));
            (f64::from(n), mse.sqrt())
        })
        .collect())
}
// ANCHOR_END: rmse_curve

/// The variance of one sample of `estimator` (its mean square error against R^2,
/// the estimator being unbiased), over `n` samples rounded up to a multiple of
/// 1024 (one random stream per 1024).
pub fn variance(estimator: Estimator, n: u32, seed: u64) -> Result<f64> {
    let setup = Setup::new()?;
    let squares: Vec<f64> = (0..n.div_ceil(1024))
        .into_par_iter()
        .map(|chunk| {
            let mut rng = Rng::for_pixel(seed, chunk, u32::MAX);
            let settings = estimator.settings();
            (0..1024)
                .map(|_| (setup.sample(&settings, &mut rng) - exact()).powi(2))
                .sum()
        })
        .collect();
    Ok(squares.iter().sum::<f64>() / (1024.0 * f64::from(n.div_ceil(1024).max(1))))
}

/// 1, 2, 4, ... up to `max`.
fn powers_of_two(max: u32) -> Vec<u32> {
    std::iter::successors(Some(1u32), |n| n.checked_mul(2))
        .take_while(|&n| n <= max)
        .collect()
}

/// The chart and its findings: `reps` estimates per point, N up to `max_n`,
/// `variance_samples` samples for each variance, three timings of `calls` samples
/// each.
pub fn chart(
    max_n: u32,
    reps: u32,
    variance_samples: u32,
    calls: u32,
) -> Result<Measured> {
    let setup = Setup::new()?;
    let ns = powers_of_two(max_n);
    let mut chart = Chart::new(
        "Monte Carlo: RMSE against samples",
        ("samples per estimate N", Scale::Log),
        (
            &format!(
                "RMSE against the exact R^2 = {} (radiance, L_e = 1)",
                exact()
            ),
            Scale::Log,
        ),
    );
    let mut slopes = Vec::new();
    let mut costs = Vec::new();
    let mut exact_table = Quoted::new(
        "estimators",
        false,
        &["estimator", "slope of log RMSE", "variance of one sample"],
    );
    let all = Estimator::INDEPENDENT
        .iter()
        .chain(&[Estimator::LightConeJittered]);
    for (i, &estimator) in all.enumerate() {
        let curve = rmse_curve(estimator, &ns, reps, 11_500 + i as u64)?;
        let slope = log_log_slope(&curve).unwrap_or(f64::NAN);
        chart = chart.with(&format!("{} (slope {slope:.2})", estimator.name()), curve);
        slopes.push(format!("{} {slope:.2}", estimator.name()));
        let mut cells = vec![estimator.name().to_string(), format!("{slope:.2}")];
        if estimator == Estimator::LightConeJittered {
            cells.push("(not independent)".into());
            exact_table = exact_table.row(cells);
        } else {
            let var = variance(estimator, variance_samples, 11_600 + i as u64)?;
            cells.push(format!("{var:.2e}"));
            exact_table = exact_table.row(cells);
            let settings = estimator.settings();
            let mut rng = Rng::for_pixel(11_700, i as u32, 0);
            // The least of three timings: other work on the machine only adds time.
            let ns = (0..3)
                .map(|_| ns_per_call(calls, |_| setup.sample(&settings, &mut rng)))
                .fold(f64::INFINITY, f64::min);
            costs.push((estimator, var, ns));
        }
    }
    let efficiency = |&(_, var, ns): &(Estimator, f64, f64)| 1.0 / (var * ns);
    let best = costs.iter().map(efficiency).fold(0.0, f64::max);
    let relative: Vec<String> = costs
        .iter()
        .map(|c| format!("{} {:.1e}", c.0.name(), efficiency(c) / best))
        .collect();
    let per_sample: Vec<String> = costs
        .iter()
        .map(|(e, var, ns)| format!("{} {:.1e} / {ns:.0} ns", e.name(), var))
        .collect();
    let mut times = Quoted::new(
        "times",
        true,
        &["estimator", "ns per sample", "efficiency / the best's"],
    );
    for c in &costs {
        times = times.row(vec![
            c.0.name().to_string(),
            format!("{:.0}", c.2),
            format!("{:.1e}", efficiency(c) / best),
        ]);
    }
    // Both tables side by side, for the chapter (timed: a test compares `estimators`).
    let mut summary = Quoted::new(
        "summary",
        true,
        &[
            "estimator",
            "slope",
            "variance of one sample",
            "ns per sample",
            "efficiency / the best's",
        ],
    );
    for row in &exact_table.rows {
        let timed = times.rows.iter().find(|t| t[0] == row[0]);
        let mut cells = row.clone();
        cells.extend(timed.map_or(vec!["-".into(), "-".into()], |t| t[1..].to_vec()));
        summary = summary.row(cells);
    }
    let ratio = |a: Estimator, b: Estimator| {
        let e =
            |x: Estimator| costs.iter().find(|c| c.0 == x).map_or(f64::NAN, efficiency);
        e(a) / e(b)
    };
    let quoted = BookNumbers::default()
        .table(exact_table)
        .table(times)
        .table(summary)
        .value(
            "cone_over_cosine",
            true,
            format!("{:.1e}", ratio(Estimator::LightCone, Estimator::Cosine)),
        )
        .value(
            "cone_over_mis_cone",
            true,
            format!("{:.1}", ratio(Estimator::LightCone, Estimator::MisCone)),
        );
    let findings = vec![
        format!("slopes of log RMSE against log N: {}", slopes.join(", ")),
        format!("variance / time of one sample: {}", per_sample.join(", ")),
        format!(
            "efficiency 1/(variance x time) relative to the best: {}",
            relative.join(", ")
        ),
    ];
    Ok(Measured {
        chart,
        findings,
        quoted,
    })
}

/// The chart of the lesson: N up to 1024, timed on this machine.
pub fn measure(quality: Quality) -> Result<Measured> {
    chart(
        1024,
        quality.pick(1000, 10_000),
        quality.pick(200_000, 2_000_000),
        quality.pick(50_000, 500_000),
    )
}
