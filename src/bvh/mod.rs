//! The bounding volume hierarchy: a scene's questions answered through a tree of boxes.
//!
//! A bounding volume hierarchy (BVH): a binary tree of boxes over a scene's
//! primitives, so that a ray tests the few primitives whose boxes it passes through
//! instead of every one (lesson 11, where a measured chart shows when it pays).
//!
//! - [`build`]: binned surface area heuristic (MacDonald and Booth 1990; binning after
//!   Wald 2007), into a flat array of 64-byte interior nodes, each holding its two
//!   children's boxes.
//! - [`traverse`]: an iterative walk with a small fixed stack; at each interior node
//!   both children's boxes are tested and the nearer one visited first, with the
//!   conservative slab test of Ize 2013 on the node boxes (STABILITY S6) and the
//!   ray's 1/d computed once ([`crate::shapes::PreparedRay`]).
//!
//! - [`list_or_tree`]: the choice between a scene's plain list and the tree, by the
//!   instructions each would cost a render, measured.
//!
//! Planes and quadrics have no box; they are kept in a plain list and tested on
//! every ray, before the tree. The tree keeps its own copy of the bounded shapes in
//! leaf order, so that a leaf's primitives sit next to each other in memory.

use glam::{Vec3, Vec3A, Vec4};

use crate::ray::{Interval, Ray};
use crate::scene::{Intersect, Scene, SceneHit};
use crate::shapes::{Aabb, Candidate, PreparedRay, Shape, Triangle};

pub mod build;
pub mod list_or_tree;
mod sah;
mod slab;
pub mod traverse;

pub use list_or_tree::{BUILD_COST, ListOrTree, TEST_COST, WALK_COST};

/// The most levels a tree may have, root included; also the size of the traversal
/// stack, which never holds more entries than the tree is deep.
pub const MAX_DEPTH: usize = 64;

/// What a child of a node is (or the root): a leaf of `count` primitives,
/// `primitives[first..first + count]` of the [`Bvh`], or the interior node
/// `nodes()[index]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Child {
    /// Primitives `primitives[first..first + count]`, `count > 0`.
    Leaf {
        /// The leaf's first primitive.
        first: usize,
        /// How many primitives it holds.
        count: usize,
    },
    /// The interior node `nodes()[index]`.
    Node(usize),
}

// ANCHOR: node
/// An interior node of the flattened tree, 64 bytes (one cache line): its two
/// children's boxes and what each child is. A node keeps its children's boxes, not
/// its own (the layout of Aila and Laine 2009, "Understanding the Efficiency of Ray
/// Traversal on GPUs"): the walk tests both boxes from the one node it has loaded,
/// and knows whether a child it enters is a leaf without loading anything else.
///
/// The boxes are stored axis by axis, each axis a 4-wide vector of four plane
/// positions: (min of child 0, min of child 1, max of child 0, max of child 1). The
/// slab test of both children is then a few SIMD operations per axis.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct Node {
    x: Vec4,
    y: Vec4,
    z: Vec4,
    /// Per child: its first primitive (a leaf) or its node's index (interior).
    first: [u32; 2],
    /// Per child: its number of primitives; 0 for an interior node.
    count: [u32; 2],
}
// ANCHOR_END: node

impl Node {
    /// A node whose children have boxes `bounds[i]` (min, max) and are
    /// `children[i]`. Counts and indices fit in u32: the build takes at most
    /// u32::MAX objects into the tree.
    pub(crate) fn new(bounds: [(Vec3, Vec3); 2], children: [Child; 2]) -> Node {
        let [(min0, max0), (min1, max1)] = bounds;
        let planes = |a: usize| Vec4::new(min0[a], min1[a], max0[a], max1[a]);
        let [(f0, c0), (f1, c1)] = children.map(Child::packed);
        Node {
            x: planes(0),
            y: planes(1),
            z: planes(2),
            first: [f0, f1],
            count: [c0, c1],
        }
    }

    /// The planes of both children's boxes along x, y and z, each as (min of child
    /// 0, min of child 1, max of child 0, max of child 1).
    #[inline(always)]
    pub(crate) fn planes(&self) -> [Vec4; 3] {
        [self.x, self.y, self.z]
    }

    /// Child `i`'s (0 or 1) box corners as 4-wide vectors (the fourth lane 0).
    pub(crate) fn corners(&self, i: usize) -> (Vec3A, Vec3A) {
        let [x, y, z] = self.planes();
        (
            Vec3A::new(x[i], y[i], z[i]),
            Vec3A::new(x[2 + i], y[2 + i], z[2 + i]),
        )
    }

    /// Child `i` packed as (first, count) ([`Child::packed`]), as the walk carries
    /// it.
    #[inline(always)]
    pub(crate) fn packed(&self, i: usize) -> (u32, u32) {
        (self.first[i], self.count[i])
    }

    /// Child `i` (0 or 1): its box, and whether it is a leaf or a node.
    pub fn child(&self, i: usize) -> (Aabb, Child) {
        let (min, max) = self.corners(i);
        let (first, count) = self.packed(i);
        (
            Aabb::from_checked(min.into(), max.into()),
            Child::unpacked(first, count),
        )
    }
}

impl Child {
    /// The child as a [`Node`] stores it, (first, count): (first primitive, count)
    /// for a leaf, (node index, 0) for an interior node.
    pub(crate) fn packed(self) -> (u32, u32) {
        match self {
            Child::Leaf { first, count } => (first as u32, count as u32),
            Child::Node(index) => (index as u32, 0),
        }
    }

    /// The child that [`Child::packed`] gave as (first, count).
    fn unpacked(first: u32, count: u32) -> Child {
        match count {
            0 => Child::Node(first as usize),
            count => Child::Leaf {
                first: first as usize,
                count: count as usize,
            },
        }
    }
}

/// The root of a tree: the box around every bounded object, and what the root is
/// (as a [`Node`] stores a child).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Root {
    pub(crate) min: Vec3A,
    pub(crate) max: Vec3A,
    pub(crate) first: u32,
    pub(crate) count: u32,
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
    /// `shapes` as triangles if every one is (copied once, not as shapes first, into
    /// a vector made at its full size).
    pub(crate) fn new<'a>(
        shapes: impl ExactSizeIterator<Item = &'a Shape> + Clone,
    ) -> LeafShapes {
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
    pub(crate) fn candidate(
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

/// A BVH over a slice of [`Object`](crate::scene::Object)s. It answers with indices
/// into that slice, so it must be used with the slice it was built from.
#[derive(Clone, Debug, PartialEq)]
pub struct Bvh {
    /// The root's box and what it is; `None` if no object has a box.
    root: Option<Root>,
    /// The interior nodes, the root first if it is one. Empty if the root is a leaf.
    nodes: Vec<Node>,
    /// Object indices, each leaf's contiguous.
    primitives: Vec<usize>,
    /// The shapes of `primitives`, in the same order.
    shapes: LeafShapes,
    /// Objects without a box (planes, quadrics), tested on every ray.
    unbounded: Vec<usize>,
}

impl Bvh {
    /// The root's box and what it is (a leaf, or node 0); `None` if no object has a
    /// box.
    pub fn root(&self) -> Option<(Aabb, Child)> {
        let r = self.root?;
        let bounds = Aabb::from_checked(r.min.into(), r.max.into());
        Some((bounds, Child::unpacked(r.first, r.count)))
    }

    /// The interior nodes, the root first if it is one (empty if the root is a leaf
    /// or there is no tree).
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// How many nodes the tree has, leaves included: each interior node has two
    /// children, so one more leaf than interior nodes.
    pub fn node_count(&self) -> usize {
        match self.root {
            None => 0,
            Some(_) => 2 * self.nodes.len() + 1,
        }
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
/// ([`Intersect::closest`], [`Intersect::occluded`]) with the same answers, faster
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
