//! The list-or-tree choice: a scene's plain list while every ray may test every
//! primitive, else the same list through a [`BvhScene`], answering every ray alike.

use super::{BvhScene, Intersect, Scene, SceneHit};
use crate::progress;
use crate::ray::{Interval, Ray};

/// Above this many ray-primitive tests (pixels times primitives) a renderer stops
/// testing every primitive on every ray and goes through lesson 11's BVH: 2^28, about
/// 2.7 x 10^8 tests, a few seconds of brute force. The torus at 480 x 270 (1.3 x 10^8
/// tests) stays below; the teapot (5.2 x 10^8) goes above.
pub const BRUTE_FORCE_TESTS: u64 = 1 << 28;

/// A scene as the renderers see it: the plain list of lesson 08 while every ray may
/// test every primitive (at most [`BRUTE_FORCE_TESTS`] tests in all), else the same
/// list through lesson 11's BVH, which answers every ray as the list does, so the
/// image is the same, bit for bit. Lesson 09's floor and mesh, lesson 10's teapot
/// and lesson 11's scenes all go through it.
#[derive(Clone, Debug, PartialEq)]
pub enum ListOrTree {
    /// Every ray tests every primitive.
    List(Scene),
    /// Rays walk a BVH over the same primitives.
    Tree(BvhScene),
}

impl ListOrTree {
    /// `scene` as a plain list, or through a BVH (built under a spinner) when a
    /// render of `rays` camera rays would make more than [`BRUTE_FORCE_TESTS`] tests.
    pub fn new(scene: Scene, rays: u64) -> ListOrTree {
        let primitives = scene.objects().len();
        if rays.saturating_mul(primitives as u64) <= BRUTE_FORCE_TESTS {
            return ListOrTree::List(scene);
        }
        let message = format!("building a BVH over {primitives} primitives");
        ListOrTree::Tree(progress::spinner(message, || BvhScene::new(scene)))
    }
}

/// The list's or the tree's answers.
impl Intersect for ListOrTree {
    fn scene(&self) -> &Scene {
        match self {
            ListOrTree::List(scene) => scene,
            ListOrTree::Tree(tree) => tree.scene(),
        }
    }

    fn closest(&self, ray: &Ray, range: Interval) -> Option<SceneHit> {
        match self {
            ListOrTree::List(scene) => scene.closest(ray, range),
            ListOrTree::Tree(tree) => tree.closest(ray, range),
        }
    }

    fn occluded(&self, ray: &Ray, range: Interval) -> bool {
        match self {
            ListOrTree::List(scene) => scene.occluded(ray, range),
            ListOrTree::Tree(tree) => tree.occluded(ray, range),
        }
    }
}
