//! Walking a BVH: which primitives a ray must be tested against.
//!
//! Iterative, with a fixed stack of [`MAX_DEPTH`] entries (the build never makes a
//! deeper tree). At an interior node both children's boxes are tested; the nearer
//! box (by entry distance) is visited next and the other pushed with its entry
//! distance, so a close hit is usually found early, shrinks the search range, and
//! lets the walk drop pushed boxes that now start beyond it without testing them
//! again (the ordered traversal of Wald et al., "Interactive Rendering with Coherent
//! Ray Tracing", 2001, as pbrt-v4 and Embree do it).
//!
//! The node boxes are tested by the conservative slab test of `src/bvh/slab.rs`
//! (STABILITY S6), both children of a node at once, with the ray's 1/d worked out
//! once per ray.

use glam::Vec3A;

use crate::bvh::slab::{BoxRay, both_entries, box_entry};
use crate::bvh::{Bvh, LeafShapes, MAX_DEPTH};
use crate::float::gamma;
use crate::ray::{Interval, Ray};
use crate::scene::{Object, SceneHit};
use crate::shapes::{Candidate, PreparedRay};

/// The relative margin added to the far end of the box tests: 4 gamma(3), about
/// 7e-7 (a few ulps of `t`). See `Nearest::box_limit`.
pub const TIE_MARGIN: f32 = 4.0 * gamma(3);

/// What the walk does after a leaf.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Walk {
    /// Go on, with boxes tested up to this far end.
    Continue { t_max: f32 },
    /// The question is answered.
    Stop,
}

/// The nearest hit found so far: its candidate and object index.
///
/// Ties: the plain list keeps the first object in list order among equal `t`
/// (a later one must be strictly nearer). To give the same answer whatever order
/// the tree visits objects in, each test here searches up to just past the best `t`
/// (its next float up) and an equal `t` wins only with a smaller index.
struct Nearest {
    best: Option<(Candidate, usize)>,
    /// The far end of the search: the range's end, or just past the best hit's `t`
    /// (its next float up) once there is one.
    limit: f32,
    /// [`Nearest::box_limit`], made when the limit changes rather than at every
    /// leaf.
    box_limit: f32,
}

impl Nearest {
    /// The far end of the search: the range's end, or just past the best hit's `t`.
    fn limit(&self) -> f32 {
        self.limit
    }

    /// How far boxes are tested: [`Nearest::limit`] moved out by [`TIE_MARGIN`] of
    /// itself. A box's entry and a primitive's `t` are rounded differently: the box
    /// around a triangle that hits at exactly the best `t` (say at a vertex it
    /// shares with the best triangle) can be entered a few ulps later. Without the
    /// margin the tree would skip that box and could break the tie differently from
    /// the list.
    fn box_limit(&self) -> f32 {
        self.box_limit
    }

    /// No hit yet: the search runs to `t_max`.
    fn up_to(t_max: f32) -> Nearest {
        Nearest {
            best: None,
            limit: t_max,
            box_limit: widened(t_max),
        }
    }

    /// Keeps `candidate` of object `i` if nearer (or as near with a smaller index).
    fn offer(&mut self, candidate: Candidate, i: usize) {
        let better = match self.best {
            None => true,
            Some((best, j)) => candidate.t < best.t || (candidate.t == best.t && i < j),
        };
        if better {
            self.best = Some((candidate, i));
            self.limit = candidate.t.next_up();
            self.box_limit = widened(self.limit);
        }
    }

    /// Offers each of a leaf's `shapes`, whose object indices are `objects`, with
    /// its candidate from `test` within `range` up to the nearest hit so far.
    #[inline(always)]
    fn offer_leaf<S>(
        &mut self,
        shapes: &[S],
        objects: &[usize],
        range: Interval,
        test: impl Fn(&S, Interval) -> Option<Candidate>,
    ) {
        for (shape, &i) in shapes.iter().zip(objects) {
            if let Some(c) = test(shape, range.up_to(self.limit())) {
                self.offer(c, i);
            }
        }
    }
}

/// `t` moved out by [`TIE_MARGIN`] of itself (infinity stays infinity), as a slab
/// exit is moved out ([`crate::shapes::aabb::moved_out`]) by its own margin.
fn widened(t: f32) -> f32 {
    t + t.abs() * TIE_MARGIN
}

impl Bvh {
    /// The nearest hit within `range` among `objects` (the slice the tree was built
    /// over) and its index: the unbounded objects first, then the tree,
    /// whose boxes are tested only up to the nearest hit so far.
    pub fn closest(
        &self,
        objects: &[Object],
        ray: &Ray,
        range: Interval,
    ) -> Option<SceneHit> {
        if self.misses_everything(ray, range) {
            return None;
        }
        let prepared = PreparedRay::new(ray);
        let (candidate, object) = self.closest_candidate(objects, &prepared, range)?;
        let hit = objects[object].shape.record(&prepared, candidate);
        Some(SceneHit { hit, object })
    }

    /// The object [`Bvh::closest`] finds, without its hit record.
    pub fn closest_object(
        &self,
        objects: &[Object],
        ray: &Ray,
        range: Interval,
    ) -> Option<usize> {
        if self.misses_everything(ray, range) {
            return None;
        }
        let prepared = PreparedRay::new(ray);
        Some(self.closest_candidate(objects, &prepared, range)?.1)
    }

    /// True if the ray can meet nothing: no unbounded object, and it misses the
    /// root's box. Tested with 1/d alone, before the rest of the ray's set-up (the
    /// watertight test's shear costs two more divisions) is made for nothing.
    fn misses_everything(&self, ray: &Ray, range: Interval) -> bool {
        let Some(root) = &self.root else {
            return self.unbounded.is_empty();
        };
        let box_ray = BoxRay::with_inv_d(
            ray.origin().into(),
            Vec3A::from(ray.direction()).recip(),
        );
        self.unbounded.is_empty()
            && box_entry(
                (root.min, root.max),
                &box_ray,
                range.up_to(widened(range.max)),
            )
            .is_none()
    }

    /// The closest candidate and its object, as [`Bvh::closest`] finds them.
    fn closest_candidate(
        &self,
        objects: &[Object],
        prepared: &PreparedRay,
        range: Interval,
    ) -> Option<(Candidate, usize)> {
        let mut nearest = Nearest::up_to(range.max);
        for &i in &self.unbounded {
            if let Some(c) = objects[i]
                .shape
                .candidate(prepared, range.up_to(nearest.limit()))
            {
                nearest.offer(c, i);
            }
        }
        self.walk(prepared, range.up_to(nearest.box_limit()), |leaf| {
            let objects = &self.primitives[leaf.clone()];
            match &self.shapes {
                LeafShapes::Triangles(t) => {
                    nearest.offer_leaf(&t[leaf], objects, range, |t, r| {
                        t.candidate(prepared, r)
                    })
                }
                LeafShapes::Shapes(s) => {
                    nearest.offer_leaf(&s[leaf], objects, range, |s, r| {
                        s.candidate(prepared, r)
                    })
                }
            }
            Walk::Continue {
                t_max: nearest.box_limit(),
            }
        });
        nearest.best
    }

    /// True if any of `objects` lies on the ray within `range`; stops at
    /// the first one found.
    pub fn occluded(&self, objects: &[Object], ray: &Ray, range: Interval) -> bool {
        let prepared = PreparedRay::new(ray);
        let hits = |&i: &usize| objects[i].shape.candidate(&prepared, range).is_some();
        if self.unbounded.iter().any(hits) {
            return true;
        }
        // The boxes get the same margin as in [`Bvh::closest`]: an object that hits
        // just before `range.max` may have a box entered just after it.
        let box_t_max = widened(range.max);
        let mut found = false;
        self.walk(&prepared, range.up_to(box_t_max), |leaf| {
            let hit = |p: usize| self.shapes.candidate(p, &prepared, range).is_some();
            if leaf.into_iter().any(hit) {
                found = true;
                Walk::Stop
            } else {
                Walk::Continue { t_max: box_t_max }
            }
        });
        found
    }

    // ANCHOR: traverse
    /// Visits, nearer child first, every leaf whose box the ray passes through
    /// within `range`, handing the range of its primitives (positions in
    /// [`Bvh::primitives`]) to `leaf`, which answers with the far end to use from
    /// then on, or [`Walk::Stop`].
    ///
    /// `(first, count)` is the child being visited, packed as a node stores it (a
    /// leaf if `count > 0`, else node `first`), its box already known to be hit;
    /// `stack` holds the farther children still to visit, packed the same way, each
    /// with its entry distance. A pushed child whose entry now lies beyond `t_max` is
    /// dropped when popped.
    fn walk(
        &self,
        ray: &PreparedRay,
        range: Interval,
        mut leaf: impl FnMut(std::ops::Range<usize>) -> Walk,
    ) {
        let Some(root) = &self.root else {
            return;
        };
        let box_ray = BoxRay::new(ray);
        let mut range = range;
        if box_entry((root.min, root.max), &box_ray, range).is_none() {
            return;
        }
        let mut stack = [(0u32, 0u32, 0.0f32); MAX_DEPTH];
        let mut pending = 0;
        let (mut first, mut count) = (root.first, root.count);
        loop {
            if count > 0 {
                let first = first as usize;
                match leaf(first..first + count as usize) {
                    Walk::Continue { t_max: t } => range.max = t,
                    Walk::Stop => return,
                }
            } else {
                let node = &self.nodes[first as usize];
                let next = match both_entries(node, &box_ray, range) {
                    [Some(a), Some(b)] => {
                        let (near, far, t_far) =
                            if a <= b { (0, 1, b) } else { (1, 0, a) };
                        let (f, c) = node.packed(far);
                        stack[pending] = (f, c, t_far);
                        pending += 1;
                        Some(near)
                    }
                    [Some(_), None] => Some(0),
                    [None, Some(_)] => Some(1),
                    [None, None] => None,
                };
                if let Some(i) = next {
                    (first, count) = node.packed(i);
                    continue;
                }
            }
            (first, count) = loop {
                if pending == 0 {
                    return;
                }
                pending -= 1;
                let (f, c, t_entry) = stack[pending];
                if t_entry <= range.max {
                    break (f, c);
                }
            };
        }
    }
    // ANCHOR_END: traverse
}
