//! The ray model of Lecture 4: the parametric line r(t) = o + t d.

use glam::Vec3;

use crate::error::{Error, Problem, Result, finite3, unit};

/// A ray with origin `o` and direction `d`: unit for every ray of [`Ray::new`].
///
/// Because `d` has length 1, the parameter `t` of a point is its signed distance
/// from the origin; a negative `t` lies behind it. A ray made by
/// [`Ray::new_unnormalised`] keeps the length of its `d`, and `t` then counts
/// lengths of `d` instead: the distance is t |d|.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    origin: Vec3,
    direction: Vec3,
}

impl Ray {
    // ANCHOR: new
    /// A ray from `origin` along `direction`, which is normalised here.
    ///
    /// Rejects a non-finite origin, and a direction that is zero or not finite.
    pub fn new(origin: Vec3, direction: Vec3) -> Result<Ray> {
        Ok(Ray {
            origin: finite3("origin", origin)?,
            direction: unit("direction", direction)?,
        })
    }
    // ANCHOR_END: new

    /// A ray from `origin` along `direction` as it is, not normalised: the points are
    /// still r(t) = o + t d, but `t` counts lengths of d, not distance (pbrt's rays
    /// are all of this kind).
    ///
    /// It is what a transform needs. An affine map M takes o + t d to
    /// M o + t (M d), so the ray (M o, M d) reaches the image of each point at the
    /// same `t`: a hit found in an instance's object space needs no rescaling to be
    /// a hit of the world ray. [`Ray::new`] would normalise M d and change every `t`
    /// by the factor |M d|. Every shape's test takes either kind (none assumes
    /// |d| = 1), and reports `t` in the ray's own units.
    ///
    /// ```
    /// use glam::Vec3;
    /// use render_lessons::ray::{Interval, Ray};
    /// use render_lessons::shapes::Sphere;
    /// use render_lessons::transform::Transform;
    ///
    /// // A world ray, and the unit sphere placed by "scale by 2": the world sphere of radius 2.
    /// let world = Ray::new(Vec3::new(0.0, 0.0, 10.0), -Vec3::Z)?;
    /// let to_object = Transform::scale(0.5, 0.5, 0.5);
    /// let object = Ray::new_unnormalised(
    ///     to_object.point(world.origin()),
    ///     to_object.vector(world.direction()), // length 0.5, kept
    /// )?;
    /// let unit = Sphere::new(Vec3::ZERO, 1.0)?;
    /// let t = unit.hit(&object, Interval::AHEAD).unwrap().t;
    /// assert_eq!(t, 8.0); // the world ray's own t: it meets the radius-2 sphere at z = 2
    /// assert_eq!(world.at(t), Vec3::new(0.0, 0.0, 2.0));
    /// // Normalised, the object ray would report 4: its own distance, not the world's.
    /// let normalised = Ray::new(object.origin(), object.direction())?;
    /// assert_eq!(unit.hit(&normalised, Interval::AHEAD).unwrap().t, 4.0);
    /// # Ok::<(), render_lessons::Error>(())
    /// ```
    ///
    /// Rejects a non-finite origin, and a direction that is zero or not finite.
    pub fn new_unnormalised(origin: Vec3, direction: Vec3) -> Result<Ray> {
        let direction = finite3("direction", direction)?;
        if direction == Vec3::ZERO {
            return Err(Error::Value {
                param: "direction",
                problem: Problem::ZeroLength,
            });
        }
        Ok(Ray {
            origin: finite3("origin", origin)?,
            direction,
        })
    }

    /// A ray from values the caller has already checked: finite, `direction` of unit
    /// length.
    #[inline]
    pub(crate) fn from_checked(origin: Vec3, direction: Vec3) -> Ray {
        debug_assert!(origin.is_finite() && direction.is_normalized());
        Ray { origin, direction }
    }

    /// The origin `o`.
    pub fn origin(&self) -> Vec3 {
        self.origin
    }

    /// The direction `d`: unit, unless the ray was made by [`Ray::new_unnormalised`].
    pub fn direction(&self) -> Vec3 {
        self.direction
    }

    // ANCHOR: at
    /// The point r(t) = o + t d, at signed distance `t` from the origin (t |d| for an
    /// unnormalised ray).
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + t * self.direction
    }
    // ANCHOR_END: at

    // ANCHOR: t_closest_to
    /// The `t` of the point on the ray's line closest to `p`: (p - o) . d / (d . d),
    /// which is (p - o) . d for a unit d.
    pub fn t_closest_to(&self, p: Vec3) -> f32 {
        (p - self.origin).dot(self.direction) / self.direction.length_squared()
    }
    // ANCHOR_END: t_closest_to
}

// ANCHOR: interval
/// The ray parameters a query accepts: `min < t < max`, both ends open, as in Ray
/// Tracing in One Weekend's `interval` (pbrt keeps only `t_max`, with 0 below).
///
/// A closest-hit loop shrinks `max` to each hit it finds, so that later primitives
/// count only if nearer; a shadow ray to a light at distance `s` asks (0, s).
///
/// ```
/// use render_lessons::ray::Interval;
///
/// assert!(Interval::AHEAD.contains(3.0));
/// assert!(!Interval::AHEAD.contains(0.0)); // open: the origin itself is not ahead
/// assert!(!Interval::AHEAD.contains(f32::NAN));
/// let nearer = Interval::AHEAD.up_to(2.0);
/// assert!(nearer.contains(1.5) && !nearer.contains(2.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The open lower end.
    pub min: f32,
    /// The open upper end.
    pub max: f32,
}

impl Interval {
    /// Every `t` ahead of the origin: 0 < t < infinity.
    pub const AHEAD: Interval = Interval::new(0.0, f32::INFINITY);

    /// The whole line, behind the origin too: -infinity < t < infinity.
    pub const EVERYWHERE: Interval = Interval::new(f32::NEG_INFINITY, f32::INFINITY);

    /// `min < t < max`.
    pub const fn new(min: f32, max: f32) -> Interval {
        Interval { min, max }
    }

    /// `min < t < max`, and `false` for NaN.
    pub fn contains(&self, t: f32) -> bool {
        t > self.min && t < self.max
    }

    /// The same interval, its upper end moved to `max`.
    pub fn up_to(self, max: f32) -> Interval {
        Interval { max, ..self }
    }
}
// ANCHOR_END: interval

/// The part of a ray inside a closed box, `t0 <= t <= t1`: both ends CLOSED, unlike
/// [`Interval`]'s. A box's slab test returns it; `t0 == t1` is a ray that only
/// touches the box (an edge or a corner), still a hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClosedSpan {
    /// Where the ray enters (the closed lower end).
    pub t0: f32,
    /// Where it leaves (the closed upper end), `t1 >= t0`.
    pub t1: f32,
}

// ANCHOR: crossings
/// Every `t` at which a ray's line crosses a surface: both crossings of a sphere, a
/// box or a quadric (entry and exit), the one of a plane, triangle or quad; none, one
/// or two, ascending.
///
/// The whole line counts, not only `t > 0`: a negative `t` is behind the ray's origin,
/// so a ray starting inside a sphere of radius 1 at its centre reports -1 and 1, and a
/// tangent ray reports its point twice. This is The Ray Tracer Challenge's
/// `intersect(shape, ray)` (ch. 5), which keeps every crossing so that later chapters
/// can tell inside from outside; [`crate::shapes::Shape::hit`] picks the nearest one in
/// a range.
///
/// Derefs to a slice: `xs.len()`, `xs[0]`, `xs.iter()`.
#[derive(Clone, Copy, Debug)]
pub struct Crossings {
    ts: [f32; 2],
    len: usize,
}
// ANCHOR_END: crossings

impl Crossings {
    /// No crossing.
    pub const NONE: Crossings = Crossings {
        ts: [0.0; 2],
        len: 0,
    };

    /// One crossing, or none if `t` is not finite.
    #[inline]
    pub(crate) fn one(t: f32) -> Crossings {
        Crossings::from_finite([t, f32::NAN])
    }

    /// Two crossings in ascending order; a non-finite one is dropped.
    #[inline]
    pub(crate) fn two(t0: f32, t1: f32) -> Crossings {
        Crossings::from_finite([t0.min(t1), t0.max(t1)])
    }

    /// The finite ones of `ts`, in order.
    #[inline]
    fn from_finite([a, b]: [f32; 2]) -> Crossings {
        match (a.is_finite(), b.is_finite()) {
            (true, true) => Crossings { ts: [a, b], len: 2 },
            (true, false) => Crossings {
                ts: [a, 0.0],
                len: 1,
            },
            (false, true) => Crossings {
                ts: [b, 0.0],
                len: 1,
            },
            (false, false) => Crossings::NONE,
        }
    }

    /// The `t` values, ascending.
    pub fn as_slice(&self) -> &[f32] {
        &self.ts[..self.len]
    }

    /// The two crossings (entry, exit) if there are two: a sphere's or a box's.
    pub fn pair(&self) -> Option<(f32, f32)> {
        match *self.as_slice() {
            [t0, t1] => Some((t0, t1)),
            _ => None,
        }
    }

    /// The smallest `t` inside `range`, if any.
    #[inline]
    pub fn first_in(&self, range: Interval) -> Option<f32> {
        let [t0, t1] = self.ts;
        if self.len > 0 && range.contains(t0) {
            Some(t0)
        } else if self.len > 1 && range.contains(t1) {
            Some(t1)
        } else {
            None
        }
    }

    /// Each `t` mapped by `f`, which must keep the order (the instance's division by a
    /// positive scale does).
    pub(crate) fn map(self, f: impl Fn(f32) -> f32) -> Crossings {
        let [t0, t1] = self.ts;
        match self.len {
            0 => Crossings::NONE,
            1 => Crossings::one(f(t0)),
            _ => Crossings::from_finite([f(t0), f(t1)]),
        }
    }
}

impl std::ops::Deref for Crossings {
    type Target = [f32];

    fn deref(&self) -> &[f32] {
        self.as_slice()
    }
}

impl PartialEq for Crossings {
    fn eq(&self, other: &Crossings) -> bool {
        self.as_slice() == other.as_slice()
    }
}
