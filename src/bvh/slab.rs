//! The slab test of the BVH's node boxes: where a ray enters a box, for one box
//! ([`box_entry`], the root) and for the four children of a 4-wide node at once
//! ([`four_entries`]), with the ray's 1/d worked out once per ray ([`BoxRay`]).
//!
//! The test is conservative: the exits are moved out by the rule of
//! [`Aabb::slab_conservative`](crate::shapes::Aabb::slab_conservative), `moved_out`
//! (Ize 2013, "Robust BVH Ray Traversal", as in pbrt-v4), so rounding cannot make a
//! box miss a point of a primitive inside it and the tree never loses a hit the
//! plain list would find (STABILITY S6). It gives the entries that test gives, bit
//! for bit (the test `box_entry_is_the_aabbs_conservative_slab_entry`).

use glam::{Vec3, Vec3A, Vec4};

use crate::bvh::WideNode;
use crate::float::{FAR_MARGIN, moved_out};
use crate::ray::{Interval, Ray};

// ANCHOR: box_entry
/// The ray as the node boxes see it, computed once per ray: the origin and 1/d as
/// 4-wide vectors (one lane unused), each axis's origin and 1/d in all four lanes
/// (for `four_entries`, whose four lanes are planes of one axis, one per child),
/// the signs of 1/d, and whether 1/d is finite on every axis.
#[derive(Clone, Copy, Debug)]
pub struct BoxRay {
    origin: Vec3A,
    inv_d: Vec3A,
    axes: [(Vec4, Vec4); 3],
    /// Bit `a` set if 1/d is negative along axis `a`: the ray then enters that
    /// axis's slabs at their max planes (for `four_entries`).
    negative: u32,
    finite: bool,
}

impl BoxRay {
    /// `ray` as the boxes see it.
    pub fn new(ray: &Ray) -> BoxRay {
        BoxRay::with_inv_d(ray.origin(), ray.direction().recip())
    }

    /// The ray from `origin` whose direction has the reciprocal `inv_d` (for a test
    /// that has 1/d already: [`crate::shapes::PreparedRay`]).
    pub fn with_inv_d(origin: Vec3, inv_d: Vec3) -> BoxRay {
        let (origin, inv_d) = (Vec3A::from(origin), Vec3A::from(inv_d));
        let axis = |a: usize| (Vec4::splat(origin[a]), Vec4::splat(inv_d[a]));
        BoxRay {
            origin,
            inv_d,
            axes: [axis(0), axis(1), axis(2)],
            negative: inv_d.cmplt(Vec3A::ZERO).bitmask(),
            finite: inv_d.is_finite(),
        }
    }

    /// 1/d.
    #[inline(always)]
    pub fn inv_d(&self) -> Vec3 {
        self.inv_d.into()
    }

    /// True if 1/d is finite on every axis: the ray is parallel to no axis.
    #[inline(always)]
    pub fn finite(&self) -> bool {
        self.finite
    }
}

/// The conservative slab test of a box given by its corners: the entry
/// distance if the ray passes through the box within `t_min..t_max`.
///
/// All three axes at once: t = (plane - o) * (1/d) for both planes of each axis,
/// the nearer of the two per axis is where the ray enters that slab, the farther
/// where it leaves; the box is entered at the last entry and left at the first
/// exit. That exit is moved out by 1 + 2 gamma(3) (a negative one towards 0 by as
/// much) so that rounding cannot lose a hit.
///
/// With 1/d finite nothing here can be NaN. A ray parallel to an axis (1/d
/// infinite) that lies exactly in a face plane gives 0 * inf = NaN on that axis;
/// [`box_entry_careful`] replaces it so that the axis constrains nothing, as in
/// [`Aabb::slab`](crate::shapes::Aabb::slab), on every CPU.
#[inline(always)]
pub(super) fn box_entry(
    (min, max): (Vec3A, Vec3A),
    ray: &BoxRay,
    range: Interval,
) -> Option<f32> {
    if !ray.finite {
        return box_entry_careful((min, max), ray, range);
    }
    let lo = (min - ray.origin) * ray.inv_d;
    let hi = (max - ray.origin) * ray.inv_d;
    let (near, far) = (lo.min(hi), lo.max(hi));
    enter(near.max_element(), far.min_element(), range)
}

/// [`box_entry`] for a ray with an infinite 1/d: each NaN becomes -inf (an entry)
/// or +inf (an exit).
#[inline(never)]
fn box_entry_careful(
    (min, max): (Vec3A, Vec3A),
    ray: &BoxRay,
    range: Interval,
) -> Option<f32> {
    let lo = (min - ray.origin) * ray.inv_d;
    let hi = (max - ray.origin) * ray.inv_d;
    let negative = ray.inv_d.cmplt(Vec3A::ZERO);
    let near = Vec3A::select(negative, hi, lo);
    let far = Vec3A::select(negative, lo, hi);
    let near = Vec3A::select(near.is_nan_mask(), Vec3A::NEG_INFINITY, near);
    let far = Vec3A::select(far.is_nan_mask(), Vec3A::INFINITY, far);
    enter(near.max_element(), far.min_element(), range)
}

/// The entry into the box whose slabs are entered by `near` and left by `far`
/// (neither NaN), within `t_min..t_max`, with the exit widened.
#[inline(always)]
fn enter(near: f32, far: f32, range: Interval) -> Option<f32> {
    let far = moved_out(far);
    let t0 = if near > range.min { near } else { range.min };
    let t1 = if far < range.max { far } else { range.max };
    (t0 <= t1).then_some(t0)
}
// ANCHOR_END: box_entry

// ANCHOR: four_entries
/// [`box_entry`] of the four children of a 4-wide node at once, each lane one
/// child: the entries (meaningful in the lanes hit) and the lanes hit as a bitmask.
///
/// Each axis's near plane is chosen by the sign of 1/d, once per ray, rather than
/// by a `min` of the two distances: for a box whose min is at most its max the two
/// rules agree, and the inside-out box of an unused lane (min +inf, max -inf) is
/// then entered at +inf and left at -inf on every axis, a miss for every ray, with
/// no NaN (1/d of a finite direction is never 0).
///
/// For a ray whose 1/d is finite on every axis ([`BoxRay::finite`]).
#[inline(always)]
pub(super) fn four_entries(
    node: &WideNode,
    ray: &BoxRay,
    range: Interval,
) -> (Vec4, u32) {
    debug_assert!(ray.finite);
    let slab = |axis: usize| {
        let (o, inv_d) = ray.axes[axis];
        let negative = ray.negative >> axis & 1 != 0;
        let near = (node.planes(axis, negative) - o) * inv_d;
        let far = (node.planes(axis, !negative) - o) * inv_d;
        (near, far)
    };
    let ((near_x, far_x), (near_y, far_y), (near_z, far_z)) =
        (slab(0), slab(1), slab(2));
    let near = near_x.max(near_y).max(near_z);
    let far = far_x.min(far_y).min(far_z);
    // moved_out, lane by lane:
    let far = far + (far.abs() * FAR_MARGIN).min(Vec4::splat(f32::MAX));
    let t0 = near.max(Vec4::splat(range.min));
    let t1 = far.min(Vec4::splat(range.max));
    (t0, t0.cmple(t1).bitmask())
}
// ANCHOR_END: four_entries

/// [`four_entries`] for a ray with an infinite 1/d: each box by
/// [`box_entry_careful`] (an unused lane's inside-out box gives no NaN there
/// either: inf - o is inf, and inf times a nonzero 1/d is infinite).
pub(super) fn four_entries_careful(
    node: &WideNode,
    ray: &BoxRay,
    range: Interval,
) -> (Vec4, u32) {
    let mut entries = Vec4::ZERO;
    let mut hit = 0;
    for lane in 0..4 {
        if let Some(t) = box_entry_careful(node.corners(lane), ray, range) {
            entries[lane] = t;
            hit |= 1 << lane;
        }
    }
    (entries, hit)
}

#[cfg(test)]
mod tests {
    use glam::Vec3;

    use super::*;
    use crate::bvh::Child;
    use crate::ray::Ray;
    use crate::rng::Rng;
    use crate::shapes::Aabb;

    /// One case of the tests below: two child boxes (some flat, some with the ray's
    /// origin in a face plane), a ray (some aimed at a corner, where the widening
    /// decides; some parallel to an axis, where 1/d is infinite) and a range (some
    /// narrow, some behind the origin).
    struct Case {
        boxes: [(Vec3, Vec3); 2],
        ray: Ray,
        range: Interval,
    }

    fn case(rng: &mut Rng, case: usize) -> Option<Case> {
        let mut next = || rng.next_f32() * 4.0 - 2.0;
        let mut point = || Vec3::new(next(), next(), next());
        let origin = point();
        let mut corners = |flat: bool| {
            let (a, b) = (point(), point());
            let (min, mut max) = (a.min(b), a.max(b));
            if flat {
                max.y = min.y;
            }
            (min, max)
        };
        let mut boxes = [
            corners(case.is_multiple_of(7)),
            corners(case.is_multiple_of(11)),
        ];
        if case.is_multiple_of(13) {
            boxes[1].0.x = origin.x; // the origin in a face plane
        }
        let (min, max) = boxes[case % 2];
        let inside = min + (max - min) * point().abs() / 2.0;
        let mut d = match case % 4 {
            0 | 1 => inside - origin,
            2 => max - origin, // at a corner, where rounding decides
            _ => point(),
        };
        if case.is_multiple_of(5) {
            d[case % 3] = 0.0; // parallel to a face: 1/d infinite
        }
        let ray = Ray::new(origin, d).ok()?;
        let (a, b) = (next(), next());
        let range = match case % 3 {
            0 => Interval::new(a.min(b), a.max(b)),
            _ => Interval::new(a.min(b) - 2.0, 16.0),
        };
        Some(Case { boxes, ray, range })
    }

    #[test]
    fn four_entries_are_the_entries_of_each_box() {
        let mut rng = Rng::new(0x33_4444, 3);
        let (mut compared, mut entered) = (0, 0);
        for n in 0..200_000 {
            let (Some(one), Some(two)) = (case(&mut rng, n), case(&mut rng, n + 1))
            else {
                continue;
            };
            let (ray, range) = match n % 4 {
                3 => (one.ray, Interval::EVERYWHERE),
                _ => (one.ray, one.range),
            };
            let children = 2 + n % 3; // two to four
            let boxes = [one.boxes, two.boxes].concat();
            let node = WideNode::new(
                &boxes[..children]
                    .iter()
                    // (A tree's box has min <= max; `case` can turn one inside out.)
                    .map(|&(a, b)| ((a.min(b), a.max(b)), Child::Node(1)))
                    .collect::<Vec<_>>(),
            );
            let box_ray = BoxRay::new(&ray);
            let each: Vec<Option<f32>> = (0..4)
                .map(|lane| {
                    (lane < children)
                        .then(|| box_entry(node.corners(lane), &box_ray, range))
                        .flatten()
                })
                .collect();
            let (t, hit) = if box_ray.finite() {
                four_entries(&node, &box_ray, range)
            } else {
                four_entries_careful(&node, &box_ray, range)
            };
            let four: Vec<Option<f32>> = (0..4)
                .map(|lane| (hit >> lane & 1 != 0).then_some(t[lane]))
                .collect();
            assert_eq!(four, each, "case {n}");
            compared += 1;
            entered += each.iter().flatten().count();
        }
        assert!(compared > 190_000, "{compared}");
        // Both answers are common: a fifth to four fifths of the boxes are entered.
        assert!(
            (compared * 3 / 5..compared * 12 / 5).contains(&entered),
            "{entered}"
        );
    }

    /// One slab rule: the BVH's node test enters a box exactly where
    /// [`Aabb::slab_conservative`] says the ray enters it, bit for bit, over the same
    /// cases (corners, axis-parallel rays, flat boxes, origins in a face plane).
    #[test]
    fn box_entry_is_the_aabbs_conservative_slab_entry() {
        let mut rng = Rng::new(0x5eed_51ab, 2);
        let (mut compared, mut entered) = (0, 0);
        for n in 0..200_000 {
            let Some(Case { boxes, ray, range }) = case(&mut rng, n) else {
                continue;
            };
            let (min, max) = boxes[n % 2];
            // (Setting a face to the origin's x can turn a box inside out.)
            let Ok(aabb) = Aabb::new(min, max) else {
                continue;
            };
            let expected = aabb
                .slab_conservative(&ray, range)
                .map(|span| span.t0.to_bits());
            let box_ray = BoxRay::new(&ray);
            let entry =
                box_entry((min.into(), max.into()), &box_ray, range).map(f32::to_bits);
            assert_eq!(entry, expected, "case {n}: {aabb:?} {ray:?} {range:?}");
            compared += 1;
            entered += usize::from(entry.is_some());
        }
        assert!(compared > 190_000, "{compared}");
        assert!(
            (compared / 5..compared * 4 / 5).contains(&entered),
            "{entered}"
        );
    }
}
