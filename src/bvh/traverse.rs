//! What a walk of the BVH is for: the nearest crossing among the primitives a ray
//! must be tested against ([`Bvh::closest`]), and whether there is any
//! ([`Bvh::any`]).
//!
//! The walk itself is in `src/bvh/wide.rs`: it visits the leaves whose boxes the
//! ray passes through, nearest first, so that a close hit is usually found early,
//! shrinks the search range, and lets the walk drop boxes that now start beyond it
//! without testing them again (the ordered traversal of Wald et al., "Interactive
//! Rendering with Coherent Ray Tracing", 2001, as pbrt-v4 and Embree do it). The
//! primitives themselves are tested by the caller, leaf by leaf: the tree knows
//! their boxes, not what they are.

use std::ops::Range;

use crate::bvh::Bvh;
use crate::bvh::slab::{BoxRay, box_entry};
use crate::float::gamma;
use crate::ray::Interval;

/// The relative margin added to the far end of the box tests: 4 gamma(3), about
/// 7e-7 (a few ulps of `t`). See [`Nearest::box_limit`].
pub const TIE_MARGIN: f32 = 4.0 * gamma(3);

/// What the tree's search needs to know of a primitive's crossing: how far along
/// the ray it lies.
pub trait Crossing: Copy {
    /// The ray parameter of the crossing.
    fn t(&self) -> f32;
}

/// What the walk does after a leaf.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Walk {
    /// Go on, with boxes tested up to this far end.
    Continue { t_max: f32 },
    /// The question is answered.
    Stop,
}

/// The nearest crossing found so far, `C` (a primitive's test's answer), and the
/// index of its primitive.
///
/// Ties: a plain list keeps the first primitive in list order among equal `t` (a
/// later one must be strictly nearer). To give the same answer whatever order the
/// tree visits primitives in, each test here searches up to just past the best `t`
/// (its next float up) and an equal `t` wins only with a smaller index.
#[derive(Clone, Copy, Debug)]
pub struct Nearest<C> {
    best: Option<(C, usize)>,
    /// The far end of the search: the range's end, or just past the best hit's `t`
    /// (its next float up) once there is one.
    limit: f32,
    /// [`Nearest::box_limit`], made when the limit changes rather than at every
    /// leaf.
    box_limit: f32,
}

impl<C: Crossing> Nearest<C> {
    /// The far end of the search: the range's end, or just past the best hit's `t`.
    pub fn limit(&self) -> f32 {
        self.limit
    }

    /// How far boxes are tested: [`Nearest::limit`] moved out by [`TIE_MARGIN`] of
    /// itself. A box's entry and a primitive's `t` are rounded differently: the box
    /// around a triangle that hits at exactly the best `t` (say at a vertex it
    /// shares with the best triangle) can be entered a few ulps later. Without the
    /// margin the tree would skip that box and could break the tie differently from
    /// the list.
    pub fn box_limit(&self) -> f32 {
        self.box_limit
    }

    /// No hit yet: the search runs to `t_max`.
    fn up_to(t_max: f32) -> Nearest<C> {
        Nearest {
            best: None,
            limit: t_max,
            box_limit: widened(t_max),
        }
    }

    /// Keeps `crossing` of primitive `i` if nearer (or as near with a smaller index).
    pub fn offer(&mut self, crossing: C, i: usize) {
        let better = match self.best {
            None => true,
            Some((best, j)) => {
                crossing.t() < best.t() || (crossing.t() == best.t() && i < j)
            }
        };
        if better {
            self.best = Some((crossing, i));
            self.limit = crossing.t().next_up();
            self.box_limit = widened(self.limit);
        }
    }

    /// Offers each of a leaf's `shapes`, whose primitive indices are `indices`, with
    /// its crossing from `test` within `range` up to the nearest hit so far.
    #[inline(always)]
    pub fn offer_leaf<S>(
        &mut self,
        shapes: &[S],
        indices: &[usize],
        range: Interval,
        test: impl Fn(&S, Interval) -> Option<C>,
    ) {
        for (shape, &i) in shapes.iter().zip(indices) {
            if let Some(c) = test(shape, range.up_to(self.limit())) {
                self.offer(c, i);
            }
        }
    }
}

/// `t` moved out by [`TIE_MARGIN`] of itself (infinity stays infinity), as a slab
/// exit is moved out by its own margin (`moved_out`).
fn widened(t: f32) -> f32 {
    t + t.abs() * TIE_MARGIN
}

impl Bvh {
    // ANCHOR: closest
    /// The nearest crossing within `range` among the primitives the tree was built
    /// over, and its primitive's index: each unbounded one tested first by
    /// `unbounded(i, range)`, then the tree walked, its boxes tested only up to the
    /// nearest crossing so far, and each leaf it reaches handed to `leaf` with the
    /// positions of its primitives in [`Bvh::primitives`], to offer their crossings
    /// to the [`Nearest`] ([`Nearest::offer_leaf`]).
    #[inline(always)]
    pub fn closest<C: Crossing>(
        &self,
        ray: &BoxRay,
        range: Interval,
        mut unbounded: impl FnMut(usize, Interval) -> Option<C>,
        mut leaf: impl FnMut(Range<usize>, &mut Nearest<C>),
    ) -> Option<(C, usize)> {
        let mut nearest = Nearest::up_to(range.max);
        for &i in &self.unbounded {
            if let Some(c) = unbounded(i, range.up_to(nearest.limit())) {
                nearest.offer(c, i);
            }
        }
        self.walk(ray, range.up_to(nearest.box_limit()), |positions| {
            leaf(positions, &mut nearest);
            Walk::Continue {
                t_max: nearest.box_limit(),
            }
        });
        nearest.best
    }
    // ANCHOR_END: closest

    /// True if any primitive lies on the ray within `range`: `unbounded(i)` for each
    /// unbounded one, then `leaf(positions)` for each leaf the walk reaches, until
    /// one says yes.
    pub fn any(
        &self,
        ray: &BoxRay,
        range: Interval,
        unbounded: impl FnMut(&usize) -> bool,
        mut leaf: impl FnMut(Range<usize>) -> bool,
    ) -> bool {
        if self.unbounded.iter().any(unbounded) {
            return true;
        }
        // The boxes get the same margin as in [`Bvh::closest`]: a primitive that hits
        // just before `range.max` may have a box entered just after it.
        let box_t_max = widened(range.max);
        if !self.enters_root(ray, range) {
            return false;
        }
        let mut found = false;
        self.walk(ray, range.up_to(box_t_max), |positions| {
            if leaf(positions) {
                found = true;
                Walk::Stop
            } else {
                Walk::Continue { t_max: box_t_max }
            }
        });
        found
    }

    /// True if the ray can meet nothing: no unbounded primitive, and it misses the
    /// root's box. Tested with 1/d alone, before the rest of a ray's set-up for the
    /// primitives' tests (the watertight test's shear costs two more divisions) is
    /// made for nothing; that set-up then reuses the same 1/d
    /// ([`PreparedRay::with_inv_d`](crate::shapes::PreparedRay::with_inv_d)) and
    /// `ray`, and [`Bvh::closest`] does not test the root's box again.
    pub fn misses_everything(&self, ray: &BoxRay, range: Interval) -> bool {
        self.unbounded.is_empty() && !self.enters_root(ray, range)
    }

    /// True if the ray enters the root's box within `range`, its end widened as the
    /// walk widens it; false for a tree with no box.
    fn enters_root(&self, ray: &BoxRay, range: Interval) -> bool {
        self.root.is_some_and(|root| {
            let range = range.up_to(widened(range.max));
            box_entry((root.min, root.max), ray, range).is_some()
        })
    }
}
