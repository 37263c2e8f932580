//! Chart 11.3: self-intersection, the bounce self-hit rate against the distance from
//! the origin (STABILITY S13, with S14 and the offset's size as findings).
//!
//! A unit sphere sits at distance |p| from the origin (its centre along (4, 2, 1),
//! the direction of S13's (X, X/2, X/4)). Primary rays from a few units away hit
//! its visible cap, and cosine-distributed bounce rays leave each hit point. The
//! sphere is convex: no bounce can meet it again, so every second hit is a rounding
//! artefact ("shadow acne"). Three ways to start the bounce: at the hit point with
//! t > 0 (no offset), with t > 1e-4 (a fixed epsilon), and from an origin moved off
//! the surface by an amount that scales with |p| (Wachter and Binder).

use glam::Vec3;

use super::{Measured, Quality};
use crate::basis::Basis;
use crate::course::chart::{Chart, Scale};
use crate::course::report::{BookNumbers, Quoted};
use crate::error::Result;
use crate::offset::{Offset, offset_ray_origin};
use crate::ray::Ray;
use crate::sampling::{cosine_hemisphere, grid};
use crate::shapes::{Plane, Sphere};

/// The distances |p| on the chart.
pub const DISTANCES: [f32; 11] = [1.0, 3.0, 1e1, 3e1, 1e2, 3e2, 1e3, 3e3, 1e4, 3e4, 1e5];

/// The three ways to start a bounce ray, with their legend names.
pub const METHODS: [(&str, Offset); 3] = [
    ("fixed epsilon: t > 1e-4", Offset::Fixed(1e-4)),
    ("no offset: t > 0", Offset::Fixed(0.0)),
    ("scaled offset (Wachter-Binder)", Offset::Scaled),
];

/// The share of bounce rays that hit their own unit sphere again, for the sphere
/// centred at distance `distance` from the origin, with `primaries` x `primaries`
/// primary rays and `bounces` x `bounces` bounce rays from each hit point.
pub fn self_hit_rate(distance: f32, offset: Offset, primaries: u32, bounces: u32) -> Result<f64> {
    let centre = distance * Vec3::new(4.0, 2.0, 1.0).normalize();
    let sphere = Sphere::new(centre, 1.0)?;
    let (mut wrong, mut total) = (0u64, 0u64);
    for (i, aim) in grid(primaries).enumerate() {
        // Primary rays from 5 units away, aimed at points spread over the visible cap.
        let target = centre + Vec3::new(aim.x - 0.5, aim.y - 0.5, 1.0).normalize() * 0.9;
        let origin = centre + Vec3::new(0.3, -0.2, 5.0) + Vec3::splat(i as f32 * 1e-3);
        let Some(hit) = sphere.hit(&Ray::new(origin, target - origin)?, 0.0, f32::INFINITY) else {
            continue;
        };
        let frame = Basis::around(hit.normal);
        let (start, t_min) = offset.start(hit.point, hit.normal);
        for u in grid(bounces) {
            let bounce = Ray::new(start, frame.to_world(cosine_hemisphere(u)))?;
            total += 1;
            wrong += u64::from(sphere.hit(&bounce, t_min, f32::INFINITY).is_some());
        }
    }
    Ok(wrong as f64 / total.max(1) as f64)
}

/// (primaries, bounces) per side of their grids.
fn counts(quality: Quality) -> (u32, u32) {
    quality.pick((8, 16), (24, 32))
}

/// Each method's (|p|, self-hit rate as a share) at every distance of
/// [`DISTANCES`], in the order of [`METHODS`].
pub fn data(quality: Quality) -> Result<Vec<Vec<(f64, f64)>>> {
    let (primaries, bounces) = counts(quality);
    METHODS
        .iter()
        .map(|&(_, offset)| {
            DISTANCES
                .iter()
                .map(|&x| Ok((f64::from(x), self_hit_rate(x, offset, primaries, bounces)?)))
                .collect()
        })
        .collect()
}

/// How far [`offset_ray_origin`] moves a point of the sphere at distance `distance`
/// (the hit point of a ray aimed at the sphere's centre, with its normal).
pub fn scaled_offset_size(distance: f32) -> Result<f64> {
    let centre = distance * Vec3::new(4.0, 2.0, 1.0).normalize();
    let sphere = Sphere::new(centre, 1.0)?;
    let origin = centre + Vec3::new(0.3, -0.2, 5.0);
    let Some(hit) = sphere.hit(&Ray::new(origin, centre - origin)?, 0.0, f32::INFINITY) else {
        return Ok(f64::NAN);
    };
    Ok((offset_ray_origin(hit.point, hit.normal).as_dvec3() - hit.point.as_dvec3()).length())
}

/// STABILITY S14, the contact shadow: a floor y = 0 and an occluder parallel to it at
/// a gap of 5e-5, near |p| = 1, the light straight above. Does the shadow ray from
/// the floor, started by `offset`, still meet the occluder?
pub fn contact_shadow_blocked(offset: Offset) -> Result<bool> {
    let floor = Plane::new(Vec3::ZERO, Vec3::Y)?;
    let occluder = Plane::new(Vec3::new(0.0, 5e-5, 0.0), Vec3::Y)?;
    let p = Vec3::new(0.6, 0.0, 0.8);
    let Some(hit) = floor.hit(&Ray::new(p + 3.0 * Vec3::Y, Vec3::NEG_Y)?, 0.0, 10.0) else {
        return Ok(false);
    };
    let (start, t_min) = offset.start(hit.point, Vec3::Y);
    Ok(occluder
        .hit(&Ray::new(start, Vec3::Y)?, t_min, 10.0)
        .is_some())
}

/// The distances |p| of the book's table.
pub const QUOTED_DISTANCES: [f32; 5] = [1.0, 1e2, 1e3, 1e4, 1e5];

/// A distance as the book's tables print it: 1, 1e2, 1e3, ...
pub(crate) fn label(x: f64) -> String {
    if x == 1.0 {
        "1".into()
    } else {
        format!("{x:.0e}")
    }
}

/// The numbers the book quotes from chart 3, all exact: table `self_hits`, each
/// method's self-hit rate and the scaled offset's size at [`QUOTED_DISTANCES`] (from
/// `rates`, as [`data`] returns them); table `contact`, S14's contact shadow.
pub fn quoted(rates: &[Vec<(f64, f64)>]) -> Result<BookNumbers> {
    let rate = |method: usize, x: f64| {
        rates
            .get(method)
            .and_then(|r| r.iter().find(|p| p.0 == x))
            .map_or(f64::NAN, |p| 100.0 * p.1)
    };
    let mut table = Quoted::new(
        "self_hits",
        false,
        &[
            "distance from the origin",
            "fixed t > 1e-4 (%)",
            "no offset (%)",
            "scaled offset (%)",
            "scaled offset's size",
        ],
    );
    for x in QUOTED_DISTANCES {
        let x64 = f64::from(x);
        table = table.row(vec![
            label(x64),
            format!("{:.2}", rate(0, x64)),
            format!("{:.2}", rate(1, x64)),
            format!("{:.2}", rate(2, x64)),
            format!("{:.1e}", scaled_offset_size(x)?),
        ]);
    }
    let blocks = |b: bool| if b { "blocks it" } else { "leaks light" };
    let contact = Quoted::new(
        "contact",
        false,
        &[
            "occluder 5e-5 above the floor, 1 from the origin",
            "fixed t > 1e-4",
            "scaled offset",
        ],
    )
    .row(vec![
        "shadow ray from the floor".into(),
        blocks(contact_shadow_blocked(Offset::Fixed(1e-4))?).into(),
        blocks(contact_shadow_blocked(Offset::Scaled)?).into(),
    ]);
    Ok(BookNumbers::default().table(table).table(contact))
}

/// The numbers the book quotes from chart 3, measured at `quality`.
pub fn exact_quoted(quality: Quality) -> Result<BookNumbers> {
    quoted(&data(quality)?)
}

/// The chart: self-hit rate in percent against |p|, one line per way to start the
/// bounce.
pub fn measure(quality: Quality) -> Result<Measured> {
    let rates = data(quality)?;
    let mut chart = Chart::new(
        "Self-intersection: bounce self-hit rate against distance from the origin",
        (
            "|p|: distance of the unit sphere from the origin (world units)",
            Scale::Log,
        ),
        (
            "self-hit rate (% of bounce rays hitting their own convex sphere)",
            Scale::Linear,
        ),
    );
    for ((name, _), points) in METHODS.iter().zip(&rates) {
        chart = chart.with(name, points.iter().map(|&(x, r)| (x, 100.0 * r)).collect());
    }
    let rate = |method: usize, x: f64| {
        rates[method]
            .iter()
            .find(|p| p.0 == x)
            .map_or(f64::NAN, |p| 100.0 * p.1)
    };
    let first_fixed = rates[0].iter().find(|p| p.1 > 0.0).map(|p| p.0);
    let worst_scaled = rates[2].iter().map(|p| p.1).fold(0.0, f64::max);
    let [s1, s3, s5] = [1.0, 1e3, 1e5].map(scaled_offset_size);
    let (s1, s3, s5) = (s1?, s3?, s5?);
    let (fixed_blocks, scaled_blocks) = (
        contact_shadow_blocked(Offset::Fixed(1e-4))?,
        contact_shadow_blocked(Offset::Scaled)?,
    );
    let blocks = |b: bool| if b { "blocks it" } else { "leaks light" };
    let findings = vec![
        format!(
            "fixed t > 1e-4: first self-hits at |p| = {}, {:.1}% at 1e3, {:.1}% at 1e4, {:.1}% at 1e5; \
             no offset: {:.1}% at |p| = 1; scaled offset: at most {:.2}% at any |p|",
            first_fixed.map_or("never".to_string(), |x| format!("{x:.0e}")),
            rate(0, 1e3),
            rate(0, 1e4),
            rate(0, 1e5),
            rate(1, 1.0),
            100.0 * worst_scaled
        ),
        format!(
            "scaled offset size (grows with |p| like the rounding error of p): {:.1e} at |p| = 1, \
             {:.1e} at 1e3, {:.1e} at 1e5",
            s1, s3, s5
        ),
        format!(
            "S14 contact shadow, occluder 5e-5 above the floor at |p| = 1: fixed 1e-4 {}, \
             scaled offset {}",
            blocks(fixed_blocks),
            blocks(scaled_blocks)
        ),
    ];
    Ok(Measured {
        chart,
        findings,
        quoted: quoted(&rates)?,
    })
}
