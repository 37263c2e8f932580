//! Walking a BVH: which primitives a ray must be tested against.
//!
//! Iterative, with a fixed stack of [`MAX_DEPTH`] node indices (the build never
//! makes a deeper tree). At an interior node the child on the near side of the split
//! axis is visited first and the other pushed, so a close hit is usually found early
//! and shrinks the search range, which then rejects the far boxes.
//!
//! The node boxes are tested with [`Aabb::slab_conservative`], the slab test whose
//! exits are widened by 1 + 2 gamma(3) (Ize 2013, "Robust BVH Ray Traversal", as in
//! pbrt-v4): rounding cannot make a box miss a point of a primitive inside it, so the
//! tree never loses a hit the plain list would find (STABILITY S6).
//!
//! [`Aabb::slab_conservative`]: crate::shapes::Aabb::slab_conservative

use crate::bvh::{Bvh, MAX_DEPTH, NodeKind};
use crate::ray::Ray;
use crate::scene::Object;
use crate::shapes::Hit;
use crate::shapes::aabb::gamma;

/// The relative margin added to the far end of the box tests: 4 gamma(3), about
/// 7e-7 (a few ulps of `t`). See [`Nearest::box_limit`].
pub const TIE_MARGIN: f32 = 4.0 * gamma(3);

/// What the walk does after a leaf.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Walk {
    /// Go on, with boxes tested up to this far end.
    Continue { t_max: f32 },
    /// The question is answered.
    Stop,
}

/// The nearest hit found so far and its object index.
///
/// Ties: the plain list keeps the first object in list order among equal `t`
/// (a later one must be strictly nearer). To give the same answer whatever order
/// the tree visits objects in, each test here searches up to just past the best `t`
/// (its next float up) and an equal `t` wins only with a smaller index.
struct Nearest {
    best: Option<(Hit, usize)>,
    t_max: f32,
}

impl Nearest {
    /// The far end of the search: `t_max`, or just past the best hit's `t`.
    fn limit(&self) -> f32 {
        match self.best {
            Some((hit, _)) => hit.t.next_up(),
            None => self.t_max,
        }
    }

    /// How far boxes are tested: [`Nearest::limit`] moved out by [`TIE_MARGIN`] of
    /// itself. A box's entry and a primitive's `t` are rounded differently: the box
    /// around a triangle that hits at exactly the best `t` (say at a vertex it
    /// shares with the best triangle) can be entered a few ulps later. Without the
    /// margin the tree would skip that box and could break the tie differently from
    /// the list.
    fn box_limit(&self) -> f32 {
        widened(self.limit())
    }

    /// Tests object `i` and keeps its hit if nearer (or as near with a smaller index).
    fn offer(&mut self, objects: &[Object], i: usize, ray: &Ray, t_min: f32) {
        let Some(hit) = objects[i].shape.hit(ray, t_min, self.limit()) else {
            return;
        };
        let better = match self.best {
            None => true,
            Some((best, j)) => hit.t < best.t || (hit.t == best.t && i < j),
        };
        if better {
            self.best = Some((hit, i));
        }
    }
}

/// `t` moved out by [`TIE_MARGIN`] of itself (infinity stays infinity).
fn widened(t: f32) -> f32 {
    t + t.abs() * TIE_MARGIN
}

impl Bvh {
    /// The nearest hit with `t_min < t < t_max` among `objects` (the slice the tree
    /// was built over) and its index: the unbounded objects first, then the tree,
    /// whose boxes are tested only up to the nearest hit so far.
    pub fn closest_hit(
        &self,
        objects: &[Object],
        ray: &Ray,
        t_min: f32,
        t_max: f32,
    ) -> Option<(Hit, usize)> {
        let mut nearest = Nearest { best: None, t_max };
        for &i in &self.unbounded {
            nearest.offer(objects, i, ray, t_min);
        }
        self.walk(ray, t_min, nearest.box_limit(), |leaf| {
            for &i in leaf {
                nearest.offer(objects, i, ray, t_min);
            }
            Walk::Continue {
                t_max: nearest.box_limit(),
            }
        });
        nearest.best
    }

    /// True if any of `objects` lies on the ray with `t_min < t < t_max`; stops at
    /// the first one found.
    pub fn occluded(&self, objects: &[Object], ray: &Ray, t_min: f32, t_max: f32) -> bool {
        let hits = |&i: &usize| objects[i].shape.hit(ray, t_min, t_max).is_some();
        if self.unbounded.iter().any(hits) {
            return true;
        }
        // The boxes get the same margin as in `closest_hit`: an object that hits just
        // before `t_max` may have a box entered just after it.
        let box_t_max = widened(t_max);
        let mut found = false;
        self.walk(ray, t_min, box_t_max, |leaf| {
            if leaf.iter().any(hits) {
                found = true;
                Walk::Stop
            } else {
                Walk::Continue { t_max: box_t_max }
            }
        });
        found
    }

    // ANCHOR: traverse
    /// Visits, nearest child first, every leaf whose box the ray passes through
    /// within `t_min < t < t_max`, handing its primitives to `leaf`, which answers
    /// with the far end to use from then on, or [`Walk::Stop`].
    ///
    /// `node` is the node being looked at; `stack` holds the far children still to
    /// visit. A box the ray misses, or a leaf, sends the walk to the top of the stack.
    fn walk(&self, ray: &Ray, t_min: f32, t_max: f32, mut leaf: impl FnMut(&[usize]) -> Walk) {
        if self.nodes.is_empty() {
            return;
        }
        let mut t_max = t_max;
        let mut stack = [0usize; MAX_DEPTH];
        let mut pending = 0;
        let mut node = 0;
        loop {
            let here = &self.nodes[node];
            let mut next = None;
            if here.bounds.slab_conservative(ray, t_min, t_max).is_some() {
                match here.kind {
                    NodeKind::Leaf { first, count } => match leaf(self.leaf(first, count)) {
                        Walk::Continue { t_max: t } => t_max = t,
                        Walk::Stop => return,
                    },
                    NodeKind::Interior { right, axis } => {
                        // The left child holds the smaller coordinates along `axis`.
                        let (near, far) = if ray.direction()[axis] < 0.0 {
                            (right, node + 1)
                        } else {
                            (node + 1, right)
                        };
                        stack[pending] = far;
                        pending += 1;
                        next = Some(near);
                    }
                }
            }
            node = match next {
                Some(near) => near,
                None if pending > 0 => {
                    pending -= 1;
                    stack[pending]
                }
                None => return,
            };
        }
    }
    // ANCHOR_END: traverse
}
