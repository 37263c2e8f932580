//! Ray / axis-aligned box: the slab test (Kay and Kajiya 1986, in the form of pbrt-v4
//! `Bounds3::IntersectP`).

use glam::Vec3;

use crate::error::{Error, Problem, Result, finite3};
use crate::float::{gamma, moved_out};
use crate::ray::{ClosedSpan, Crossings, Interval, Ray};
use crate::shapes::{Hit, PreparedRay};

/// Where a ray crosses a box's surface: the distance `t`, the `axis` of the face
/// (0, 1, 2 for x, y, z) and the sign `outward` (+1 or -1) of the face's outward
/// normal along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FaceHit {
    /// The ray parameter of the crossing.
    pub t: f32,
    /// The axis the face is perpendicular to.
    pub axis: usize,
    /// The sign of the outward normal along `axis`.
    pub outward: f32,
}

/// The box of points with `min <= p <= max` on every axis (a closed set).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    min: Vec3,
    max: Vec3,
}

/// The entry and exit of one slab, with the axis index that produced each.
#[derive(Clone, Copy, Debug)]
struct Span {
    t0: f32,
    axis0: usize,
    t1: f32,
    axis1: usize,
}

impl Aabb {
    /// The box from `min` to `max`.
    ///
    /// Rejects non-finite corners, and `min > max` on any axis with
    /// [`Problem::EmptyRange`] naming `box`; `min == max` is allowed (a box of zero
    /// thickness, such as a flat quad's bounds).
    pub fn new(min: Vec3, max: Vec3) -> Result<Aabb> {
        let (min, max) = (finite3("min", min)?, finite3("max", max)?);
        for i in 0..3 {
            if min[i] > max[i] {
                return Err(Error::Value {
                    param: "box",
                    problem: Problem::EmptyRange {
                        min: min[i],
                        max: max[i],
                    },
                });
            }
        }
        Ok(Aabb { min, max })
    }

    /// The corner with the smallest coordinates.
    pub fn min(&self) -> Vec3 {
        self.min
    }

    /// The corner with the largest coordinates.
    pub fn max(&self) -> Vec3 {
        self.max
    }

    /// The smallest box holding both `self` and `other`.
    pub fn union(&self, other: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// The smallest box holding every point of `points`, or `None` for no points or
    /// a non-finite one.
    pub fn around(points: impl IntoIterator<Item = Vec3>) -> Option<Aabb> {
        let mut points = points.into_iter();
        let first = points.next()?;
        let (min, max) =
            points.fold((first, first), |(lo, hi), p| (lo.min(p), hi.max(p)));
        Aabb::new(min, max).ok()
    }

    /// The centre point (min + max) / 2.
    pub fn centre(&self) -> Vec3 {
        0.5 * (self.min + self.max)
    }

    /// The area of the box's surface, 2 (xy + yz + zx): the measure of how likely a
    /// random ray is to hit it, which the surface area heuristic uses.
    pub fn surface_area(&self) -> f32 {
        let e = self.max - self.min;
        2.0 * (e.x * e.y + e.y * e.z + e.z * e.x)
    }

    /// True if `other` lies inside `self` (the closed box; equal boxes count).
    pub fn contains(&self, other: &Aabb) -> bool {
        self.min.cmple(other.min).all() && other.max.cmple(self.max).all()
    }

    /// The box moved outwards by `margin >= 0` on every side, or `None` if a corner
    /// overflows.
    pub fn padded(&self, margin: f32) -> Option<Aabb> {
        Aabb::new(
            self.min - Vec3::splat(margin),
            self.max + Vec3::splat(margin),
        )
        .ok()
    }

    // ANCHOR: slab
    /// The slab test: the closed interval `[t0, t1]` of the ray inside the box,
    /// clipped to `range`, or `None`.
    ///
    /// Convention: INCLUSIVE. The box is closed and the result is a hit whenever
    /// t0 <= t1, so a ray that grazes an edge, touches a corner or runs along a face
    /// plane over the face hits, with t0 == t1 for a single touching point (STABILITY
    /// S8).
    ///
    /// Per axis, t = (min - o) / d and (max - o) / d, computed as (min - o) * (1 / d)
    /// and ordered into an entry and an exit by the sign of 1/d. A zero component of
    /// d (+0 or -0) gives 1/d = +inf or -inf; a ray lying in a face plane then gives
    /// 0 * inf = NaN for that plane. Left as it is, the NaN would make the answer
    /// depend on the sign of the zero; `slab_ends` turns it into -inf (an entry) or
    /// +inf (an exit), so the axis on whose boundary the ray runs constrains nothing,
    /// for either sign, as the closed box requires.
    pub fn slab(&self, ray: &Ray, range: Interval) -> Option<ClosedSpan> {
        let s =
            self.span(ray.origin(), ray.direction().recip(), range, Exits::Exact)?;
        Some(ClosedSpan { t0: s.t0, t1: s.t1 })
    }
    // ANCHOR_END: slab

    // ANCHOR: slab_conservative
    /// [`Aabb::slab`] with each axis' t_far moved out by `moved_out` (pbrt-v4,
    /// `Bounds3::IntersectP`: t_far *= 1 + 2 gamma(3)), so that rounding in the three
    /// operations behind it cannot make the box miss a point that lies on it, such as
    /// a vertex of a triangle it bounds (STABILITY S6). The BVH's node test applies
    /// the same rule to its boxes, and gives the same entries (a test ties the two).
    pub fn slab_conservative(&self, ray: &Ray, range: Interval) -> Option<ClosedSpan> {
        self.slab_conservative_prepared(&PreparedRay::new(ray), range)
    }
    // ANCHOR_END: slab_conservative

    /// [`Aabb::slab_conservative`] with the ray's 1/d computed once per ray, not
    /// once per box.
    #[inline]
    pub fn slab_conservative_prepared(
        &self,
        ray: &PreparedRay,
        range: Interval,
    ) -> Option<ClosedSpan> {
        let o = ray.ray().origin();
        let s = self.span(o, ray.inv_d, range, Exits::MovedOut)?;
        Some(ClosedSpan { t0: s.t0, t1: s.t1 })
    }

    // ANCHOR: span
    /// The slab loop shared by both tests, for a ray from `o` with 1/d = `inv_d`;
    /// `exits` says whether each axis' t_far is moved out. `t0` only grows and `t1`
    /// only shrinks, so one check after the three axes rejects what a check after each
    /// would: the loop runs without a branch that the CPU could mispredict.
    #[inline]
    fn span(
        &self,
        o: Vec3,
        inv_d: Vec3,
        range: Interval,
        exits: Exits,
    ) -> Option<Span> {
        let mut s = Span {
            t0: range.min,
            axis0: 0,
            t1: range.max,
            axis1: 0,
        };
        for i in 0..3 {
            let (t_near, t_far) =
                slab_ends(self.min[i] - o[i], self.max[i] - o[i], inv_d[i]);
            let t_far = match exits {
                Exits::Exact => t_far,
                Exits::MovedOut => moved_out(t_far),
            };
            if t_near > s.t0 {
                (s.t0, s.axis0) = (t_near, i);
            }
            if t_far < s.t1 {
                (s.t1, s.axis1) = (t_far, i);
            }
        }
        (s.t0 <= s.t1).then_some(s)
    }
    // ANCHOR_END: span

    // ANCHOR: box_hit
    /// The nearest crossing of the box surface within `range`: the entry, or the
    /// exit for a ray starting inside; on the face of the axis whose slab set that end
    /// of the interval, with the sign of the face's outward normal along it.
    #[inline]
    pub fn nearest_face(&self, ray: &PreparedRay, range: Interval) -> Option<FaceHit> {
        let (o, d) = (ray.ray().origin(), ray.ray().direction());
        let s = self.span(o, ray.inv_d, Interval::EVERYWHERE, Exits::Exact)?;
        let face = |t, axis: usize, outward| FaceHit { t, axis, outward };
        if range.contains(s.t0) {
            Some(face(s.t0, s.axis0, -d[s.axis0].signum()))
        } else if range.contains(s.t1) {
            Some(face(s.t1, s.axis1, d[s.axis1].signum()))
        } else {
            None
        }
    }

    /// The hit record of `face`: its normal, and the point snapped onto the face. Along
    /// the face's axis the point is the face's own coordinate, exact: its error there
    /// is 0. Along the face it carries o + t d's rounding, which an offset along the
    /// normal never needs.
    pub fn hit_at(&self, ray: &Ray, face: FaceHit) -> Hit {
        let FaceHit { t, axis, outward } = face;
        let mut normal = Vec3::ZERO;
        normal[axis] = outward;
        let mut point = ray.at(t);
        point[axis] = if outward > 0.0 {
            self.max[axis]
        } else {
            self.min[axis]
        };
        let mut error = gamma(4) * point.abs();
        error[axis] = 0.0;
        Hit::new(ray, t, point, normal, error)
    }

    /// The nearest crossing of the box surface within `range`:
    /// [`Aabb::nearest_face`], then [`Aabb::hit_at`].
    pub fn hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let face = self.nearest_face(&PreparedRay::new(ray), range)?;
        Some(self.hit_at(ray, face))
    }
    // ANCHOR_END: box_hit

    /// Both crossings of the ray's line with the box surface, entry and exit: the
    /// slab interval [t0, t1] over the whole line (equal where the ray touches an edge
    /// or a corner).
    pub fn crossings(&self, ray: &Ray) -> Crossings {
        let (o, inv_d) = (ray.origin(), ray.direction().recip());
        self.span(o, inv_d, Interval::EVERYWHERE, Exits::Exact)
            .map_or(Crossings::NONE, |s| Crossings::two(s.t0, s.t1))
    }

    /// The outward unit normal of the face nearest `p`. On each axis i the distance
    /// from p to the nearer of the two faces is h_i - |p_i - c_i| (c the centre, h the
    /// half size); the axis with the smallest wins, ties to the first (x, then y, then
    /// z, as The Ray Tracer Challenge's cube at its edges and corners), and the normal
    /// is +-e_i on the side of the centre p lies (+ when p_i = c_i).
    pub fn normal_at(&self, p: Vec3) -> Vec3 {
        let (c, h) = (self.centre(), 0.5 * (self.max - self.min));
        let offset = p - c;
        let gap = h - offset.abs();
        let mut axis = 0;
        for i in 1..3 {
            if gap[i] < gap[axis] {
                axis = i;
            }
        }
        let mut n = Vec3::ZERO;
        n[axis] = if offset[axis] < 0.0 { -1.0 } else { 1.0 };
        n
    }
}

// ANCHOR: slab_ends
/// Where a ray enters and leaves one slab, from the distances `to_min` = min - o and
/// `to_max` = max - o of its two planes along the axis and `inv_d` = 1 / d there.
///
/// The ray meets the min plane first when d > 0 and the max plane first when d < 0,
/// so the sign of 1/d orders the two ends (not a comparison of the values, which a
/// NaN would defeat). Where d is +0 or -0, 1/d is +inf or -inf, and a ray whose
/// origin lies exactly in one of the two planes gives 0 * inf = NaN for that end:
/// the ray runs along the face, inside the closed slab for every t. The NaN becomes
/// -inf as an entry and +inf as an exit, so that axis constrains nothing, whichever
/// the sign of the zero (STABILITY S8; the BVH's traversal applies the same rule).
#[inline(always)]
fn slab_ends(to_min: f32, to_max: f32, inv_d: f32) -> (f32, f32) {
    let (a, b) = (to_min * inv_d, to_max * inv_d);
    let (near, far) = if inv_d < 0.0 { (b, a) } else { (a, b) };
    let near = if near.is_nan() {
        f32::NEG_INFINITY
    } else {
        near
    };
    let far = if far.is_nan() { f32::INFINITY } else { far };
    (near, far)
}
// ANCHOR_END: slab_ends

/// Whether a slab test moves each exit out ([`moved_out`]) or takes it as computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Exits {
    Exact,
    MovedOut,
}
