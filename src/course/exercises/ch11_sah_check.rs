//! The check of chapter 11's second coding exercise, the surface area heuristic's
//! cost of a split: the cases, the reference answer for each, and the hints for the
//! typical mistakes. The student's function is in `ch11.rs`; the harness is
//! `harness.rs`.

use glam::Vec3;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run, v};
use crate::bvh::build::{TRAVERSAL_COST, split_cost};
use crate::shapes::Aabb;

/// Coding exercise 11.6.
pub const SAH_COST: Exercise = Exercise {
    number: "11.6",
    chapter: "11",
    chapter_title: "Speed against accuracy",
    function: "sah_cost",
    file: "src/course/exercises/ch11.rs",
};

// ANCHOR: solution
/// A worked solution of exercise 11.6: each child's primitives are tested by the
/// share A(child) / A(node) of the rays that reach the node.
pub fn sah_cost_solution(
    node: &Aabb,
    left: &Aabb,
    left_count: usize,
    right: &Aabb,
    right_count: usize,
) -> f32 {
    let area = node.surface_area();
    let left_share = left.surface_area() / area;
    let right_share = right.surface_area() / area;
    TRAVERSAL_COST + left_share * left_count as f32 + right_share * right_count as f32
}
// ANCHOR_END: solution

/// The arguments of `sah_cost`: the node's box, then each child's box and count.
type SahArgs = (Aabb, Aabb, usize, Aabb, usize);

/// A box's volume.
fn volume(b: &Aabb) -> f32 {
    let e = b.max() - b.min();
    e.x * e.y * e.z
}

/// `C_trav + (m(L) N(L) + m(R) N(R)) / m(node)` for a measure `m` of a box, with the
/// traversal cost `c_trav`.
fn cost_by(a: &SahArgs, m: fn(&Aabb) -> f32, c_trav: f32) -> f32 {
    let (node, left, nl, right, nr) = a;
    c_trav + (m(left) * *nl as f32 + m(right) * *nr as f32) / m(node)
}

/// Checks `sah_cost(node, left, left_count, right, right_count)`: the SAH cost of a
/// split, C_trav + (A(L) N(L) + A(R) N(R)) / A(node), in primitive tests.
pub fn check_sah_cost(
    f: impl Fn(&Aabb, &Aabb, usize, &Aabb, usize) -> f32 + Send + Sync + 'static,
) -> Outcome {
    sah_cost_checked(Box::new(f))
}

/// [`check_sah_cost`] for the answer as a trait object: compiled once, here, not again
/// for every closure a test passes (see [`super::harness`]).
fn sah_cost_checked(
    f: Box<dyn Fn(&Aabb, &Aabb, usize, &Aabb, usize) -> f32 + Send + Sync>,
) -> Outcome {
    let aabb = |min: Vec3, max: Vec3| Aabb::new(min, max).expect("valid box");
    let cube = aabb(Vec3::ZERO, v(2.0, 2.0, 2.0));
    let left_half = aabb(Vec3::ZERO, v(1.0, 2.0, 2.0));
    let right_half = aabb(v(1.0, 0.0, 0.0), v(2.0, 2.0, 2.0));
    let corner = aabb(Vec3::ZERO, v(0.5, 0.5, 0.5));
    let long = aabb(Vec3::ZERO, v(8.0, 1.0, 1.0));
    let long_left = aabb(Vec3::ZERO, v(2.0, 1.0, 1.0));
    let long_right = aabb(v(2.0, 0.0, 0.0), v(8.0, 1.0, 1.0));
    let flat = aabb(Vec3::ZERO, v(4.0, 4.0, 0.0));
    let flat_left = aabb(Vec3::ZERO, v(1.0, 4.0, 0.0));
    let flat_right = aabb(v(3.0, 0.0, 0.0), v(4.0, 4.0, 0.0));
    let cases: Vec<Case<SahArgs>> = [
        (
            "a cube cut in two halves, 4 primitives each",
            (cube, left_half, 4, right_half, 4),
        ),
        (
            "a cube cut in two halves, 1 and 7 primitives",
            (cube, left_half, 1, right_half, 7),
        ),
        (
            "a small corner box split off, 2 and 6",
            (cube, corner, 2, cube, 6),
        ),
        (
            "a long box cut a quarter of the way, 5 and 3",
            (long, long_left, 5, long_right, 3),
        ),
        (
            "a flat box (no volume), 2 and 2",
            (flat, flat_left, 2, flat_right, 2),
        ),
    ]
    .into_iter()
    .map(|(what, (node, left, nl, right, nr))| {
        let show = |b: &Aabb| format!("{} to {}", b.min().show(), b.max().show());
        let case = format!(
            "{what}: node {}, left {} with {nl}, right {} with {nr}",
            show(&node),
            show(&left),
            show(&right)
        );
        (case, (node, left, nl, right, nr))
    })
    .collect();
    let area: fn(&Aabb) -> f32 = Aabb::surface_area;
    run(
        &cases,
        |(node, left, nl, right, nr)| {
            let count = |n: &usize| u32::try_from(*n).expect("a small count");
            split_cost(
                node.surface_area(),
                (left.surface_area(), count(nl)),
                (right.surface_area(), count(nr)),
            )
        },
        move |(node, left, nl, right, nr)| f(&node, &left, nl, &right, nr),
        &[
            Mistake {
                looks_like: &gives(&|a: &SahArgs| Some(cost_by(a, area, 0.0))),
                hint: "add the cost of visiting the node, C_trav = TRAVERSAL_COST: without it a \
                       split always looks at least as cheap as a leaf",
            },
            Mistake {
                looks_like: &gives(&|a: &SahArgs| {
                    let (_, left, nl, right, nr) = a;
                    Some(
                        TRAVERSAL_COST
                            + area(left) * *nl as f32
                            + area(right) * *nr as f32,
                    )
                }),
                hint: "divide by the node's surface area: A(child) / A(node) is the probability \
                       that a ray through the node's box hits the child's box",
            },
            Mistake {
                looks_like: &gives(&|a: &SahArgs| {
                    Some(cost_by(a, volume, TRAVERSAL_COST))
                }),
                hint: "the heuristic weighs boxes by their surface area, 2 (xy + yz + zx), not \
                       their volume: a random ray hits a box in proportion to its area (and a \
                       flat box has no volume at all)",
            },
            Mistake {
                looks_like: &gives(&|a: &SahArgs| {
                    let (node, left, _, right, _) = a;
                    Some(TRAVERSAL_COST + (area(left) + area(right)) / area(node))
                }),
                hint: "each child's share must be multiplied by its number of primitives, \
                       N(L) and N(R): a ray that enters a child tests every primitive in it",
            },
        ],
        "C_trav + (A(L) N(L) + A(R) N(R)) / A(node), A the surface area 2 (xy + yz + zx)",
    )
}
