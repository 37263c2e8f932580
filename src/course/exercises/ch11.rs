//! Chapter 11, Speed against accuracy: coding exercises 11.4 and 11.6.
//!
//! Check them with `cargo test --test exercises ch11`.
// The parameters are unused until you write the bodies.
#![allow(unused_variables)]

use glam::Vec3;

use crate::ray::{ClosedSpan, Interval};
use crate::shapes::Aabb;

/// Coding exercise 11.4: the slab test with a precomputed `1/d`. The closed interval
/// `[t0, t1]` of the ray `o + t d` inside the closed box `[min, max]`, clipped to
/// `[range.min, range.max]`, as a `ClosedSpan { t0, t1 }`, or `None` if it is empty.
/// `inv_d` is `1 / d`, component by component, computed once per ray by the caller: a
/// zero component of `d` gives an infinite one here (`1 / 0 = inf`, `1 / -0 = -inf`).
///
/// Per axis i, t_near = (min_i - o_i) * inv_d_i and t_far = (max_i - o_i) * inv_d_i,
/// swapped if inv_d_i < 0 (the sign decides, not a comparison of the ends, which a NaN
/// defeats). Start with [t0, t1] = [range.min, range.max]; raise t0 to
/// t_near if t_near > t0, lower t1 to t_far if t_far < t1, and give up when t0 > t1.
/// The box is closed (a hit whenever t0 <= t1), and a NaN from 0 * inf (a ray lying
/// in a face's plane) must leave the interval alone.
pub fn slab(
    o: Vec3,
    inv_d: Vec3,
    min: Vec3,
    max: Vec3,
    range: Interval,
) -> Option<ClosedSpan> {
    todo!(
        "Coding exercise 11.4 (chapter 11, Speed against accuracy): the slab test \
         with a precomputed 1/d"
    )
}

/// Coding exercise 11.6: the surface area heuristic. The expected cost, in primitive
/// tests, of splitting the BVH node whose box is `node` into a left child (box `left`,
/// `left_count` primitives) and a right child (box `right`, `right_count` primitives):
///
/// C_trav + (A(L) N(L) + A(R) N(R)) / A(node),
///
/// where A is a box's surface area (`Aabb::surface_area`), N a primitive count and
/// C_trav = `crate::bvh::build::TRAVERSAL_COST` the cost of visiting a node. A ray that
/// hits the node's box hits a child's box with probability about A(child) / A(node).
/// (`bvh::build::split_cost` is the crate's answer, from the areas.)
pub fn sah_cost(
    node: &Aabb,
    left: &Aabb,
    left_count: usize,
    right: &Aabb,
    right_count: usize,
) -> f32 {
    todo!(
        "Coding exercise 11.6 (chapter 11, Speed against accuracy): the SAH cost of a split"
    )
}
