//! Ray / triangle: Möller-Trumbore (JGT 1997) and the watertight test of Woop,
//! Benthin and Wald (JCGT 2013).

use glam::{Vec3, Vec4, Vec4Swizzles};

use crate::error::{Error, Problem, Result, finite3};
use crate::float::gamma;
use crate::ray::{Interval, Ray};
use crate::shapes::{Aabb, Crossings, Hit, PreparedRay};

// ANCHOR: barycentric
/// Where a ray crosses a triangle: the distance `t` along the ray and the barycentric
/// coordinates `b` = (b0, b1, b2) of the point, p = b0 v0 + b1 v1 + b2 v2 with
/// b0 + b1 + b2 = 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Barycentric {
    /// The ray parameter of the crossing.
    pub t: f32,
    /// The weights of v0, v1 and v2.
    pub b: [f32; 3],
}
// ANCHOR_END: barycentric

// ANCHOR: triangle
/// The triangle with corners `v0`, `v1`, `v2`; its front is the side from which they
/// run counter-clockwise, where (v1 - v0) x (v2 - v0) points.
///
/// Stored axis by axis: `by_axis[0]` holds the x of v0, v1 and v2 in three lanes of
/// a 4-wide vector (the fourth is 0), `by_axis[1]` their y, `by_axis[2]` their z, so
/// that the watertight test works on the three corners at once, one lane each.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle {
    by_axis: [Vec4; 3],
}
// ANCHOR_END: triangle

impl Triangle {
    /// The triangle `v0, v1, v2`.
    ///
    /// Rejects non-finite corners, and a degenerate triangle (zero area: the cross
    /// product of two edges is zero, or too small to normalise) with
    /// [`Problem::NotPositive`] naming `area`.
    pub fn new(v0: Vec3, v1: Vec3, v2: Vec3) -> Result<Triangle> {
        let tri = Triangle::from_checked(
            finite3("v0", v0)?,
            finite3("v1", v1)?,
            finite3("v2", v2)?,
        );
        let cross = (v1 - v0).cross(v2 - v0);
        if cross.normalize_or_zero() == Vec3::ZERO {
            let area = 0.5 * cross.length();
            let value = if area.is_finite() { area } else { 0.0 };
            return Err(Error::Value {
                param: "area",
                problem: Problem::NotPositive { value },
            });
        }
        Ok(tri)
    }

    /// The triangle of corners the caller has already checked ([`Triangle::new`]
    /// accepted them once), such as a mesh's.
    pub(crate) fn from_checked(v0: Vec3, v1: Vec3, v2: Vec3) -> Triangle {
        let axis = |a: usize| Vec4::new(v0[a], v1[a], v2[a], 0.0);
        Triangle {
            by_axis: [axis(0), axis(1), axis(2)],
        }
    }

    /// The three corners.
    pub fn vertices(&self) -> [Vec3; 3] {
        let [x, y, z] = self.by_axis;
        [0, 1, 2].map(|i| Vec3::new(x[i], y[i], z[i]))
    }

    /// The unit geometric normal, normalize((v1 - v0) x (v2 - v0)).
    pub fn normal(&self) -> Vec3 {
        let [v0, v1, v2] = self.vertices();
        (v1 - v0).cross(v2 - v0).normalize_or(Vec3::Z)
    }

    /// The bounding box of the three corners: exact, no rounding. STABILITY S6 is the
    /// promise that a ray the triangle test hits also passes the conservative slab
    /// test on this box.
    pub fn bounds(&self) -> Option<Aabb> {
        Aabb::around(self.vertices())
    }

    // ANCHOR: moller_trumbore
    /// Möller and Trumbore (JGT 1997): solve o + t d = (1 - b1 - b2) v0 + b1 v1 + b2 v2
    /// by Cramer's rule. With e1 = v1 - v0, e2 = v2 - v0, p = d x e2, T = o - v0 and
    /// q = T x e1: det = e1 . p, b1 = T . p / det, b2 = d . q / det, t = e2 . q / det
    /// (the paper's names: `tvec` is T).
    ///
    /// Returns the crossing for a hit with `t` in `range`. Fast, but b1 and b2
    /// of two triangles sharing an edge are rounded separately, so a ray aimed exactly
    /// at the edge or a vertex can slip between them (STABILITY S4, S5).
    pub fn moller_trumbore(&self, ray: &Ray, range: Interval) -> Option<Barycentric> {
        let (o, d) = (ray.origin(), ray.direction());
        let [v0, v1, v2] = self.vertices();
        let (e1, e2) = (v1 - v0, v2 - v0);
        let p = d.cross(e2);
        let det = e1.dot(p);
        if det == 0.0 {
            return None; // the ray is parallel to the plane
        }
        let inv = 1.0 / det;
        let tvec = o - v0;
        let b1 = tvec.dot(p) * inv;
        if !(0.0..=1.0).contains(&b1) {
            return None; // also catches NaN
        }
        let q = tvec.cross(e1);
        let b2 = d.dot(q) * inv;
        if !(b2 >= 0.0 && b1 + b2 <= 1.0) {
            return None;
        }
        let t = e2.dot(q) * inv;
        let b = [1.0 - b1 - b2, b1, b2];
        range.contains(t).then_some(Barycentric { t, b })
    }
    // ANCHOR_END: moller_trumbore

    /// [`Triangle::watertight_prepared`] for a single ray: prepares it first.
    pub fn watertight(&self, ray: &Ray, range: Interval) -> Option<Barycentric> {
        self.watertight_prepared(&PreparedRay::new(ray), range)
    }

    // ANCHOR: watertight
    /// The watertight test of Woop, Benthin and Wald (JCGT 2013), as in pbrt-v3/v4.
    ///
    /// Translate the vertices so the ray starts at the origin, permute the axes so the
    /// largest component of d is z, and shear so d becomes (0, 0, 1): the ray is now
    /// the z axis and the test is 2-D. The permutation and the shear depend on the ray
    /// alone, so [`PreparedRay`] computes them once per ray. The edge functions
    /// e0 = p1.x p2.y - p1.y p2.x (and cyclically) are the same numbers, bit for bit,
    /// for the two triangles sharing an edge, so no ray slips between them; when one
    /// is exactly 0 it is recomputed in f64 so that its sign is right. A hit needs all
    /// three of one sign; then b_i = e_i / (e0 + e1 + e2) and t interpolates the
    /// sheared z. The three corners are the lanes of [`Triangle`]'s 4-wide vectors, so
    /// each step is one operation for all three (the fourth lane is ignored).
    ///
    /// Returns the crossing for a hit with `t` in `range`. Always inlined: the
    /// loops that test triangle after triangle (a BVH leaf, a scene's list) then
    /// keep the ray in registers instead of passing it through memory for each call.
    #[inline(always)]
    pub fn watertight_prepared(
        &self,
        ray: &PreparedRay,
        range: Interval,
    ) -> Option<Barycentric> {
        let (o, shear) = (ray.ray().origin().to_array(), ray.shear);
        let [kx, ky, kz] = ray.axes;
        // Lane i is corner i, relative to o along kx, ky and kz, then sheared.
        let relative = |k: usize| self.by_axis[k] - Vec4::splat(o[k]);
        let z = relative(kz);
        let x = relative(kx) + shear.x * z;
        let y = relative(ky) + shear.y * z;
        // Lane i: the edge function of the two corners after corner i, cyclically.
        let mut e = x.yzxw() * y.zxyw() - y.yzxw() * x.zxyw();
        if e.cmpeq(Vec4::ZERO).bitmask() & CORNERS != 0 {
            e = edges_f64(x, y);
        }
        let any_negative = e.cmplt(Vec4::ZERO).bitmask() & CORNERS != 0;
        let any_positive = e.cmpgt(Vec4::ZERO).bitmask() & CORNERS != 0;
        let det = e.x + e.y + e.z;
        if (any_negative && any_positive) || det == 0.0 {
            return None;
        }
        let z = z * shear.z;
        let ez = e * z;
        let t_scaled = ez.x + ez.y + ez.z;
        if surely_outside(t_scaled, det, range) {
            return None; // before the division, which most rejected candidates skip
        }
        let inv = 1.0 / det;
        let (t, b) = (t_scaled * inv, [e.x * inv, e.y * inv, e.z * inv]);
        let finite = b.iter().all(|x| x.is_finite());
        if range.min >= 0.0 && t <= t_error([x, y, z], e, inv) {
            return None; // t may be rounding above a crossing at or behind the origin
        }
        (finite && range.contains(t)).then_some(Barycentric { t, b })
    }
    // ANCHOR_END: watertight

    // ANCHOR: triangle_hit
    /// The hit record of a `crossing` (from [`Triangle::watertight`]): at its `t`, with
    /// its barycentric coordinates `b`.
    ///
    /// The point is b0 v0 + b1 v1 + b2 v2, not o + t d: far from the origin the
    /// barycentric point stays on the triangle's plane, o + t d does not (STABILITY
    /// S7). Its error bound is gamma(7) (|b0 v0| + |b1 v1| + |b2 v2|) per coordinate.
    pub fn hit_at(&self, ray: &Ray, crossing: Barycentric) -> Hit {
        let (t, b) = (crossing.t, crossing.b);
        let [v0, v1, v2] = self.vertices();
        let [w0, w1, w2] = [b[0] * v0, b[1] * v1, b[2] * v2];
        let point = w0 + w1 + w2;
        // pbrt-v4 section 6.8.5: three products and two sums, gamma(7) of their sizes.
        let error = gamma(7) * (w0.abs() + w1.abs() + w2.abs());
        Hit::new(ray, t, point, self.normal(), error)
    }

    /// The crossing within `range`, by [`Triangle::watertight`].
    pub fn hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let crossing = self.watertight(ray, range)?;
        Some(self.hit_at(ray, crossing))
    }
    // ANCHOR_END: triangle_hit

    /// The crossing of the ray's line with the triangle, if any:
    /// [`Triangle::watertight`] over the whole line, -inf < t < inf.
    pub fn crossings(&self, ray: &Ray) -> Crossings {
        self.watertight(ray, Interval::EVERYWHERE)
            .map_or(Crossings::NONE, |crossing| Crossings::one(crossing.t))
    }

    /// The unit normal normalize(e1 x e2), e1 = v1 - v0, e2 = v2 - v0, the same at
    /// every point `_p` (see [`Triangle::normal`]). A left-handed course such as The
    /// Ray Tracer Challenge writes e2 x e1: list its corners as v0, v2, v1 here to keep
    /// its normal.
    pub fn normal_at(&self, _p: Vec3) -> Vec3 {
        self.normal()
    }
}

/// True if t = `t_scaled` / `det` certainly lies outside `range`, decided
/// without dividing (pbrt-v4 does the same): behind the origin when `range.min >= 0`
/// and the signs differ, or beyond `range.max` with a margin of 8 ulps, far more
/// than the rounding of the quotient and of `range.max |det|`. A NaN decides nothing.
fn surely_outside(t_scaled: f32, det: f32, range: Interval) -> bool {
    const MARGIN: f32 = 1.0 + 8.0 * f32::EPSILON;
    let (t_abs, det_abs) = if det < 0.0 {
        (-t_scaled, -det)
    } else {
        (t_scaled, det)
    };
    (range.min >= 0.0 && t_abs <= 0.0) || t_abs > range.max * det_abs * MARGIN
}

// ANCHOR: t_error
/// A bound on the rounding error of the watertight test's t (pbrt-v4 section 6.8.4,
/// "Conservative Ray-Triangle t Tests"), from the sheared corners' `x`, `y` and
/// scaled `z` (lane i corner i), the edge functions `e` and 1/det. Each sheared x, y
/// is off by gamma(5) (|x| + |z|) at most, each scaled z by gamma(3) |z|; an edge
/// function multiplies two of them, and t sums three e_i z_i. A t below this bound
/// cannot be told from 0: a ray leaving the triangle's own plane would find the
/// triangle again just past its origin.
fn t_error([x, y, z]: [Vec4; 3], e: Vec4, inv_det: f32) -> f32 {
    // The largest magnitude among the three corners' lanes.
    let largest = |v: Vec4| v.abs().truncate().max_element();
    let (max_x, max_y, max_z, max_e) = (largest(x), largest(y), largest(z), largest(e));
    let delta_x = gamma(5) * (max_x + max_z);
    let delta_y = gamma(5) * (max_y + max_z);
    let delta_z = gamma(3) * max_z;
    let delta_e = 2.0 * (gamma(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
    3.0 * (gamma(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * inv_det.abs()
}
// ANCHOR_END: t_error

/// The lanes of the three corners in a 4-wide comparison's bitmask.
const CORNERS: u32 = 0b111;

/// The three edge functions of [`Triangle::watertight_prepared`] again, each in f64,
/// where the product of two f32 is exact: lane i of `x` and `y` is corner i.
fn edges_f64(x: Vec4, y: Vec4) -> Vec4 {
    let edge = |a: usize, b: usize| {
        let (ax, ay, bx, by) = (x[a] as f64, y[a] as f64, x[b] as f64, y[b] as f64);
        (ax * by - ay * bx) as f32
    };
    Vec4::new(edge(1, 2), edge(2, 0), edge(0, 1), 0.0)
}
