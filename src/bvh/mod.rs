//! The bounding volume hierarchy: a tree of boxes over primitives, so that a ray
//! tests the few primitives whose boxes it passes through instead of every one.
//!
//! A bounding volume hierarchy (BVH) is a binary tree of boxes (lesson 11, where a
//! measured chart shows when it pays). The tree knows its primitives by their boxes
//! and their indices only ([`Bounded`]); what a primitive is, and how a ray is tested
//! against it, belongs to whoever built the tree: a scene's objects
//! ([`crate::scene::BvhScene`]) or a mesh's triangles
//! (`shapes::TriangleMesh`). Both search it with the one walk and the one
//! closest-hit rule here ([`Bvh::closest`]).
//!
//! - [`build`]: binned surface area heuristic (MacDonald and Booth 1990; binning after
//!   Wald 2007), into a flat array of 64-byte interior nodes, each holding its two
//!   children's boxes.
//! - [`wide`]: the binary tree collapsed into nodes of up to four children (each
//!   binary node with its children's children), and the walk over them: an
//!   iterative walk with a small fixed stack; at each node the four children's boxes
//!   are tested at once, the nearest hit child is visited first, with the
//!   conservative slab test of Ize 2013 (STABILITY S6) and the ray's 1/d computed
//!   once ([`BoxRay`]).
//! - [`traverse`]: what the walk is for: the nearest crossing (with the same
//!   answer as a plain list, ties included) and whether there is any.
//!
//! Primitives without a box (planes, quadrics) are kept in a plain list and tested
//! on every ray, before the tree.

use glam::{Vec3, Vec3A, Vec4};

pub mod build;
mod sah;
mod slab;
pub mod traverse;
pub mod wide;

pub use slab::BoxRay;
pub use traverse::{Crossing, Nearest, TIE_MARGIN};

/// What the tree needs to know of a primitive: the corners (min, max) of its box, or
/// `None` for a primitive without one, which is tested on every ray.
pub trait Bounded {
    /// The box's (min, max) corners.
    fn corners(&self) -> Option<(Vec3, Vec3)>;
}

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
/// An interior node of the flattened binary tree the build makes, 64 bytes (one
/// cache line): its two children's boxes and what each child is. A node keeps its
/// children's boxes, not its own (the layout of Aila and Laine 2009,
/// "Understanding the Efficiency of Ray Traversal on GPUs"), as the 4-wide nodes
/// that the walk visits do ([`WideNode`], made from these by `wide::collapse`): a
/// node's test needs no other node, and knows whether a child is a leaf.
///
/// The boxes are stored axis by axis, each axis a 4-wide vector of four plane
/// positions: (min of child 0, min of child 1, max of child 0, max of child 1).
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

    /// Child `i` (0 or 1): its box's (min, max) corners, and whether it is a leaf
    /// or a node.
    pub fn child(&self, i: usize) -> ((Vec3, Vec3), Child) {
        let (min, max) = self.corners(i);
        let (first, count) = self.packed(i);
        ((min.into(), max.into()), Child::unpacked(first, count))
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

/// The most children of a 4-wide node.
pub const WIDTH: usize = 4;

// ANCHOR: wide_node
/// A node of the 4-wide tree, 128 bytes (two cache lines): the boxes of its
/// children, structure of arrays, and what each child is, packed as a [`Node`]
/// packs its two (`Child::packed`).
///
/// `planes` holds, axis by axis, the four children's min planes and then their
/// max planes: x min, x max, y min, y max, z min, z max, each a 4-wide vector. A
/// lane with no child holds the box turned inside out (every min +inf, every max
/// -inf), which every ray misses (see `four_entries` in `src/bvh/slab.rs`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct WideNode {
    planes: [Vec4; 6],
    /// Per child: its first primitive (a leaf) or its node's index (interior).
    first: [u32; WIDTH],
    /// Per child: its number of primitives; 0 for an interior node (or no child).
    count: [u32; WIDTH],
}
// ANCHOR_END: wide_node

impl WideNode {
    /// A node whose children are `children`, each with its box's (min, max)
    /// corners; at most [`WIDTH`] of them.
    pub(crate) fn new(children: &[((Vec3, Vec3), Child)]) -> WideNode {
        debug_assert!(children.len() <= WIDTH);
        let (min, max) = (Vec4::INFINITY, Vec4::NEG_INFINITY); // inside out
        let mut node = WideNode {
            planes: [min, max, min, max, min, max],
            first: [0; WIDTH],
            count: [0; WIDTH],
        };
        for (lane, &((min, max), child)) in children.iter().enumerate() {
            for axis in 0..3 {
                node.planes[2 * axis][lane] = min[axis];
                node.planes[2 * axis + 1][lane] = max[axis];
            }
            (node.first[lane], node.count[lane]) = child.packed();
        }
        node
    }

    /// The min planes (`max` false) or the max planes (`max` true) of the four
    /// children along `axis`.
    #[inline(always)]
    pub(crate) fn planes(&self, axis: usize, max: bool) -> Vec4 {
        self.planes[2 * axis + usize::from(max)]
    }

    /// Child `lane`'s box corners as 4-wide vectors (the fourth lane 0); the box
    /// turned inside out for a lane with no child.
    pub(crate) fn corners(&self, lane: usize) -> (Vec3A, Vec3A) {
        let corner = |max: bool| {
            Vec3A::new(
                self.planes(0, max)[lane],
                self.planes(1, max)[lane],
                self.planes(2, max)[lane],
            )
        };
        (corner(false), corner(true))
    }

    /// Child `lane` packed as (first, count), as the walk carries it.
    #[inline(always)]
    pub(crate) fn packed(&self, lane: usize) -> (u32, u32) {
        (self.first[lane], self.count[lane])
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

/// A BVH over a slice of primitives ([`Bvh::build`]). It answers with indices into
/// that slice, so it must be used with the slice it was built from.
#[derive(Clone, Debug, PartialEq)]
pub struct Bvh {
    /// The root's box and what it is; `None` if no primitive has a box.
    root: Option<Root>,
    /// The interior nodes, the root first if it is one. Empty if the root is a leaf.
    nodes: Vec<Node>,
    /// The same tree with four children a node ([`wide::collapse`]), the root
    /// first; what [`Bvh::closest`] walks.
    wide: Vec<WideNode>,
    /// Primitive indices, each leaf's contiguous.
    primitives: Vec<usize>,
    /// Primitives without a box (planes, quadrics), tested on every ray.
    unbounded: Vec<usize>,
}

impl Bvh {
    /// The root's box, as its (min, max) corners, and what it is (a leaf, or node 0);
    /// `None` if no primitive has a box.
    pub fn root(&self) -> Option<((Vec3, Vec3), Child)> {
        let r = self.root?;
        let corners = (r.min.into(), r.max.into());
        Some((corners, Child::unpacked(r.first, r.count)))
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

    /// The primitive indices the leaves refer to, each leaf's contiguous: a leaf
    /// `Child::Leaf { first, count }` holds `primitives()[first..first + count]`.
    pub fn primitives(&self) -> &[usize] {
        &self.primitives
    }

    /// The primitives with no box, tested on every ray.
    pub fn unbounded(&self) -> &[usize] {
        &self.unbounded
    }
}
