//! Chart 11.4: precision against position, the hit-point error against the distance
//! from the origin (STABILITY S15).
//!
//! A unit sphere sits at distance X from the world origin (its centre along
//! (1, 0.5, 0.25)), seen by a pinhole camera about 3 units from it. The same rays are
//! intersected three ways:
//!
//! - f32 world space: camera, sphere and ray in world coordinates, as a renderer
//!   that stores its scene in f32 does;
//! - f32 camera-relative: the same camera with its frame at the origin and the sphere
//!   moved by minus the camera position, intersected in f32, and the hit point moved
//!   back by the camera position in f64;
//! - f64 world space: everything in f64 world coordinates.
//!
//! The centre and the camera position are f32 values and the rays the camera's own
//! f32 rays, so the three start from exactly the same scene: what differs is only the
//! arithmetic. The reference is computed in f64 relative to the camera (the
//! difference of two f32 positions is exact in f64), so it does not itself carry
//! the rounding of a large coordinate; errors are measured as offsets from the
//! camera, p - e, which f64 subtracts exactly.

use crate::ray::Interval;
use glam::{DVec3, Vec3};

use super::sphere::{reference, stable_f64};
use super::{Measured, Quality};
use crate::camera::{Film, Frame, PinholeCamera};
use crate::course::chart::{Chart, Scale};
use crate::course::report::{BookNumbers, Quoted};
use crate::error::Result;
use crate::shapes::Sphere;

/// The distances X on the chart.
pub const DISTANCES: [f64; 13] = [
    1.0, 3.0, 1e1, 3e1, 1e2, 3e2, 1e3, 3e3, 1e4, 3e4, 1e5, 3e5, 1e6,
];

/// The three ways to compute the hit point, with their legend names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PrecisionMethod {
    /// Everything in f32 world coordinates.
    WorldF32,
    /// f32 relative to the camera, the camera position added back in f64.
    CameraRelativeF32,
    /// Everything in f64 world coordinates.
    WorldF64,
}

impl PrecisionMethod {
    /// In the chart's order.
    pub const ALL: [PrecisionMethod; 3] = [
        PrecisionMethod::WorldF32,
        PrecisionMethod::CameraRelativeF32,
        PrecisionMethod::WorldF64,
    ];

    /// The legend's name.
    pub fn name(self) -> &'static str {
        match self {
            PrecisionMethod::WorldF32 => "f32 world space",
            PrecisionMethod::CameraRelativeF32 => "f32 camera-relative",
            PrecisionMethod::WorldF64 => "f64 world space",
        }
    }
}

/// Mean hit-point errors (world units) at distance `distance`, with an `n` x `n`
/// pixel camera, in the order of [`PrecisionMethod::ALL`].
pub fn errors_at(distance: f64, n: u32) -> Result<[f64; 3]> {
    let axis = DVec3::new(1.0, 0.5, 0.25).normalize();
    let centre = (distance * axis).as_vec3();
    let eye = centre + Vec3::new(0.3, -0.2, 3.0);
    // The eye and the centre are within a factor 2 of each other, so centre - eye is
    // exact in f32 (Sterbenz) and both frames get the same basis.
    let towards = centre - eye;
    let film = Film::new(n, n, (-0.25, 0.25), (-0.25, 0.25))?;
    let world_camera =
        PinholeCamera::new(film, 1.0, Frame::look(eye, towards, Vec3::Y)?)?;
    let local_camera =
        PinholeCamera::new(film, 1.0, Frame::look(Vec3::ZERO, towards, Vec3::Y)?)?;
    let world_sphere = Sphere::new(centre, 1.0)?;
    let local_sphere = Sphere::new(towards, 1.0)?;
    let (e, c) = (eye.as_dvec3(), centre.as_dvec3());
    let mut sums = [0.0; 3];
    let mut count = 0usize;
    for py in 0..n {
        for px in 0..n {
            let world_ray = world_camera.ray(px, py);
            let local_ray = local_camera.ray(px, py);
            debug_assert_eq!(world_ray.direction(), local_ray.direction());
            let d = world_ray.direction().as_dvec3();
            let Some(t_ref) = reference(DVec3::ZERO, d, c - e, 1.0) else {
                continue;
            };
            let truth = t_ref * d; // the hit point relative to the eye
            let error = |p: DVec3| ((p - e) - truth).length();
            let world = world_sphere
                .hit(&world_ray, Interval::AHEAD)
                .map_or(f64::INFINITY, |h| error(h.point.as_dvec3()));
            let relative = local_sphere
                .hit(&local_ray, Interval::AHEAD)
                .map_or(f64::INFINITY, |h| error(e + h.point.as_dvec3()));
            let world64 = stable_f64(e, d, c, 1.0)
                .map_or(f64::INFINITY, |(t, _)| error(e + t * d));
            for (sum, err) in sums.iter_mut().zip([world, relative, world64]) {
                *sum += err;
            }
            count += 1;
        }
    }
    Ok(sums.map(|s| s / count.max(1) as f64))
}

/// Each method's (X, mean hit-point error) at every distance of [`DISTANCES`], in
/// the order of [`PrecisionMethod::ALL`].
pub fn data(quality: Quality) -> Result<Vec<Vec<(f64, f64)>>> {
    let n = quality.pick(16, 64);
    let mut curves = vec![Vec::new(); 3];
    for &x in &DISTANCES {
        let errors = errors_at(x, n)?;
        for (curve, err) in curves.iter_mut().zip(errors) {
            curve.push((x, err));
        }
    }
    Ok(curves)
}

/// The distances X of the book's table.
pub const QUOTED_DISTANCES: [f64; 4] = [1.0, 1e2, 1e4, 1e6];

/// The spacing of f32 values at `x`: the distance to the next float above it.
fn spacing(x: f64) -> f64 {
    let v = x as f32;
    f64::from(f32::from_bits(v.to_bits() + 1) - v)
}

/// The numbers the book quotes from chart 4, all exact: table `errors`, each
/// method's mean hit-point error at [`QUOTED_DISTANCES`] (from `curves`, as [`data`]
/// returns them), with the f32 spacing there.
pub fn quoted(curves: &[Vec<(f64, f64)>]) -> BookNumbers {
    let at = |m: usize, x: f64| {
        curves
            .get(m)
            .and_then(|c| c.iter().find(|p| p.0 == x))
            .map_or(f64::NAN, |p| p.1)
    };
    let mut header = vec!["X"];
    header.extend(PrecisionMethod::ALL.map(|m| m.name()));
    header.push("f32 spacing at X");
    let mut table = Quoted::new("errors", false, &header);
    for x in QUOTED_DISTANCES {
        let mut cells = vec![super::offsets::label(x)];
        cells.extend([0, 1, 2].map(|m| format!("{:.1e}", at(m, x))));
        cells.push(format!("{:.1e}", spacing(x)));
        table = table.row(cells);
    }
    BookNumbers::default().table(table)
}

/// The numbers the book quotes from chart 4, measured at `quality`.
pub fn exact_quoted(quality: Quality) -> Result<BookNumbers> {
    Ok(quoted(&data(quality)?))
}

/// The chart: mean hit-point error against X, one line per method.
pub fn measure(quality: Quality) -> Result<Measured> {
    let curves = data(quality)?;
    let mut chart = Chart::new(
        "Precision against position: hit-point error against distance from the origin",
        (
            "X: distance of the unit sphere from the world origin (world units)",
            Scale::Log,
        ),
        ("mean hit-point error (world units)", Scale::Log),
    );
    for (method, points) in PrecisionMethod::ALL.iter().zip(&curves) {
        chart = chart.with(method.name(), points.clone());
    }
    let at = |m: usize, x: f64| {
        curves[m]
            .iter()
            .find(|p| p.0 == x)
            .map_or(f64::NAN, |p| p.1)
    };
    let findings = vec![
        format!(
            "f32 world space: {:.1e} at X = 1, {:.1e} at 1e4, {:.1e} at 1e6 (the f32 spacing \
             there is {:.1e}, {:.1e}): the error follows the float spacing at X",
            at(0, 1.0),
            at(0, 1e4),
            at(0, 1e6),
            spacing(1e4),
            spacing(1e6)
        ),
        format!(
            "f32 camera-relative: {:.1e} at X = 1, {:.1e} at 1e6: the same f32 arithmetic near \
             the origin, only the camera position kept in f64",
            at(1, 1.0),
            at(1, 1e6)
        ),
        format!(
            "f64 world space: {:.1e} at X = 1e6; it too grows with X, from far smaller numbers",
            at(2, 1e6)
        ),
    ];
    Ok(Measured {
        chart,
        findings,
        quoted: quoted(&curves),
    })
}
