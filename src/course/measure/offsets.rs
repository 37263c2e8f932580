//! Chart 11.3: self-intersection, the bounce self-hit rate against distance
//! (STABILITY S13, with S14 and the offset's size as findings).
//!
//! A unit sphere and primary rays that hit its visible cap; from each hit,
//! cosine-distributed bounce rays leave the surface. The sphere is convex: no bounce
//! can meet it again, so every second hit is a rounding artefact ("shadow acne").
//! Two placements ([`Placement`]): the sphere far from the world origin with the rays
//! from a few units away (S13), and the sphere at the world origin seen from far
//! away. Four ways to start the bounce ([`METHODS`]): at the hit point with t > 0
//! (no offset), with t > 1e-4 (a fixed epsilon), from an origin moved off the
//! surface by an amount that scales with |p| (Wachter and Binder), all three from the
//! point o + t d; and from the hit point projected onto the sphere, moved past its
//! error bound (pbrt-v4).

use glam::Vec3;

use super::{Measured, Quality};
use crate::basis::Basis;
use crate::course::chart::{Chart, Scale};
use crate::course::report::{BookNumbers, Quoted};
use crate::error::Result;
use crate::ray::{Interval, Ray};
use crate::sampling::{cosine_hemisphere, grid};
use crate::shapes::{Hit, Plane, Sphere};
use crate::spawn::{Offset, Start, offset_ray_origin};

/// The distances on the chart.
pub const DISTANCES: [f32; 13] = [
    1.0, 3.0, 1e1, 3e1, 1e2, 3e2, 1e3, 3e3, 1e4, 3e4, 1e5, 1e6, 1e7,
];

/// The four ways to start a bounce ray, with their legend names.
pub const METHODS: [(&str, Offset); 4] = [
    ("fixed epsilon: t > 1e-4", Offset::Fixed(1e-4)),
    ("no offset: t > 0", Offset::Fixed(0.0)),
    ("scaled offset (Wachter-Binder)", Offset::Scaled),
    ("error-bound offset (pbrt-v4)", Offset::ErrorBound),
];

/// Where the unit sphere and the primary rays' origins are, for a distance D.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Placement {
    /// The sphere centred at distance D from the world origin (along (4, 2, 1), the
    /// direction of S13's (X, X/2, X/4)), the rays from 5 units away: |p| is about
    /// D, t about 5.
    SphereFar,
    /// The sphere at the world origin, the rays from distance D away: |p| is about
    /// 1, t about D.
    CameraFar,
}

impl Placement {
    /// Both, in the order of the chart's two groups of lines.
    pub const ALL: [Placement; 2] = [Placement::SphereFar, Placement::CameraFar];

    /// The sphere's centre and the primary rays' base origin at distance `d`.
    fn layout(self, d: f32) -> (Vec3, Vec3) {
        let towards_camera = Vec3::new(0.3, -0.2, 5.0);
        match self {
            Placement::SphereFar => {
                let centre = d * Vec3::new(4.0, 2.0, 1.0).normalize();
                (centre, centre + towards_camera)
            }
            Placement::CameraFar => (Vec3::ZERO, d * towards_camera.normalize()),
        }
    }

    /// The name in the chart's legend.
    fn name(self) -> &'static str {
        match self {
            Placement::SphereFar => "sphere far",
            Placement::CameraFar => "camera far",
        }
    }
}

/// The share of bounce rays that hit their own unit sphere again, with the sphere and
/// the rays placed by `placement` at distance `distance`, with `primaries` x
/// `primaries` primary rays and `bounces` x `bounces` bounce rays from each hit.
pub fn self_hit_rate(
    placement: Placement,
    distance: f32,
    offset: Offset,
    primaries: u32,
    bounces: u32,
) -> Result<f64> {
    let (centre, base) = placement.layout(distance);
    let sphere = Sphere::new(centre, 1.0)?;
    let (mut wrong, mut total) = (0u64, 0u64);
    for (i, aim) in grid(primaries).enumerate() {
        // Primary rays aimed at points spread over the visible cap.
        let target =
            centre + Vec3::new(aim.x - 0.5, aim.y - 0.5, 1.0).normalize() * 0.9;
        let origin = base + Vec3::splat(i as f32 * 1e-3);
        let ray = Ray::new(origin, target - origin)?;
        let Some(hit) = sphere.hit(&ray, Interval::AHEAD) else {
            continue;
        };
        let frame = Basis::around(hit.normal);
        let Start {
            point: start,
            t_min,
        } = offset.start(start_point(&ray, &hit, offset), hit.error, hit.normal);
        for u in grid(bounces) {
            let bounce = Ray::new(start, frame.to_world(cosine_hemisphere(u)))?;
            total += 1;
            wrong += u64::from(
                sphere
                    .hit(&bounce, Interval::new(t_min, f32::INFINITY))
                    .is_some(),
            );
        }
    }
    Ok(wrong as f64 / total.max(1) as f64)
}

/// The point a bounce leaves from: for the error-bound offset the hit's own point,
/// projected onto the sphere, whose error bound it was made for; for the others the
/// point o + t d that a ray tracer computes first, as lesson 08 first did.
fn start_point(ray: &Ray, hit: &Hit, offset: Offset) -> Vec3 {
    match offset {
        Offset::ErrorBound => hit.point,
        _ => ray.at(hit.t),
    }
}

/// (primaries, bounces) per side of their grids.
fn counts(quality: Quality) -> (u32, u32) {
    quality.pick((8, 16), (24, 32))
}

/// The chart's lines: every method with the sphere far away; with the camera far
/// away, every method but "no offset" (which fails at every distance either way).
pub const SERIES: [(Placement, usize); 7] = [
    (Placement::SphereFar, 0),
    (Placement::SphereFar, 1),
    (Placement::SphereFar, 2),
    (Placement::SphereFar, 3),
    (Placement::CameraFar, 0),
    (Placement::CameraFar, 2),
    (Placement::CameraFar, 3),
];

/// Each series' (distance, self-hit rate as a share) at every distance of
/// [`DISTANCES`], in the order of [`SERIES`].
pub fn data(quality: Quality) -> Result<Vec<Vec<(f64, f64)>>> {
    let (primaries, bounces) = counts(quality);
    SERIES
        .iter()
        .map(|&(placement, method)| {
            DISTANCES
                .iter()
                .map(|&x| {
                    let rate = self_hit_rate(
                        placement,
                        x,
                        METHODS[method].1,
                        primaries,
                        bounces,
                    )?;
                    Ok((f64::from(x), rate))
                })
                .collect()
        })
        .collect()
}

/// The rate of `series` at distance `x` in percent, from `rates` as [`data`] returns
/// them; NaN if it was not measured.
fn percent(rates: &[Vec<(f64, f64)>], series: (Placement, usize), x: f64) -> f64 {
    SERIES
        .iter()
        .position(|&s| s == series)
        .and_then(|i| rates.get(i))
        .and_then(|r| r.iter().find(|p| p.0 == x))
        .map_or(f64::NAN, |p| 100.0 * p.1)
}

/// How far [`offset_ray_origin`] moves a point of the sphere at distance `distance`
/// (the hit point of a ray aimed at the sphere's centre, with its normal).
pub fn scaled_offset_size(distance: f32) -> Result<f64> {
    let (centre, origin) = Placement::SphereFar.layout(distance);
    let sphere = Sphere::new(centre, 1.0)?;
    let ray = Ray::new(origin, centre - origin)?;
    let Some(hit) = sphere.hit(&ray, Interval::AHEAD) else {
        return Ok(f64::NAN);
    };
    let p = start_point(&ray, &hit, Offset::Scaled);
    Ok((offset_ray_origin(p, hit.normal).as_dvec3() - p.as_dvec3()).length())
}

/// STABILITY S14, the contact shadow: a floor y = 0 and an occluder parallel to it at
/// a gap of 5e-5, near |p| = 1, the light straight above. Does the shadow ray from
/// the floor, started by `offset`, still meet the occluder?
pub fn contact_shadow_blocked(offset: Offset) -> Result<bool> {
    let floor = Plane::new(Vec3::ZERO, Vec3::Y)?;
    let occluder = Plane::new(Vec3::new(0.0, 5e-5, 0.0), Vec3::Y)?;
    let p = Vec3::new(0.6, 0.0, 0.8);
    let Some(hit) = floor.hit(
        &Ray::new(p + 3.0 * Vec3::Y, Vec3::NEG_Y)?,
        Interval::new(0.0, 10.0),
    ) else {
        return Ok(false);
    };
    let Start {
        point: start,
        t_min,
    } = offset.start(hit.point, hit.error, Vec3::Y);
    Ok(occluder
        .hit(&Ray::new(start, Vec3::Y)?, Interval::new(t_min, 10.0))
        .is_some())
}

/// The distances of the book's table with the sphere far away.
pub const QUOTED_DISTANCES: [f32; 6] = [1.0, 1e2, 1e3, 1e4, 1e5, 1e6];

/// The distances of the book's table with the camera far away: the 10, 300,
/// 1e4 and 1e6, and the 1e3 where the scaled offset fails most.
pub const QUOTED_CAMERA_DISTANCES: [f32; 6] = [1.0, 1e1, 3e2, 1e3, 1e4, 1e6];

/// A distance as the book's tables print it: 1, 1e2, 1e3, ...
pub(crate) fn label(x: f64) -> String {
    if x == 1.0 {
        "1".into()
    } else {
        format!("{x:.0e}")
    }
}

/// The numbers the book quotes from chart 3, all exact: table `self_hits` (the
/// sphere far away), each method's self-hit rate and the scaled offset's size at
/// [`QUOTED_DISTANCES`]; table `camera_far` (the sphere at the origin, the camera far
/// away) at [`QUOTED_CAMERA_DISTANCES`] (from `rates`, as [`data`] returns them);
/// table `contact`, S14's contact shadow.
pub fn quoted(rates: &[Vec<(f64, f64)>]) -> Result<BookNumbers> {
    let cell = |series: (Placement, usize), x: f32| {
        format!("{:.2}", percent(rates, series, f64::from(x)))
    };
    let far = Placement::SphereFar;
    let mut table = Quoted::new(
        "self_hits",
        false,
        &[
            "distance from the origin",
            "fixed t > 1e-4 (%)",
            "no offset (%)",
            "scaled offset (%)",
            "error bound (%)",
            "scaled offset's size",
        ],
    );
    for x in QUOTED_DISTANCES {
        table = table.row(vec![
            label(f64::from(x)),
            cell((far, 0), x),
            cell((far, 1), x),
            cell((far, 2), x),
            cell((far, 3), x),
            format!("{:.1e}", scaled_offset_size(x)?),
        ]);
    }
    let camera = Placement::CameraFar;
    let mut camera_far = Quoted::new(
        "camera_far",
        false,
        &[
            "distance of the camera",
            "fixed t > 1e-4 (%)",
            "scaled offset (%)",
            "error bound (%)",
        ],
    );
    for x in QUOTED_CAMERA_DISTANCES {
        camera_far = camera_far.row(vec![
            label(f64::from(x)),
            cell((camera, 0), x),
            cell((camera, 2), x),
            cell((camera, 3), x),
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
            "error bound",
        ],
    )
    .row(vec![
        "shadow ray from the floor".into(),
        blocks(contact_shadow_blocked(Offset::Fixed(1e-4))?).into(),
        blocks(contact_shadow_blocked(Offset::Scaled)?).into(),
        blocks(contact_shadow_blocked(Offset::ErrorBound)?).into(),
    ]);
    Ok(BookNumbers::default()
        .table(table)
        .table(camera_far)
        .table(contact))
}

/// The numbers the book quotes from chart 3, measured at `quality`.
pub fn exact_quoted(quality: Quality) -> Result<BookNumbers> {
    quoted(&data(quality)?)
}

/// The chart: self-hit rate in percent against the distance, one line per
/// placement and way to start the bounce ([`SERIES`]).
pub fn measure(quality: Quality) -> Result<Measured> {
    let rates = data(quality)?;
    let mut chart = Chart::new(
        "Self-intersection: bounce self-hit rate against distance",
        (
            "D: distance of the unit sphere from the origin (sphere far), or of the camera from the sphere (camera far)",
            Scale::Log,
        ),
        (
            "self-hit rate (% of bounce rays hitting their own convex sphere)",
            Scale::Linear,
        ),
    );
    for (&(placement, method), points) in SERIES.iter().zip(&rates) {
        let name = format!("{}, {}", METHODS[method].0, placement.name());
        chart =
            chart.with(&name, points.iter().map(|&(x, r)| (x, 100.0 * r)).collect());
    }
    let far = Placement::SphereFar;
    let camera = Placement::CameraFar;
    let rate = |series: (Placement, usize), x: f64| percent(&rates, series, x);
    let first = |series: (Placement, usize)| {
        let i = SERIES.iter().position(|&s| s == series)?;
        rates[i].iter().find(|p| p.1 > 0.0).map(|p| p.0)
    };
    let worst = |keep: &dyn Fn(&(Placement, usize)) -> bool| {
        SERIES
            .iter()
            .zip(&rates)
            .filter(|(s, _)| keep(s))
            .flat_map(|(_, r)| r.iter().map(|p| p.1))
            .fold(0.0, f64::max)
    };
    let at = |x: Option<f64>| x.map_or("never".to_string(), |x| format!("{x:.0e}"));
    let [s1, s3, s5] = [1.0, 1e3, 1e5].map(scaled_offset_size);
    let (s1, s3, s5) = (s1?, s3?, s5?);
    let blocks = |b: bool| if b { "blocks it" } else { "leaks light" };
    let findings = vec![
        format!(
            "sphere far: fixed t > 1e-4 first self-hits at D = {}, {:.1}% at 1e3, {:.1}% at 1e4, \
             {:.1}% at 1e5; no offset: {:.1}% at D = 1; scaled offset: at most {:.2}%",
            at(first((far, 0))),
            rate((far, 0), 1e3),
            rate((far, 0), 1e4),
            rate((far, 0), 1e5),
            rate((far, 1), 1.0),
            100.0 * worst(&|s| *s == (far, 2))
        ),
        format!(
            "camera far: fixed t > 1e-4 first self-hits at D = {}, scaled offset at D = {} \
             ({:.1}% at 1e3, {:.1}% at 1e4); error bound: at most {:.2}% in either placement",
            at(first((camera, 0))),
            at(first((camera, 2))),
            rate((camera, 2), 1e3),
            rate((camera, 2), 1e4),
            100.0 * worst(&|s| s.1 == 3)
        ),
        format!(
            "scaled offset size (grows with |p| like the rounding error of p): {:.1e} at |p| = 1, \
             {:.1e} at 1e3, {:.1e} at 1e5",
            s1, s3, s5
        ),
        format!(
            "S14 contact shadow, occluder 5e-5 above the floor at |p| = 1: fixed 1e-4 {}, \
             scaled offset {}, error bound {}",
            blocks(contact_shadow_blocked(Offset::Fixed(1e-4))?),
            blocks(contact_shadow_blocked(Offset::Scaled)?),
            blocks(contact_shadow_blocked(Offset::ErrorBound)?)
        ),
    ];
    Ok(Measured {
        chart,
        findings,
        quoted: quoted(&rates)?,
    })
}
