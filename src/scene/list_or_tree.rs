//! The list-or-tree choice: a scene's plain list while testing every primitive on
//! every ray costs less than a tree, else the same list through a [`BvhScene`],
//! answering every ray alike.

use super::{BvhScene, Intersect, Scene, SceneHit};
use crate::progress;
use crate::ray::{Interval, Ray};

/// What one ray-primitive test costs the list, in machine instructions: 108, a
/// triangle of lesson 09's torus or teapot against a camera ray in a release build.
/// Measured with `valgrind --tool=callgrind` (one thread), as the difference
/// between ray casting lesson 09's floor and mesh at 96 x 54 pixels and only
/// reading it, divided by the rays and the primitives.
pub const TEST_COST: u64 = 108;

/// What a ray costs the tree beyond what it costs the list at one primitive, in
/// instructions: the walk down lesson 11's BVH. Measured as [`TEST_COST`] is, on
/// the torus, the teapot and the teapot split in four twice (1025 to 64 513
/// primitives): 466 to 510, the most taken.
pub const WALK_COST: u64 = 510;

/// What building the tree costs a primitive, in instructions: 1765 for the torus,
/// 2030 for the teapot, 2489 for the teapot split in four twice (it grows with the
/// tree's depth); rounded up.
pub const BUILD_COST: u64 = 2500;

/// A scene as the renderers see it: the plain list of lesson 08 while testing every
/// primitive on every ray costs less than building lesson 11's BVH and walking it
/// ([`ListOrTree::new`]), else the same list through the BVH, which answers every
/// ray as the list does, so the image is the same, bit for bit. Lesson 09's floor
/// and mesh, lesson 10's scenes and lesson 11's go through it.
#[derive(Clone, Debug, PartialEq)]
pub enum ListOrTree {
    /// Every ray tests every primitive.
    List(Scene),
    /// Rays walk a BVH over the same primitives.
    Tree(BvhScene),
}

impl ListOrTree {
    // ANCHOR: choice
    /// `scene` as a plain list, or through a BVH (built under a spinner), whichever
    /// costs fewer instructions for `rays` rays. Of n primitives, b have a box and
    /// go into the tree; the other n - b (planes, quadrics) are tested on every ray
    /// either way. The list costs rays x n x [`TEST_COST`]; the tree b x
    /// [`BUILD_COST`] + rays x ([`WALK_COST`] + (n - b) x [`TEST_COST`]). The list
    /// wins for a handful of boxed primitives or of rays.
    pub fn new(scene: Scene, rays: u64) -> ListOrTree {
        let n = scene.objects().len() as u64;
        let b = scene
            .objects()
            .iter()
            .filter(|o| o.shape.bounds().is_some())
            .count() as u64;
        let list = rays.saturating_mul(n).saturating_mul(TEST_COST);
        let per_ray = WALK_COST.saturating_add((n - b).saturating_mul(TEST_COST));
        let tree = b
            .saturating_mul(BUILD_COST)
            .saturating_add(rays.saturating_mul(per_ray));
        if list <= tree {
            return ListOrTree::List(scene);
        }
        let message = format!("building a BVH over {b} primitives");
        ListOrTree::Tree(progress::spinner(message, || BvhScene::new(scene)))
    }
    // ANCHOR_END: choice
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
