//! A capped cylinder: the solid x^2 + y^2 <= r^2, z_min <= z <= z_max, its side
//! closed by two discs (The Ray Tracer Challenge, ch. 13, "closed cylinders";
//! pbrt-v4's cylinder with two disks).
//!
//! The solid is the intersection of two convex sets, the infinite solid cylinder
//! and the slab between the caps, so a ray's line is inside it over one interval:
//! the later of the two entries to the earlier of the two exits, the slab test of a
//! box with the cylinder as one of its slabs. Whichever set gave an end says which
//! surface the ray crosses there: the side, or a cap.
//!
//! A cylinder elsewhere, or along another axis, is an [`crate::shapes::Instance`].

use glam::{Vec2, Vec3};

use crate::error::{Error, Problem, Result, finite, positive};
use crate::float::gamma;
use crate::quadratic;
use crate::ray::{Crossings, Interval, Ray};
use crate::shapes::{Aabb, Hit};

/// A cylinder of radius `r` about the Z axis from `z_min` to `z_max`, capped.
///
/// ```
/// use glam::Vec3;
/// use render_lessons::ray::{Interval, Ray};
/// use render_lessons::shapes::{Cylinder, CylinderPart, PartHit};
///
/// let can = Cylinder::new(1.0, 0.0, 2.0)?;
/// // Through the side, from x = -5 at half height: the side at x = -1.
/// let side = Ray::new(Vec3::new(-5.0, 0.0, 1.0), Vec3::X)?;
/// let entry = PartHit { t: 4.0, part: CylinderPart::Side };
/// assert_eq!(can.nearest(&side, Interval::AHEAD), Some(entry));
/// // Down onto the top cap, then out through the bottom one.
/// let down = Ray::new(Vec3::new(0.5, 0.0, 5.0), -Vec3::Z)?;
/// assert_eq!(can.crossings(&down).as_slice(), [3.0, 5.0]);
/// assert_eq!(can.hit(&down, Interval::AHEAD).unwrap().normal, Vec3::Z);
/// // Above the top, where the infinite cylinder would be hit: nothing.
/// let above = Ray::new(Vec3::new(-5.0, 0.0, 3.0), Vec3::X)?;
/// assert!(can.hit(&above, Interval::AHEAD).is_none());
/// # Ok::<(), render_lessons::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cylinder {
    radius: f32,
    z_min: f32,
    z_max: f32,
}

/// Which surface of a [`Cylinder`] a crossing is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CylinderPart {
    /// The curved side, x^2 + y^2 = r^2.
    Side,
    /// The cap z = z_min, normal -Z.
    Bottom,
    /// The cap z = z_max, normal +Z.
    Top,
}

/// Where a ray crosses a [`Cylinder`]: the distance `t` and the surface it is on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PartHit {
    /// The ray parameter of the crossing.
    pub t: f32,
    /// The side or a cap.
    pub part: CylinderPart,
}

/// The span of a ray's line inside the solid: entry and exit, and the part of each.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Span {
    t0: f32,
    part0: CylinderPart,
    t1: f32,
    part1: CylinderPart,
}

impl Cylinder {
    /// The capped cylinder of `radius` about the Z axis from `z_min` to `z_max`.
    ///
    /// Errors name `radius` (not finite and positive, or its square not finite),
    /// `z_min` or `z_max` (not finite), and `z range` when z_min >= z_max.
    pub fn new(radius: f32, z_min: f32, z_max: f32) -> Result<Cylinder> {
        positive("radius", positive("radius", radius)? * radius)?;
        let (z_min, z_max) = (finite("z_min", z_min)?, finite("z_max", z_max)?);
        if z_min >= z_max {
            return Err(Error::Value {
                param: "z range",
                problem: Problem::EmptyRange {
                    min: z_min,
                    max: z_max,
                },
            });
        }
        Ok(Cylinder {
            radius,
            z_min,
            z_max,
        })
    }

    /// The radius r.
    pub fn radius(&self) -> f32 {
        self.radius
    }

    /// The caps' heights (z_min, z_max).
    pub fn z_range(&self) -> (f32, f32) {
        (self.z_min, self.z_max)
    }

    /// The box (-r, -r, z_min) to (r, r, z_max), whose corners are the cylinder's own
    /// numbers, moved out by gamma(3) times the largest of them so that a hit point
    /// rounded just outside still lies in it.
    pub fn bounds(&self) -> Option<Aabb> {
        let r = self.radius;
        let size = r.max(self.z_min.abs()).max(self.z_max.abs());
        Aabb::new(Vec3::new(-r, -r, self.z_min), Vec3::new(r, r, self.z_max))
            .ok()?
            .padded(gamma(3) * size)
    }

    // ANCHOR: cylinder_span
    /// Where the ray's line is inside the infinite solid cylinder x^2 + y^2 <= r^2:
    /// the roots of a t^2 + b t + c = 0 in x and y alone, with a = d_x^2 + d_y^2,
    /// b = 2 (o_x d_x + o_y d_y), c = o_x^2 + o_y^2 - r^2, and the sphere's
    /// cancellation-free discriminant in two dimensions, 4a (r^2 - |l|^2), l the
    /// point of the line nearest the axis. A line parallel to the axis (a = 0) is
    /// inside for every t, or for none.
    fn side_span(&self, o: Vec2, d: Vec2) -> Option<(f32, f32)> {
        let (a, half_b) = (d.dot(d), o.dot(d));
        let c = o.dot(o) - self.radius * self.radius;
        if a == 0.0 {
            return (c <= 0.0).then_some((f32::NEG_INFINITY, f32::INFINITY));
        }
        let l = o - (half_b / a) * d;
        let delta = self.radius * self.radius - l.dot(l);
        // The sphere's stable roots, the far one allowed to overflow to an infinite
        // end of the span.
        let (t0, t1) = quadratic::stable_pair(a, 2.0 * half_b, c, 4.0 * (a * delta))?;
        Some((t0.min(t1), t0.max(t1)))
    }

    /// Where the ray's line is inside the solid: the later entry and the earlier exit
    /// of the side's span and the slab z_min <= z <= z_max (a cap wins a tie), or
    /// `None` if they do not overlap.
    fn span(&self, ray: &Ray) -> Option<Span> {
        let (o, d) = (ray.origin(), ray.direction());
        let (s0, s1) = self.side_span(o.truncate(), d.truncate())?;
        let (z0, z1, cap0, cap1) = if d.z == 0.0 {
            let inside = (self.z_min..=self.z_max).contains(&o.z);
            let all = (f32::NEG_INFINITY, f32::INFINITY);
            let (z0, z1) = inside.then_some(all)?;
            (z0, z1, CylinderPart::Bottom, CylinderPart::Top)
        } else {
            let (to_min, to_max) = ((self.z_min - o.z) / d.z, (self.z_max - o.z) / d.z);
            if d.z > 0.0 {
                (to_min, to_max, CylinderPart::Bottom, CylinderPart::Top)
            } else {
                (to_max, to_min, CylinderPart::Top, CylinderPart::Bottom)
            }
        };
        let (t0, part0) = if z0 >= s0 {
            (z0, cap0)
        } else {
            (s0, CylinderPart::Side)
        };
        let (t1, part1) = if z1 <= s1 {
            (z1, cap1)
        } else {
            (s1, CylinderPart::Side)
        };
        (t0 <= t1 && t0.is_finite() && t1.is_finite()).then_some(Span {
            t0,
            part0,
            t1,
            part1,
        })
    }
    // ANCHOR_END: cylinder_span

    /// The nearest crossing within `range` and the part it is on: the entry, or the
    /// exit for a ray starting inside.
    pub fn nearest(&self, ray: &Ray, range: Interval) -> Option<PartHit> {
        let s = self.span(ray)?;
        if range.contains(s.t0) {
            Some(PartHit {
                t: s.t0,
                part: s.part0,
            })
        } else if range.contains(s.t1) {
            Some(PartHit {
                t: s.t1,
                part: s.part1,
            })
        } else {
            None
        }
    }

    /// The hit record of `crossing` (at `t` on `part`): the point moved onto that
    /// surface, its error bound and the outward normal.
    ///
    /// On a cap the height is the cap's own, exact (error 0 along Z), and (x, y) is
    /// o + t d pulled in to the rim if rounding left it just outside; its error
    /// along the cap never matters to an offset along the normal. On the side, o + t d
    /// carries t's error, which grows with t, so (x, y) is scaled back onto the
    /// circle, (x, y) r / |(x, y)| (as the sphere's point is, pbrt-v4 section 6.8.5),
    /// with error gamma(5) |x| and gamma(5) |y|, and z is clamped to the caps.
    pub fn hit_at(&self, ray: &Ray, crossing: PartHit) -> Hit {
        let PartHit { t, part } = crossing;
        let p = ray.at(t);
        let xy = p.truncate();
        let length = xy.length();
        let (point, normal, error) = match part {
            CylinderPart::Side if length > 0.0 && length.is_finite() => {
                let xy = xy * (self.radius / length);
                let z = p.z.clamp(self.z_min, self.z_max);
                let point = xy.extend(z);
                (
                    point,
                    (xy / self.radius).extend(0.0),
                    gamma(5) * xy.abs().extend(0.0),
                )
            }
            CylinderPart::Side => (p, -ray.direction(), super::on_ray_error(ray, t)),
            cap => {
                let z = if cap == CylinderPart::Top {
                    self.z_max
                } else {
                    self.z_min
                };
                let xy = if length > self.radius {
                    xy * (self.radius / length)
                } else {
                    xy
                };
                let sign = if cap == CylinderPart::Top { 1.0 } else { -1.0 };
                let error = (gamma(4) * p.truncate().abs()).extend(0.0);
                (xy.extend(z), Vec3::new(0.0, 0.0, sign), error)
            }
        };
        Hit::new(ray, t, point, normal.normalize_or(-ray.direction()), error)
    }

    /// The nearest crossing within `range`: [`Cylinder::nearest`], then
    /// [`Cylinder::hit_at`].
    pub fn hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let crossing = self.nearest(ray, range)?;
        Some(self.hit_at(ray, crossing))
    }

    /// Both crossings of the ray's line with the closed surface, entry and exit,
    /// negative behind the origin; equal where the line only touches it (tangent to
    /// the side, or through the rim).
    pub fn crossings(&self, ray: &Ray) -> Crossings {
        self.span(ray)
            .map_or(Crossings::NONE, |s| Crossings::two(s.t0, s.t1))
    }

    /// The outward unit normal of the surface nearest `p`: a cap's +-Z where a cap is
    /// as near as the side or nearer, else the side's (x, y, 0) / |(x, y)|; the zero
    /// vector on the axis when the side is nearest (no direction to choose).
    pub fn normal_at(&self, p: Vec3) -> Vec3 {
        let side = (self.radius - p.truncate().length()).abs();
        let (bottom, top) = ((p.z - self.z_min).abs(), (self.z_max - p.z).abs());
        if top <= side && top <= bottom {
            Vec3::Z
        } else if bottom <= side {
            Vec3::NEG_Z
        } else {
            p.truncate().extend(0.0).normalize_or_zero()
        }
    }
}
