//! A scene through a tree: the questions of [`Intersect`] answered by walking
//! lesson 11's bounding volume hierarchy ([`crate::bvh`]) over the scene's objects,
//! with the same answers as the plain list, faster once the scene is big.
//!
//! The tree keeps its own copy of the bounded shapes in leaf order, so that a
//! leaf's primitives sit next to each other in memory; planes and quadrics have no
//! box and are tested on every ray, before the tree.

use super::{Intersect, Object, Scene, SceneHit};
use crate::bvh::{Bounded, BoxRay, Bvh};
use crate::ray::{Interval, Ray};
use crate::shapes::{Candidate, PreparedRay, Shape, Triangle};

/// An object's box is its shape's.
impl Bounded for Object {
    fn corners(&self) -> Option<(glam::Vec3, glam::Vec3)> {
        self.shape.corners()
    }
}

/// The tree's own copy of the bounded shapes, in leaf order: triangles alone when
/// every one is a triangle (48 bytes each instead of a [`Shape`]'s 80, so a leaf's
/// primitives share fewer cache lines, and one test with no `match`), else the
/// shapes.
#[derive(Clone, Debug, PartialEq)]
enum LeafShapes {
    Triangles(Vec<Triangle>),
    Shapes(Vec<Shape>),
}

impl LeafShapes {
    /// `shapes` as triangles if every one is (copied once, not as shapes first, into
    /// a vector made at its full size).
    fn new<'a>(shapes: impl ExactSizeIterator<Item = &'a Shape> + Clone) -> LeafShapes {
        let mut triangles = Vec::with_capacity(shapes.len());
        for shape in shapes.clone() {
            match shape {
                Shape::Triangle(t) => triangles.push(*t),
                _ => return LeafShapes::Shapes(shapes.cloned().collect()),
            }
        }
        LeafShapes::Triangles(triangles)
    }

    /// Primitive `p`'s candidate within `range` (its kind's `candidate`).
    #[inline(always)]
    fn candidate(
        &self,
        p: usize,
        ray: &PreparedRay,
        range: Interval,
    ) -> Option<Candidate> {
        match self {
            LeafShapes::Triangles(t) => t[p].candidate(ray, range),
            LeafShapes::Shapes(s) => s[p].candidate(ray, range),
        }
    }
}

/// A [`Scene`] together with a BVH over its objects: the same questions as the scene
/// ([`Intersect::closest`], [`Intersect::occluded`]) with the same answers, faster
/// once the scene is big. The scene itself is unchanged.
#[derive(Clone, Debug, PartialEq)]
pub struct BvhScene {
    scene: Scene,
    bvh: Bvh,
    /// The shapes of `bvh.primitives()`, in the same order.
    shapes: LeafShapes,
}

impl BvhScene {
    /// Builds the BVH over `scene`'s objects ([`Bvh::build`]).
    pub fn new(scene: Scene) -> BvhScene {
        let bvh = Bvh::build(scene.objects());
        let objects = scene.objects();
        let shapes =
            LeafShapes::new(bvh.primitives().iter().map(|&i| &objects[i].shape));
        BvhScene { scene, bvh, shapes }
    }

    /// The scene (background, light, objects).
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The tree.
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }

    /// The ray as the boxes see it and as the primitives' tests do, both from one
    /// 1/d; `None` if it can meet nothing ([`Bvh::misses_everything`]), before the
    /// rest of the set-up is made for nothing.
    #[inline(always)]
    fn prepare(&self, ray: &Ray, range: Interval) -> Option<(BoxRay, PreparedRay)> {
        let box_ray = BoxRay::new(ray);
        if self.bvh.misses_everything(&box_ray, range) {
            return None;
        }
        let prepared = PreparedRay::with_inv_d(ray, box_ray.inv_d());
        Some((box_ray, prepared))
    }

    /// The closest candidate and its object, as [`Intersect::closest`] finds them:
    /// the unbounded objects, then the tree's leaves, by [`Bvh::closest`], with
    /// `box_ray` the ray as the boxes see it (the one `prepared` was made from).
    fn closest_candidate(
        &self,
        prepared: &PreparedRay,
        box_ray: &BoxRay,
        range: Interval,
    ) -> Option<(Candidate, usize)> {
        let objects = self.scene.objects();
        let unbounded = |i: usize, r| objects[i].shape.candidate(prepared, r);
        self.bvh
            .closest(box_ray, range, unbounded, |leaf, nearest| {
                let indices = &self.bvh.primitives()[leaf.clone()];
                match &self.shapes {
                    LeafShapes::Triangles(t) => {
                        nearest.offer_leaf(&t[leaf], indices, range, |t, r| {
                            t.candidate(prepared, r)
                        })
                    }
                    LeafShapes::Shapes(s) => {
                        nearest.offer_leaf(&s[leaf], indices, range, |s, r| {
                            s.candidate(prepared, r)
                        })
                    }
                }
            })
    }
}

/// The tree answers what the list answers ([`Scene::closest`], [`Scene::occluded`]):
/// the nearest hit within the range, on a tie (equal `t`) the object that
/// comes first in the scene's list; and whether anything lies on the ray.
impl Intersect for BvhScene {
    fn scene(&self) -> &Scene {
        &self.scene
    }

    fn closest(&self, ray: &Ray, range: Interval) -> Option<SceneHit> {
        let (box_ray, prepared) = self.prepare(ray, range)?;
        let (candidate, object) = self.closest_candidate(&prepared, &box_ray, range)?;
        let hit = self.scene.objects()[object]
            .shape
            .record(&prepared, candidate);
        Some(SceneHit { hit, object })
    }

    fn closest_object(&self, ray: &Ray, range: Interval) -> Option<usize> {
        let (box_ray, prepared) = self.prepare(ray, range)?;
        Some(self.closest_candidate(&prepared, &box_ray, range)?.1)
    }

    fn occluded(&self, ray: &Ray, range: Interval) -> bool {
        let prepared = PreparedRay::new(ray);
        let objects = self.scene.objects();
        let unbounded =
            |&i: &usize| objects[i].shape.candidate(&prepared, range).is_some();
        self.bvh.any(&prepared.box_ray(), range, unbounded, |leaf| {
            let hit = |p: usize| self.shapes.candidate(p, &prepared, range).is_some();
            leaf.into_iter().any(hit)
        })
    }
}
