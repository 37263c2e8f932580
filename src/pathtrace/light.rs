//! Sampling the lights: choosing a point y on an emitter as seen from a shading point
//! p, with its density expressed per unit solid angle at p, so that the estimator can
//! compare it with the BRDF's density (Veach 1997, ch. 9) and divide by it.
//!
//! - Area sampling picks y uniformly on the surface, density 1/A per unit area; per
//!   unit solid angle that is |y - p|^2 / (A |cos theta_l|), theta_l the angle at y
//!   between the light's normal and the direction back to p (pbrt-v3 eq. 14.15).
//! - Cone sampling (spheres only) picks a direction uniformly inside the cone of
//!   directions from p that meet the sphere, density 1 / (2 pi (1 - cos theta_max))
//!   with sin theta_max = r / |c - p| (pbrt-v3 section 14.2.2). Every sample then
//!   lands on the cap p can see, (1 - r/D)/2 of the sphere's area from a distance D
//!   to its centre; area sampling wastes the other (1 + r/D)/2 on the hidden side.

use std::f32::consts::{PI, TAU};

use glam::{Vec2, Vec3};

use crate::basis::Basis;
use crate::ray::{Interval, Ray};
use crate::sampling::uniform_sphere;
use crate::shapes::{Quad, Shape, Sphere};

/// How points on a spherical light are chosen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SphereSampling {
    /// Uniformly over the whole sphere's area.
    Area,
    /// Uniformly over the cone of directions the sphere subtends (falls back to area
    /// sampling when p is inside the sphere or touching it, where no cone exists).
    Cone,
}

/// A point on a light, its unit normal, and the solid-angle density of having chosen
/// it from the shading point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightPoint {
    /// y.
    pub point: Vec3,
    /// The light's unit normal at y (outward; emission is two-sided).
    pub normal: Vec3,
    /// A bound on y's rounding error, per coordinate (see [`crate::shapes::Hit::error`]).
    pub error: Vec3,
    /// Density per unit solid angle at p, finite and positive.
    pub pdf: f32,
}

/// From sin^2 theta_max = r^2 / d^2 = 0.999 on (p inside the sphere, on it, or within
/// 0.05 % of its radius outside) no usable cone exists, and spheres are sampled by
/// area instead.
const MAX_CONE_SIN2: f32 = 0.999;

// ANCHOR: area_pdf
/// The solid-angle density at `p` of a point `y` (normal `n`) chosen with density
/// 1/`area` per unit area: |y - p|^2 / (A |cos theta_l|). `None` when it is not a
/// finite positive number: the light seen exactly edge-on (cos theta_l = 0), or y = p.
fn area_to_solid_angle(p: Vec3, y: Vec3, n: Vec3, area: f32) -> Option<f32> {
    let to_p = p - y;
    let d2 = to_p.length_squared();
    let cos_l = n.dot(to_p).abs() / d2.sqrt();
    let pdf = d2 / (area * cos_l);
    (pdf.is_finite() && pdf > 0.0).then_some(pdf)
}
// ANCHOR_END: area_pdf

// ANCHOR: cone
/// The unit axis from `p` to the sphere's centre and 1 - cos theta_max, computed as
/// sin^2 / (1 + cos) so that a small, distant light does not cancel to 0.
fn cone(p: Vec3, sphere: &Sphere) -> Option<(Vec3, f32)> {
    let to_c = sphere.centre() - p;
    let d2 = to_c.length_squared();
    let sin2_max = sphere.radius() * sphere.radius() / d2;
    if sin2_max.is_nan() || sin2_max >= MAX_CONE_SIN2 {
        return None;
    }
    let cos_max = (1.0 - sin2_max).sqrt();
    let one_minus_cos = sin2_max / (1.0 + cos_max);
    (one_minus_cos > 0.0).then(|| (to_c / d2.sqrt(), one_minus_cos))
}

/// A direction in the cone around `axis` with 1 - cos theta_max = `one_minus_cos`:
/// 1 - cos theta = u.x (1 - cos theta_max) is uniform, so is the solid angle.
fn sample_cone(axis: Vec3, one_minus_cos: f32, u: Vec2) -> Vec3 {
    let h = u.x * one_minus_cos;
    let cos = 1.0 - h;
    let sin = (h * (2.0 - h)).max(0.0).sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Basis::around(axis).to_world(Vec3::new(sin * c, sin * s, cos))
}
// ANCHOR_END: cone

/// A point of `shape` (a sphere or a quad; `None` for any other shape) chosen from
/// `p` with the uniform numbers `u`.
pub fn sample(shape: &Shape, p: Vec3, u: Vec2, strategy: SphereSampling) -> Option<LightPoint> {
    match shape {
        Shape::Sphere(s) => match (strategy, cone(p, s)) {
            (SphereSampling::Cone, Some((axis, omc))) => {
                let ray = Ray::new(p, sample_cone(axis, omc, u)).ok()?;
                let hit = s.hit(&ray, Interval::AHEAD)?;
                let pdf = 1.0 / (TAU * omc);
                pdf.is_finite().then_some(LightPoint {
                    point: hit.point,
                    normal: hit.normal,
                    error: hit.error,
                    pdf,
                })
            }
            _ => {
                let normal = uniform_sphere(u);
                let (point, error) = s.surface_point(normal);
                let pdf = area_to_solid_angle(p, point, normal, sphere_area(s))?;
                Some(LightPoint {
                    point,
                    normal,
                    error,
                    pdf,
                })
            }
        },
        Shape::Quad(q) => quad_point(q, p, u),
        _ => None,
    }
}

fn quad_point(q: &Quad, p: Vec3, u: Vec2) -> Option<LightPoint> {
    let point = q.point(u.x, u.y);
    let pdf = area_to_solid_angle(p, point, q.normal(), q.area())?;
    Some(LightPoint {
        point,
        normal: q.normal(),
        error: q.error_at(point),
        pdf,
    })
}

fn sphere_area(s: &Sphere) -> f32 {
    4.0 * PI * s.radius() * s.radius()
}

/// The solid-angle density with which [`sample`] would have chosen the point `y`
/// (normal `n`) of `shape` from `p`; 0 where it cannot be chosen or the density is
/// not finite. Used for the MIS weight of a path that hits a light by BRDF sampling.
pub fn pdf(shape: &Shape, p: Vec3, y: Vec3, n: Vec3, strategy: SphereSampling) -> f32 {
    let pdf = match shape {
        Shape::Sphere(s) => match (strategy, cone(p, s)) {
            (SphereSampling::Cone, Some((_, omc))) => Some(1.0 / (TAU * omc)),
            _ => area_to_solid_angle(p, y, n, sphere_area(s)),
        },
        Shape::Quad(q) => area_to_solid_angle(p, y, n, q.area()),
        _ => None,
    };
    pdf.filter(|p| p.is_finite()).unwrap_or(0.0)
}
