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
//!
//! Each strategy is a function beside its density (`sphere_area` and
//! `sphere_area_pdf`, `sphere_cone` and `sphere_cone_pdf`, `quad_area` and
//! `quad_area_pdf`), and [`LightShape`] holds a light's shape with the strategy its
//! kind allows: a sphere by area or by cone, a quad by area.
//! `tests/lessons/lesson_10_densities.rs` checks that each density integrates to 1 over
//! the directions and matches a histogram of samples.

use std::f32::consts::PI;

use glam::{Vec2, Vec3};

use crate::basis::Basis;
use crate::ray::{Interval, Ray};
use crate::sampling::{uniform_cone, uniform_cone_pdf, uniform_sphere};
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
    /// A bound on y's rounding error, per coordinate (see
    /// [`crate::shapes::Hit::error`]).
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

// ANCHOR_END: cone

/// A light's shape with the strategy that chooses its points: each kind of shape
/// has its own strategies, so a quad is never asked how a sphere is sampled.
///
/// ```
/// use glam::{Vec2, Vec3};
/// use render_lessons::pathtrace::light::{LightShape, SphereSampling};
/// use render_lessons::shapes::{Quad, Shape, Sphere};
///
/// let bulb = Shape::from(Sphere::new(Vec3::new(0.0, 3.0, 0.0), 1.0)?);
/// let light = LightShape::new(&bulb, SphereSampling::Cone).unwrap();
/// let y = light.sample(Vec3::ZERO, Vec2::new(0.3, 0.6)).unwrap();
/// // The density the sample reports is the one `pdf` gives for its point: what MIS needs.
/// assert_eq!(light.pdf(Vec3::ZERO, y.point, y.normal), y.pdf);
///
/// // A quad has one strategy; the spheres' choice does not reach it.
/// let panel = Shape::from(Quad::new(Vec3::new(-1.0, 3.0, -1.0), 2.0 * Vec3::X, 2.0 * Vec3::Z)?);
/// assert!(matches!(LightShape::new(&panel, SphereSampling::Cone), Some(LightShape::Quad(_))));
/// # Ok::<(), render_lessons::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightShape {
    /// A sphere, sampled by area or by the cone it subtends.
    Sphere(Sphere, SphereSampling),
    /// A quad, sampled uniformly by area, its only strategy.
    Quad(Quad),
}

impl LightShape {
    /// `shape` as a light, spheres sampled by `spheres`; `None` for a shape no
    /// strategy here can sample (only spheres and quads can be lights).
    pub fn new(shape: &Shape, spheres: SphereSampling) -> Option<LightShape> {
        match shape {
            Shape::Sphere(s) => Some(LightShape::Sphere(*s, spheres)),
            Shape::Quad(q) => Some(LightShape::Quad(*q)),
            _ => None,
        }
    }

    /// A point of the light chosen from `p` with the uniform numbers `u`, by the
    /// shape's strategy; `None` if none can be chosen (no finite density).
    pub fn sample(&self, p: Vec3, u: Vec2) -> Option<LightPoint> {
        match *self {
            LightShape::Sphere(s, SphereSampling::Area) => sphere_area(&s, p, u),
            LightShape::Sphere(s, SphereSampling::Cone) => sphere_cone(&s, p, u),
            LightShape::Quad(q) => quad_area(&q, p, u),
        }
    }

    /// The solid-angle density with which [`LightShape::sample`] would have chosen
    /// the point `y` (normal `n`) from `p`; 0 where it cannot be chosen or the density
    /// is not finite. Used for the MIS weight of a path that hits a light by BRDF
    /// sampling.
    pub fn pdf(&self, p: Vec3, y: Vec3, n: Vec3) -> f32 {
        match *self {
            LightShape::Sphere(s, SphereSampling::Area) => sphere_area_pdf(&s, p, y, n),
            LightShape::Sphere(s, SphereSampling::Cone) => sphere_cone_pdf(&s, p, y, n),
            LightShape::Quad(q) => quad_area_pdf(&q, p, y, n),
        }
    }
}

/// A point of the sphere `s` chosen uniformly over its area, seen from `p`.
pub fn sphere_area(s: &Sphere, p: Vec3, u: Vec2) -> Option<LightPoint> {
    let normal = uniform_sphere(u);
    let (point, error) = s.surface_point(normal);
    let pdf = area_to_solid_angle(p, point, normal, sphere_area_of(s))?;
    Some(LightPoint {
        point,
        normal,
        error,
        pdf,
    })
}

/// The solid-angle density at `p` of [`sphere_area`] choosing `y` (normal `n`):
/// |y - p|^2 / (A |cos theta_l|), A = 4 pi r^2; 0 where it is not finite.
pub fn sphere_area_pdf(s: &Sphere, p: Vec3, y: Vec3, n: Vec3) -> f32 {
    finite_or_zero(area_to_solid_angle(p, y, n, sphere_area_of(s)))
}

/// A point of the sphere `s` chosen uniformly inside the cone of directions from `p`
/// that meet it, the first point each direction meets; [`sphere_area`] where no
/// cone exists (`p` inside the sphere, on it, or within 0.05 % of its radius).
pub fn sphere_cone(s: &Sphere, p: Vec3, u: Vec2) -> Option<LightPoint> {
    let Some((axis, omc)) = cone(p, s) else {
        return sphere_area(s, p, u);
    };
    let ray = Ray::new(p, Basis::around(axis).to_world(uniform_cone(omc, u))).ok()?;
    let hit = s.hit(&ray, Interval::AHEAD)?;
    let pdf = uniform_cone_pdf(omc);
    pdf.is_finite().then_some(LightPoint {
        point: hit.point,
        normal: hit.normal,
        error: hit.error,
        pdf,
    })
}

/// The solid-angle density at `p` of [`sphere_cone`] choosing `y` (normal `n`):
/// 1 / (2 pi (1 - cos theta_max)) for every point of the visible cap, whatever `y`
/// (the caller passes a point the cone can reach); [`sphere_area_pdf`] where no cone
/// exists; 0 where it is not finite.
pub fn sphere_cone_pdf(s: &Sphere, p: Vec3, y: Vec3, n: Vec3) -> f32 {
    match cone(p, s) {
        Some((_, omc)) => finite_or_zero(Some(uniform_cone_pdf(omc))),
        None => sphere_area_pdf(s, p, y, n),
    }
}

/// A point of the quad `q` chosen uniformly over its area, seen from `p`.
pub fn quad_area(q: &Quad, p: Vec3, u: Vec2) -> Option<LightPoint> {
    let point = q.point(u.x, u.y);
    let pdf = area_to_solid_angle(p, point, q.normal(), q.area())?;
    Some(LightPoint {
        point,
        normal: q.normal(),
        error: q.error_at(point),
        pdf,
    })
}

/// The solid-angle density at `p` of [`quad_area`] choosing `y` (normal `n`):
/// |y - p|^2 / (A |cos theta_l|); 0 where it is not finite.
pub fn quad_area_pdf(q: &Quad, p: Vec3, y: Vec3, n: Vec3) -> f32 {
    finite_or_zero(area_to_solid_angle(p, y, n, q.area()))
}

fn sphere_area_of(s: &Sphere) -> f32 {
    4.0 * PI * s.radius() * s.radius()
}

/// The density if it is a finite number, else 0.
fn finite_or_zero(pdf: Option<f32>) -> f32 {
    pdf.filter(|p| p.is_finite()).unwrap_or(0.0)
}
