//! Chart 11.1: ray/sphere, the error of the hit distance against D/r (STABILITY S1).
//!
//! A unit sphere is moved away from the ray origin along a fixed direction, to D/r
//! from 1.5 to 1e6, and rays from the origin are aimed at it (over a disc of 0.9 r
//! around its centre, so every ray truly hits). Each method's near root is compared
//! with a reference computed in f64 from the same f32 inputs by independent code (the
//! geometric form: the foot of the perpendicular from the centre, then back along the
//! ray by the half chord). A wrong answer counts as a relative error of 1: a miss
//! where the reference hits, or a "hit" more than the sphere's diameter 2r away from
//! the reference, which is no point of this sphere at all (and any error above 1 is
//! capped there too). The share of wrong answers is a finding of its own.
//!
//! The textbook discriminant b^2 - 4ac cancels: its error grows like D/r until, near
//! D/r = 1e3 in f32, it is as large as the discriminant itself and rays miss. The
//! Hearn-Baker discriminant r^2 - |f - (f.d) d|^2 (with stable roots) keeps the
//! relative error at the rounding unit whatever D/r.
//!
//! This file measures the chart; `tables.rs` builds the tables the book quotes
//! from it.

mod tables;

pub use tables::{QUOTED_DISTANCES, exact_quoted, quoted, quoted_times};

use glam::{DVec3, Vec3};

use super::{Measured, Quality, ns_per_call};
use crate::course::chart::{Chart, Scale};
use crate::error::Result;
use crate::ray::Ray;
use crate::shapes::Sphere;
use tables::at;

/// The four root finders on the chart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SphereMethod {
    /// [`Sphere::roots_textbook`], in f32.
    TextbookF32,
    /// [`Sphere::roots_stable`] (Hearn-Baker discriminant, stable roots), in f32.
    StableF32,
    /// The same textbook formula in f64.
    TextbookF64,
    /// The same stable formula in f64.
    StableF64,
}

impl SphereMethod {
    /// In the chart's order.
    pub const ALL: [SphereMethod; 4] = [
        SphereMethod::TextbookF32,
        SphereMethod::StableF32,
        SphereMethod::TextbookF64,
        SphereMethod::StableF64,
    ];

    /// The legend's name (without the time).
    pub fn name(self) -> &'static str {
        match self {
            SphereMethod::TextbookF32 => "textbook f32",
            SphereMethod::StableF32 => "stable f32",
            SphereMethod::TextbookF64 => "textbook f64",
            SphereMethod::StableF64 => "stable f64",
        }
    }
}

/// One method's accuracy over the chart's distances.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    /// Which root finder.
    pub method: SphereMethod,
    /// (D/r, mean relative error |t - t_ref| / t_ref of the near root), a wrong
    /// answer counted as 1 and every error capped at 1.
    pub errors: Vec<(f64, f64)>,
    /// (D/r, share of wrong answers: the method misses although the reference hits,
    /// or its t is more than the diameter 2r from the reference's).
    pub wrong: Vec<(f64, f64)>,
}

/// The distances D/r on the chart.
pub const DISTANCES: [f64; 13] = [
    1.5, 3.0, 1e1, 3e1, 1e2, 3e2, 1e3, 3e3, 1e4, 3e4, 1e5, 3e5, 1e6,
];

/// The direction from the ray origin to the sphere's centre (that of STABILITY S1).
fn towards() -> Vec3 {
    Vec3::new(0.3, 0.2, -1.0).normalize()
}

/// The unit sphere at distance `dist` along [`towards`], and the rays from the origin
/// aimed at the points of an `n` x `n` grid over [-0.9, 0.9]^2 (in the plane through
/// the centre across the line of sight) that lie within 0.9 of the centre.
fn scene(dist: f64, n: usize) -> Result<(Sphere, Vec<Ray>)> {
    let w = towards();
    let centre = dist as f32 * w;
    let sphere = Sphere::new(centre, 1.0)?;
    let u = w.cross(Vec3::Y).normalize();
    let v = u.cross(w);
    let mut rays = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n {
            let su = -0.9 + 1.8 * (i as f32 + 0.5) / n as f32;
            let sv = -0.9 + 1.8 * (j as f32 + 0.5) / n as f32;
            if su * su + sv * sv <= 0.81 {
                rays.push(Ray::new(Vec3::ZERO, centre + su * u + sv * v)?);
            }
        }
    }
    Ok((sphere, rays))
}

/// The near root for the same f32 inputs, in f64, by the geometric form (independent
/// of the code measured): t_mid = -f.d / a is the foot of the perpendicular from the
/// centre, h the half chord, t = t_mid - h.
pub(crate) fn reference(o: DVec3, d: DVec3, centre: DVec3, radius: f64) -> Option<f64> {
    let f = o - centre;
    let a = d.dot(d);
    let t_mid = -f.dot(d) / a;
    let l = f + t_mid * d;
    let h2 = radius * radius - l.dot(l);
    (h2 >= 0.0).then(|| t_mid - (h2 / a).sqrt())
}

/// The textbook roots in f64, as [`Sphere::roots_textbook`] computes them in f32.
fn textbook_f64(o: DVec3, d: DVec3, centre: DVec3, radius: f64) -> Option<(f64, f64)> {
    let f = o - centre;
    let a = d.dot(d);
    let b = 2.0 * f.dot(d);
    let c = f.dot(f) - radius * radius;
    let disc = b * b - 4.0 * a * c;
    if disc.is_nan() || disc < 0.0 {
        return None;
    }
    let s = disc.sqrt();
    let (t0, t1) = ((-b - s) / (2.0 * a), (-b + s) / (2.0 * a));
    Some((t0.min(t1), t0.max(t1)))
}

/// The stable roots in f64, as [`Sphere::roots_stable`] computes them in f32.
pub(crate) fn stable_f64(
    o: DVec3,
    d: DVec3,
    centre: DVec3,
    radius: f64,
) -> Option<(f64, f64)> {
    let f = o - centre;
    let a = d.dot(d);
    let half_b = f.dot(d);
    let c = f.dot(f) - radius * radius;
    let l = f - (half_b / a) * d;
    let delta = radius * radius - l.dot(l);
    if delta.is_nan() || delta < 0.0 {
        return None;
    }
    let sign = if half_b >= 0.0 { 1.0 } else { -1.0 };
    let q = -(half_b + sign * (a * delta).sqrt());
    if q == 0.0 {
        return Some((0.0, 0.0));
    }
    let (t0, t1) = (c / q, q / a);
    Some((t0.min(t1), t0.max(t1)))
}

/// The near root by `method`, as f64.
fn near_root(method: SphereMethod, sphere: &Sphere, ray: &Ray) -> Option<f64> {
    let (o, d) = (ray.origin().as_dvec3(), ray.direction().as_dvec3());
    let (c, r) = (sphere.centre().as_dvec3(), f64::from(sphere.radius()));
    match method {
        SphereMethod::TextbookF32 => {
            sphere.roots_textbook(ray).first().map(|&t| f64::from(t))
        }
        SphereMethod::StableF32 => {
            sphere.roots_stable(ray).first().map(|&t| f64::from(t))
        }
        SphereMethod::TextbookF64 => textbook_f64(o, d, c, r).map(|(t, _)| t),
        SphereMethod::StableF64 => stable_f64(o, d, c, r).map(|(t, _)| t),
    }
}

/// Rays per side of the aiming grid.
fn grid_side(quality: Quality) -> usize {
    quality.pick(32, 128)
}

/// The accuracy of every method at every distance of [`DISTANCES`] (no timing: this
/// is what the tests check).
pub fn data(quality: Quality) -> Result<Vec<Curve>> {
    let mut curves: Vec<Curve> = SphereMethod::ALL
        .iter()
        .map(|&method| Curve {
            method,
            errors: Vec::new(),
            wrong: Vec::new(),
        })
        .collect();
    for &dist in &DISTANCES {
        let (sphere, rays) = scene(dist, grid_side(quality))?;
        let (c, r) = (sphere.centre().as_dvec3(), f64::from(sphere.radius()));
        let references: Vec<Option<f64>> = rays
            .iter()
            .map(|ray| {
                reference(ray.origin().as_dvec3(), ray.direction().as_dvec3(), c, r)
            })
            .collect();
        let hits = references.iter().flatten().count().max(1) as f64;
        for curve in &mut curves {
            let (mut error_sum, mut wrong) = (0.0, 0usize);
            for (ray, reference) in rays.iter().zip(&references) {
                let Some(t_ref) = *reference else { continue };
                match near_root(curve.method, &sphere, ray) {
                    Some(t) if (t - t_ref).abs() <= 2.0 * r => {
                        error_sum += ((t - t_ref).abs() / t_ref).min(1.0);
                    }
                    _ => {
                        error_sum += 1.0;
                        wrong += 1;
                    }
                }
            }
            curve.errors.push((dist, error_sum / hits));
            curve.wrong.push((dist, wrong as f64 / hits));
        }
    }
    Ok(curves)
}

/// The fastest of `rounds` timings of each of `works`, taken in turn (one round
/// times every work once), so that a slow spell of a shared machine cannot fall on
/// one method only: the minimum is the time with the least interference.
pub(crate) fn fastest<const N: usize>(
    rounds: u32,
    mut works: [&mut dyn FnMut() -> f64; N],
) -> [f64; N] {
    let mut best = [f64::INFINITY; N];
    for _ in 0..rounds {
        for (b, work) in best.iter_mut().zip(works.iter_mut()) {
            *b = b.min(work());
        }
    }
    best
}

/// Nanoseconds per ray/sphere test of each method (both roots), over a fixed batch
/// of 4096 rays at D/r = 100, in the order of [`SphereMethod::ALL`]: the fastest of a
/// few rounds.
pub fn times(quality: Quality) -> Result<[f64; 4]> {
    let (sphere, rays) = scene(100.0, 80)?;
    let rays = &rays[..4096];
    let rays64: Vec<(DVec3, DVec3)> = rays
        .iter()
        .map(|r| (r.origin().as_dvec3(), r.direction().as_dvec3()))
        .collect();
    let (c, r) = (sphere.centre().as_dvec3(), f64::from(sphere.radius()));
    let calls = quality.pick(500_000, 5_000_000);
    let at = |i: u32| (i & 4095) as usize;
    Ok(fastest(
        quality.pick(5, 9),
        [
            &mut || ns_per_call(calls, |i| sphere.roots_textbook(&rays[at(i)])),
            &mut || ns_per_call(calls, |i| sphere.roots_stable(&rays[at(i)])),
            &mut || {
                ns_per_call(calls, |i| {
                    let (o, d) = rays64[at(i)];
                    textbook_f64(o, d, c, r)
                })
            },
            &mut || {
                ns_per_call(calls, |i| {
                    let (o, d) = rays64[at(i)];
                    stable_f64(o, d, c, r)
                })
            },
        ],
    ))
}

/// The chart: relative error of the hit distance against D/r, one line per method,
/// each named with its time per test.
pub fn measure(quality: Quality) -> Result<Measured> {
    let curves = data(quality)?;
    let ns = times(quality)?;
    let mut chart = Chart::new(
        "Ray/sphere: hit-distance error against D/r",
        (
            "D/r: distance from ray origin to sphere centre / radius (ratio)",
            Scale::Log,
        ),
        (
            "mean relative error of t, |t - t_ref| / t_ref (a miss = 1)",
            Scale::Log,
        ),
    );
    for (curve, ns) in curves.iter().zip(ns) {
        chart = chart.with(
            &format!("{} ({ns:.1} ns)", curve.method.name()),
            curve.errors.clone(),
        );
    }
    let [textbook, stable, textbook64, stable64] = [0, 1, 2, 3].map(|i| &curves[i]);
    let pct = |c: &Curve, x| 100.0 * at(&c.wrong, x);
    let worst64 = stable64.errors.iter().map(|p| p.1).fold(0.0, f64::max);
    let findings = vec![
        format!(
            "textbook f32 answers wrong (a miss, or a t more than 2r off) on {:.1}% of rays at \
             D/r = 3e3, {:.0}% at 1e4, {:.0}% at 1e6 (drawn as relative error 1); stable f32 on \
             {:.1}% at 1e6",
            pct(textbook, 3e3),
            pct(textbook, 1e4),
            pct(textbook, 1e6),
            pct(stable, 1e6)
        ),
        format!(
            "relative error at D/r = 1e3: textbook f32 {:.1e}, stable f32 {:.1e}; at 1e6: \
             textbook f64 {:.1e}, stable f64 {:.1e} (stable f64 at most {worst64:.1e} anywhere)",
            at(&textbook.errors, 1e3),
            at(&stable.errors, 1e3),
            at(&textbook64.errors, 1e6),
            at(&stable64.errors, 1e6)
        ),
        format!(
            "time per test: textbook f32 {:.1} ns, stable f32 {:.1} ns ({:+.0}%), \
             textbook f64 {:.1} ns, stable f64 {:.1} ns",
            ns[0],
            ns[1],
            100.0 * (ns[1] / ns[0] - 1.0),
            ns[2],
            ns[3]
        ),
    ];
    let quoted = quoted(&curves).merge(quoted_times(ns));
    Ok(Measured {
        chart,
        findings,
        quoted,
    })
}

#[cfg(test)]
mod tests {
    use glam::Vec3;

    use super::*;

    /// The f64 lines of chart 1 measure the formulas the core runs in f32: on inputs
    /// where every operation of both is exact (small whole numbers, perfect squares
    /// under the roots), the f64 copies give the f32 core's roots exactly, so a change
    /// to either formula that the other does not follow shows here.
    #[test]
    fn the_f64_copies_are_the_cores_formulas() {
        let sphere = Sphere::new(Vec3::new(0.0, 0.0, -10.0), 3.0).unwrap();
        let (c, r) = (sphere.centre().as_dvec3(), f64::from(sphere.radius()));
        let cases = [
            (Vec3::ZERO, Vec3::NEG_Z, [7.0, 13.0]),
            (Vec3::new(1.0, 2.0, 0.0), Vec3::NEG_Z, [8.0, 12.0]),
            (Vec3::new(0.0, 0.0, -20.0), 2.0 * Vec3::Z, [3.5, 6.5]),
            (Vec3::new(3.0, 0.0, 0.0), Vec3::NEG_Z, [10.0, 10.0]),
        ];
        for (o, d, exact) in cases {
            let ray = Ray::new_unnormalised(o, d).unwrap();
            let (o, d) = (o.as_dvec3(), d.as_dvec3());
            let f32_pair = |roots: crate::ray::Crossings| {
                [f64::from(roots[0]), f64::from(roots[1])]
            };
            let textbook = textbook_f64(o, d, c, r).map(|(a, b)| [a, b]);
            let stable = stable_f64(o, d, c, r).map(|(a, b)| [a, b]);
            assert_eq!(textbook, Some(f32_pair(sphere.roots_textbook(&ray))), "{o}");
            assert_eq!(stable, Some(f32_pair(sphere.roots_stable(&ray))), "{o}");
            assert_eq!(stable, Some(exact), "{o}");
        }
    }
}
