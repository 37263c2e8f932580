//! A bounding volume hierarchy (BVH): a binary tree of boxes over a scene's
//! primitives, so that a ray tests the few primitives whose boxes it passes through
//! instead of every one (lesson 11, where a measured chart shows when it pays).
//!
//! - [`build`]: binned surface area heuristic (MacDonald and Booth 1990; binning after
//!   Wald 2007), into a flat array of 32-byte nodes whose two children sit side by
//!   side.
//! - [`traverse`]: an iterative walk with a small fixed stack; at each interior node
//!   both children's boxes are tested and the nearer one visited first, with the
//!   conservative slab test of Ize 2013 on the node boxes (STABILITY S6) and the
//!   ray's 1/d computed once ([`PreparedRay`](crate::shapes::PreparedRay)).
//!
//! Planes and quadrics have no box; they are kept in a plain list and tested on
//! every ray, before the tree. The tree keeps its own copy of the bounded shapes in
//! leaf order, so that a leaf's primitives sit next to each other in memory.

use glam::{Vec3, Vec3A, Vec4};

use crate::ray::{Interval, Ray};
use crate::scene::{Intersect, Scene, SceneHit};
use crate::shapes::{Aabb, Candidate, PreparedRay, Shape, Triangle};

pub mod build;
mod sah;
pub mod traverse;

/// The most levels a tree may have, root included; also the size of the traversal
/// stack, which never holds more entries than the tree is deep.
pub const MAX_DEPTH: usize = 64;

/// What a node holds besides its box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NodeKind {
    /// Primitives `primitives[first..first + count]` of the [`Bvh`].
    Leaf { first: usize, count: usize },
    /// Two children, side by side: nodes `left` and `left + 1`.
    Interior { left: usize },
}

// ANCHOR: node
/// One node of the flattened tree, 32 bytes: a box and two counts. A leaf has
/// `count > 0` primitives from `first` on; an interior node has `count == 0` and its
/// children at `first` and `first + 1`, so one cache line holds both their boxes.
///
/// Stored as two 4-wide vectors, (min, first) and (max, count), the counts' bits in
/// the fourth lanes: the traversal loads each corner with one aligned SIMD load
/// (Embree and tinybvh pack their nodes the same way).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Node {
    min_first: Vec4,
    max_count: Vec4,
}
// ANCHOR_END: node

impl Node {
    /// A node with box `min..max`: a leaf of `count > 0` primitives from `first`, or
    /// an interior node (`count == 0`) with children `first` and `first + 1`.
    pub(crate) fn new(min: Vec3, max: Vec3, first: u32, count: u32) -> Node {
        Node {
            min_first: min.extend(f32::from_bits(first)),
            max_count: max.extend(f32::from_bits(count)),
        }
    }

    /// The box's corners as 4-wide vectors (the fourth lane unused).
    #[inline(always)]
    pub(crate) fn corners(&self) -> (Vec3A, Vec3A) {
        (
            Vec3A::from_vec4(self.min_first),
            Vec3A::from_vec4(self.max_count),
        )
    }

    /// The first primitive (a leaf) or the left child (an interior node).
    #[inline(always)]
    pub(crate) fn first(&self) -> u32 {
        self.min_first.w.to_bits()
    }

    /// The number of primitives; 0 for an interior node.
    #[inline(always)]
    pub(crate) fn count(&self) -> u32 {
        self.max_count.w.to_bits()
    }

    /// The box around every primitive below this node.
    pub fn bounds(&self) -> Aabb {
        Aabb::from_checked(self.min_first.truncate(), self.max_count.truncate())
    }

    /// Leaf or interior.
    pub fn kind(&self) -> NodeKind {
        let first = self.first() as usize;
        match self.count() {
            0 => NodeKind::Interior { left: first },
            count => NodeKind::Leaf {
                first,
                count: count as usize,
            },
        }
    }
}

/// The tree's own copy of the bounded shapes, in leaf order: triangles alone when
/// every one is a triangle (a mesh: 36 bytes each instead of a [`Shape`]'s 80, so a
/// leaf's primitives share fewer cache lines, and one test with no `match`), else
/// the shapes.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum LeafShapes {
    Triangles(Vec<Triangle>),
    Shapes(Vec<Shape>),
}

impl LeafShapes {
    /// `shapes` as triangles if every one is (copied once, not as shapes first).
    pub(crate) fn new<'a>(shapes: impl Iterator<Item = &'a Shape> + Clone) -> LeafShapes {
        let triangle = |s: &Shape| match s {
            Shape::Triangle(t) => Some(*t),
            _ => None,
        };
        match shapes.clone().map(triangle).collect::<Option<Vec<_>>>() {
            Some(triangles) => LeafShapes::Triangles(triangles),
            None => LeafShapes::Shapes(shapes.cloned().collect()),
        }
    }

    /// Primitive `p`'s candidate within `range` ([`Shape::candidate`]).
    #[inline(always)]
    pub(crate) fn candidate(
        &self,
        p: usize,
        ray: &PreparedRay,
        range: Interval,
    ) -> Option<Candidate> {
        match self {
            LeafShapes::Triangles(t) => t[p]
                .watertight_prepared(ray, range)
                .map(Candidate::triangle),
            LeafShapes::Shapes(s) => s[p].candidate(ray, range),
        }
    }
}

/// A BVH over a slice of [`Object`]s. It answers with indices into that slice, so it
/// must be used with the slice it was built from.
#[derive(Clone, Debug, PartialEq)]
pub struct Bvh {
    /// The tree, root first. Empty if no object has a box.
    nodes: Vec<Node>,
    /// Object indices, each leaf's contiguous.
    primitives: Vec<usize>,
    /// The shapes of `primitives`, in the same order.
    shapes: LeafShapes,
    /// Objects without a box (planes, quadrics), tested on every ray.
    unbounded: Vec<usize>,
}

impl Bvh {
    /// The nodes, root first (empty if no object has a box).
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// The object indices the leaves refer to.
    pub fn primitives(&self) -> &[usize] {
        &self.primitives
    }

    /// The objects with no box, tested on every ray.
    pub fn unbounded(&self) -> &[usize] {
        &self.unbounded
    }
}

/// A [`Scene`] together with a BVH over its objects: the same questions as the scene
/// ([`BvhScene::closest_hit`], [`BvhScene::occluded`]) with the same answers, faster
/// once the scene is big. The scene itself is unchanged.
#[derive(Clone, Debug, PartialEq)]
pub struct BvhScene {
    scene: Scene,
    bvh: Bvh,
}

impl BvhScene {
    /// Builds the BVH over `scene`'s objects ([`Bvh::build`]).
    pub fn new(scene: Scene) -> BvhScene {
        let bvh = Bvh::build(scene.objects());
        BvhScene { scene, bvh }
    }

    /// The scene (background, light, objects).
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The tree.
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
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
        self.bvh.closest(self.scene.objects(), ray, range)
    }

    fn closest_object(&self, ray: &Ray, range: Interval) -> Option<usize> {
        self.bvh.closest_object(self.scene.objects(), ray, range)
    }

    fn occluded(&self, ray: &Ray, range: Interval) -> bool {
        self.bvh.occluded(self.scene.objects(), ray, range)
    }
}
