//! Ray / general quadric: the points x = (x, y, z, 1) with x^T Q x = 0, for a
//! symmetric 4x4 matrix Q (Haines, "Essential Ray Tracing Algorithms", in Glassner
//! (ed.), An Introduction to Ray Tracing, 1989, section "Ray/Quadric Intersection").
//!
//! One matrix covers ellipsoids, cylinders, cones, paraboloids and hyperboloids.
//! Along the ray, with the homogeneous origin o = (o, 1) and direction d = (d, 0),
//! (o + t d)^T Q (o + t d) = a t^2 + b t + c with
//! a = d^T Q d, b = 2 d^T Q o, c = o^T Q o (Q symmetric, so d^T Q o = o^T Q d).
//!
//! Unlike the sphere's, this `a` can be zero: a ray parallel to a paraboloid's or a
//! cylinder's axis, or to a cone's generator, meets the surface once, and the
//! quadratic degenerates to the line b t + c = 0. The textbook formula divides by
//! 2a and fails as a -> 0; the stable form has no special case (STABILITY S9).

use glam::{DVec3, Mat4, Vec3, Vec4};

use crate::error::{Error, Problem, Result, positive, unit};
use crate::float::{difference_of_products, gamma};
use crate::quadratic;
use crate::ray::{Crossings, Interval, Ray};
use crate::shapes::Hit;

/// Largest asymmetry |Q_ij - Q_ji| accepted, relative to the largest |Q_ij|: a few
/// f32 roundings, so that a matrix computed as M^-T Q M^-1 still passes.
pub const SYMMETRY_TOLERANCE: f32 = 1e-5;

/// The surface x^T Q x = 0 of a symmetric 4x4 matrix Q in homogeneous coordinates.
///
/// Outside is where x^T Q x > 0: the normal (the gradient of x^T Q x) points there.
/// Negating Q describes the same surface with the other side outside.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quadric {
    q: Mat4,
}

impl Quadric {
    /// The quadric x^T Q x = 0.
    ///
    /// Rejects, naming `Q`: a non-finite entry ([`Problem::NotFinite`]); an asymmetry
    /// max |Q_ij - Q_ji| above [`SYMMETRY_TOLERANCE`] times max |Q_ij| (reported as
    /// [`Problem::NotSymmetric`] with that relative asymmetry as its `error`); and a
    /// matrix whose quadratic part (upper-left 3x3) and linear part (Q_i3, i < 3) are
    /// both zero ([`Problem::ZeroLength`]): x^T Q x is then the constant Q_33, and its
    /// zero set is empty or all of space. That includes Q = 0.
    pub fn new(q: Mat4) -> Result<Quadric> {
        if !q.is_finite() {
            return Err(Error::Value {
                param: "Q",
                problem: Problem::NotFinite,
            });
        }
        let m = q.to_cols_array_2d();
        let mut scale = 0.0_f32;
        let mut asym = 0.0_f32;
        let mut xyz_part = 0.0_f32;
        for (i, row) in m.iter().enumerate() {
            for (j, &v) in row.iter().enumerate() {
                scale = scale.max(v.abs());
                asym = asym.max((v - m[j][i]).abs());
                if i < 3 || j < 3 {
                    xyz_part = xyz_part.max(v.abs());
                }
            }
        }
        if xyz_part == 0.0 {
            return Err(Error::Value {
                param: "Q",
                problem: Problem::ZeroLength,
            });
        }
        // scale > 0 here, since xyz_part > 0.
        let relative = asym / scale;
        if relative > SYMMETRY_TOLERANCE {
            return Err(Error::Value {
                param: "Q",
                problem: Problem::NotSymmetric { error: relative },
            });
        }
        Ok(Quadric { q })
    }

    /// The ellipsoid x^2/r_x^2 + y^2/r_y^2 + z^2/r_z^2 = 1 centred at the origin:
    /// Q = diag(1/r_x^2, 1/r_y^2, 1/r_z^2, -1).
    ///
    /// Each radius must be finite and positive, and so must 1/r^2 (no overflow or
    /// underflow); errors name `radii`.
    pub fn ellipsoid(radii: Vec3) -> Result<Quadric> {
        let inv = |r: f32| -> Result<f32> {
            positive("radii", 1.0 / (positive("radii", r)? * r))
        };
        let (ix, iy, iz) = (inv(radii.x)?, inv(radii.y)?, inv(radii.z)?);
        Quadric::new(Mat4::from_diagonal(Vec4::new(ix, iy, iz, -1.0)))
    }

    /// The infinite circular cylinder about the Z axis, x^2 + y^2 = r^2:
    /// Q = diag(1, 1, 0, -r^2).
    ///
    /// `radius` and its square must be finite and positive; errors name `radius`.
    pub fn cylinder(radius: f32) -> Result<Quadric> {
        let r2 = positive("radius", positive("radius", radius)? * radius)?;
        Quadric::new(Mat4::from_diagonal(Vec4::new(1.0, 1.0, 0.0, -r2)))
    }

    /// The infinite double cone about the Z axis with its apex at the origin,
    /// x^2 + y^2 = (s z)^2, where the slope s is the radius per unit of height:
    /// Q = diag(1, 1, -s^2, 0).
    ///
    /// `slope` and its square must be finite and positive; errors name `slope`.
    pub fn cone(slope: f32) -> Result<Quadric> {
        let s2 = positive("slope", positive("slope", slope)? * slope)?;
        Quadric::new(Mat4::from_diagonal(Vec4::new(1.0, 1.0, -s2, 0.0)))
    }

    // ANCHOR: along_axis
    /// The infinite circular cylinder of radius `radius` about the line through the
    /// origin along `axis` (normalised here to a): the points whose distance from the
    /// axis, |x|^2 - (a.x)^2, squared, is r^2. So Q's upper-left 3x3 block is
    /// I - a a^T and Q_33 = -r^2; `cylinder_along(Vec3::Z, r)` is
    /// [`Quadric::cylinder`]. A cylinder elsewhere is an [`crate::shapes::Instance`] of
    /// this one, translated.
    ///
    /// The Ray Tracer Challenge's cylinder (ch. 13) is `cylinder_along(Vec3::Y, 1.0)`,
    /// without its caps. Errors name `axis` (zero or not finite) and `radius`.
    pub fn cylinder_along(axis: Vec3, radius: f32) -> Result<Quadric> {
        let a = unit("axis", axis)?;
        let r2 = positive("radius", positive("radius", radius)? * radius)?;
        Quadric::new(along(a, 0.0, -r2))
    }

    /// The infinite double cone about the line through the origin along `axis`
    /// (normalised to a), apex at the origin, radius `slope` times the height along a:
    /// |x|^2 - (a.x)^2 = k^2 (a.x)^2 with k the slope, so Q's upper-left block is
    /// I - a a^T - k^2 a a^T and Q_33 = 0; `cone_along(Vec3::Z, k)` is
    /// [`Quadric::cone`].
    ///
    /// The Ray Tracer Challenge's cone (ch. 13) is `cone_along(Vec3::Y, 1.0)`, without
    /// its caps. Errors name `axis` and `slope`.
    pub fn cone_along(axis: Vec3, slope: f32) -> Result<Quadric> {
        let a = unit("axis", axis)?;
        let k2 = positive("slope", positive("slope", slope)? * slope)?;
        Quadric::new(along(a, k2, 0.0))
    }
    // ANCHOR_END: along_axis

    /// The paraboloid z = x^2 + y^2, a bowl opening towards +Z; x^T Q x = x^2 + y^2 - z
    /// with Q_00 = Q_11 = 1 and Q_23 = Q_32 = -1/2 (the linear term -z w is split
    /// between the two symmetric entries).
    pub fn paraboloid() -> Result<Quadric> {
        Quadric::new(Mat4::from_cols(
            Vec4::new(1.0, 0.0, 0.0, 0.0),
            Vec4::new(0.0, 1.0, 0.0, 0.0),
            Vec4::new(0.0, 0.0, 0.0, -0.5),
            Vec4::new(0.0, 0.0, -0.5, 0.0),
        ))
    }

    /// The matrix Q.
    pub fn matrix(&self) -> Mat4 {
        self.q
    }

    /// x^T Q x at the point p (x = (p, 1)): zero on the surface, positive outside.
    pub fn value(&self, p: Vec3) -> f32 {
        let x = p.extend(1.0);
        x.dot(self.q * x)
    }

    /// The gradient of x^T Q x at p: the xyz part of 2 Q x (Q symmetric). Not
    /// normalised; zero at a cone's apex.
    pub fn gradient(&self, p: Vec3) -> Vec3 {
        2.0 * (self.q * p.extend(1.0)).truncate()
    }

    /// The coefficients (a, b, c) of a t^2 + b t + c along the ray:
    /// a = d^T Q d, b = 2 d^T Q o, c = o^T Q o.
    pub fn coefficients(&self, ray: &Ray) -> (f32, f32, f32) {
        let o = ray.origin().extend(1.0);
        let d = ray.direction().extend(0.0);
        let qo = self.q * o;
        (d.dot(self.q * d), 2.0 * d.dot(qo), o.dot(qo))
    }

    // ANCHOR: quadric_roots_textbook
    /// The roots by the school formula ([`quadratic::textbook`]), with no special
    /// case for a = 0.
    ///
    /// As a -> 0 (a ray nearly parallel to a paraboloid's axis) one root runs off to
    /// infinity and the other, the one that matters, is -b + sqrt(b^2 - 4ac) with
    /// b^2 >> 4ac: two nearly equal numbers subtracted, then divided by the tiny 2a.
    /// In f32 it is tens of percent off at a ~ 1e-8, garbage or missing below, and at
    /// a = 0 it is 0/0 and the hit is lost (STABILITY S9). Kept to show that failure.
    pub fn roots_textbook(&self, ray: &Ray) -> Crossings {
        let (a, b, c) = self.coefficients(ray);
        quadratic::textbook(a, b, c)
    }
    // ANCHOR_END: quadric_roots_textbook

    // ANCHOR: quadric_roots_stable
    /// The roots computed so that neither cancels, and a -> 0 needs no special case:
    /// [`quadratic::stable`], whose c/q tends to the root -c/b of the linear equation
    /// b t + c = 0 as a -> 0, and leaves one root at a = 0.
    ///
    /// The discriminant is formed as a difference of products with one fused
    /// multiply-add correction ([`difference_of_products`]), accurate to a few ulps
    /// even when b^2 and 4ac nearly cancel (a grazing ray); a tangent ray's, rounded a
    /// few ulps below 0, counts as 0 ([`quadratic::tangent_as_zero`]).
    pub fn roots_stable(&self, ray: &Ray) -> Crossings {
        let (a, b, c) = self.coefficients(ray);
        let disc = difference_of_products(b, b, 4.0 * a, c);
        let disc = quadratic::tangent_as_zero(disc, b * b, 4.0 * a * c);
        quadratic::stable(a, b, c, disc)
    }
    // ANCHOR_END: quadric_roots_stable

    // ANCHOR: quadric_hit
    /// The nearest crossing within `range`, using [`Quadric::roots_stable`].
    ///
    /// The normal is the normalised gradient, the xyz part of 2 Q x: it points to
    /// where x^T Q x > 0 (outward for the named constructors). Where the gradient
    /// vanishes (a cone's apex) there is no normal; `-d` stands in for it.
    pub fn hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let t = self.nearest(ray, range)?;
        Some(self.hit_at(ray, t))
    }

    /// The smallest root within `range`, by [`Quadric::roots_stable`].
    pub fn nearest(&self, ray: &Ray, range: Interval) -> Option<f32> {
        self.roots_stable(ray).first_in(range)
    }

    /// The hit record at `t`: the point o + t d moved onto the surface
    /// ([`Quadric::refine`]), its error bound, and the normalised gradient there.
    pub fn hit_at(&self, ray: &Ray, t: f32) -> Hit {
        let (point, error) = self.refine(ray.at(t));
        let normal = self.gradient(point).normalize_or(-ray.direction());
        Hit::new(ray, t, point, normal, error)
    }
    // ANCHOR_END: quadric_hit

    // ANCHOR: quadric_refine
    /// `p` (near the surface) moved onto it, and a bound on the result's error.
    ///
    /// o + t d carries t's error, which grows with t. A general quadric has no
    /// closed-form projection, so Newton's method does it in f64, where the f32 input
    /// is exact: p <- p - F(p) g / |g|^2 with F = x^T Q x and g its gradient, a few
    /// times (each step squares the distance left). The bound, per coordinate: the
    /// rounding back to f32, gamma(1) |p|; the distance Newton left, |F| / |g|; and
    /// the rounding of F itself in f32, gamma(8) sum |Q_ij x_i x_j| / |g|, so that a
    /// ray spawned past the bound also finds F of the right sign at its origin.
    pub fn refine(&self, p: Vec3) -> (Vec3, Vec3) {
        let q = self.q.as_dmat4();
        let value = |x: DVec3| x.extend(1.0).dot(q * x.extend(1.0));
        let grad = |x: DVec3| 2.0 * (q * x.extend(1.0)).truncate();
        let mut x = p.as_dvec3();
        for _ in 0..4 {
            let g = grad(x);
            let step = value(x) / g.length_squared() * g;
            if !step.is_finite() {
                break;
            }
            x -= step;
        }
        let point = x.as_vec3();
        let point = if point.is_finite() { point } else { p };
        let x = point.as_dvec3();
        let g = grad(x).length();
        let h = x.extend(1.0).abs();
        let size = h.dot(q.abs() * h);
        let left = (value(x).abs() + f64::from(gamma(8)) * size) / g;
        let left = if left.is_finite() { left as f32 } else { 0.0 };
        (point, gamma(1) * point.abs() + Vec3::splat(left))
    }
    // ANCHOR_END: quadric_refine

    /// Every crossing of the ray's line, ascending, from [`Quadric::roots_stable`]:
    /// two, one (a ray parallel to a cone's generator or a paraboloid's axis), or none.
    pub fn crossings(&self, ray: &Ray) -> Crossings {
        self.roots_stable(ray)
    }

    /// The unit normal at the surface point `p`: the normalised gradient, the xyz part
    /// of 2 Q (p, 1), pointing to where x^T Q x > 0; the zero vector where the
    /// gradient vanishes (a cone's apex).
    pub fn normal_at(&self, p: Vec3) -> Vec3 {
        self.gradient(p).normalize_or_zero()
    }
}

/// The symmetric matrix with upper-left block (delta_ij - a_i a_j) - k a_i a_j, zero
/// linear part and Q_33 = `w`: a cylinder (k = 0) or cone (k = s^2) about the unit
/// axis `a`. Each entry is a product a_i a_j rounded once, so Q is exactly symmetric,
/// and for a = e_z the entries are exactly those of diag(1, 1, -k, w).
fn along(a: Vec3, k: f32, w: f32) -> Mat4 {
    let mut m = [[0.0_f32; 4]; 4];
    for (i, row) in m.iter_mut().enumerate().take(3) {
        for (j, entry) in row.iter_mut().enumerate().take(3) {
            let delta = if i == j { 1.0 } else { 0.0 };
            let aa = a[i] * a[j];
            *entry = (delta - aa) - k * aa;
        }
    }
    m[3][3] = w;
    Mat4::from_cols_array_2d(&m)
}
