//! The 4-wide tree that rays walk: the binary tree collapsed after the
//! build, so that a node holds the boxes of up to four children and a ray tests
//! them with one set of SIMD operations (the collapse of Wald, Benthin and Boulos
//! 2008, "Getting Rid of Packets", and of Embree's wide BVHs).
//!
//! A 4-wide node's children are its binary node's grandchildren, or a child itself
//! where that child is a leaf: two, three or four children. The leaves, and the
//! primitives' order, are the binary tree's. The node is [`WideNode`] (in
//! `src/bvh/mod.rs`, beside the binary [`Node`]), its box test `four_entries` (in
//! `src/bvh/slab.rs`); here are the collapse and the walk.

use std::ops::Range;

use arrayvec::ArrayVec;
use glam::{Vec3, Vec4};

use crate::bvh::slab::{BoxRay, four_entries, four_entries_careful};
use crate::bvh::traverse::Walk;
use crate::bvh::{Bvh, Child, MAX_DEPTH, Node, WIDTH, WideNode};
use crate::ray::Interval;

// ANCHOR: collapse
/// The 4-wide tree of the binary tree whose interior nodes are `nodes`, the root
/// `nodes[0]`: its nodes, the root first (empty if `nodes` is).
pub(crate) fn collapse(nodes: &[Node]) -> Vec<WideNode> {
    let mut wide = Vec::with_capacity(nodes.len() / 2 + 1);
    if !nodes.is_empty() {
        collapse_from(nodes, 0, &mut wide);
    }
    wide
}

/// Adds the 4-wide node made of binary node `index` to `wide`, then the subtrees
/// of its interior children (a parent before its children, the first child's
/// subtree right after its parent), and returns its index in `wide`.
fn collapse_from(nodes: &[Node], index: usize, wide: &mut Vec<WideNode>) -> usize {
    let here = wide.len();
    wide.push(WideNode::new(&[]));
    let node = &nodes[index];
    let mut children = ArrayVec::<((Vec3, Vec3), Child), WIDTH>::new();
    for i in 0..2 {
        match node.child(i) {
            (_, Child::Node(n)) => children.extend([0, 1].map(|j| nodes[n].child(j))),
            leaf => children.push(leaf),
        }
    }
    for (_, child) in &mut children {
        if let Child::Node(n) = *child {
            *child = Child::Node(collapse_from(nodes, n, wide));
        }
    }
    wide[here] = WideNode::new(&children);
    here
}
// ANCHOR_END: collapse

/// The most entries the 4-wide walk's stack holds: a 4-wide node stands for two
/// levels of the binary tree, so a path from the root passes at most
/// [`MAX_DEPTH`] / 2 of them, each pushing at most three children.
const STACK: usize = (WIDTH - 1) * MAX_DEPTH / 2;

impl Bvh {
    // ANCHOR: walk
    /// Visits, nearest child first, every leaf whose box the ray passes through
    /// within `range`, handing the range of its primitives to `leaf`, which answers
    /// with the far end to use from then on, or [`Walk::Stop`].
    ///
    /// The root's own box is not tested: the callers test it before (`Bvh::any`, and
    /// the scene through `Bvh::misses_everything`), and a box test only ever spares
    /// work: without it the root node's four boxes are tested all the same (or a leaf
    /// root's primitives).
    pub(super) fn walk(
        &self,
        box_ray: &BoxRay,
        range: Interval,
        leaf: impl FnMut(Range<usize>) -> Walk,
    ) {
        let Some(root) = &self.root else {
            return;
        };
        let root = (root.first, root.count);
        if box_ray.finite() {
            self.walk_from(root, box_ray, range, leaf, four_entries);
        } else {
            self.walk_from(root, box_ray, range, leaf, four_entries_careful);
        }
    }

    /// The walk from the child `(first, count)` (a leaf if `count > 0`, else wide
    /// node `first`), its box already known to be hit, with `entries` as the node
    /// test. Of the children a node's test hits, the nearest is visited next and
    /// the others pushed farthest first, each with its entry distance; a pushed
    /// child whose entry now lies beyond `t_max` is dropped when popped.
    ///
    /// The cases of one or two children hit, which are most nodes, each name their
    /// lanes. The processor guesses which case it is (branch prediction), usually
    /// rightly, since neighbouring rays take the same turns, and loads the next node
    /// while the box test is still being worked out. Computing the nearest lane from
    /// the bitmask as a number makes each node's load wait for its parent's test,
    /// and the same walk slower (BENCHMARKS.md, "Against Embree").
    #[inline(always)]
    fn walk_from(
        &self,
        (mut first, mut count): (u32, u32),
        box_ray: &BoxRay,
        mut range: Interval,
        mut leaf: impl FnMut(Range<usize>) -> Walk,
        entries: impl Fn(&WideNode, &BoxRay, Interval) -> (Vec4, u32),
    ) {
        let mut stack = ArrayVec::<(u32, u32, f32), STACK>::new();
        loop {
            if count > 0 {
                let first = first as usize;
                match leaf(first..first + count as usize) {
                    Walk::Continue { t_max: t } => range.max = t,
                    Walk::Stop => return,
                }
            } else {
                let node = &self.wide[first as usize];
                let (t, hit) = entries(node, box_ray, range);
                let mut push = |lane: usize, t: f32| {
                    let (f, c) = node.packed(lane);
                    stack.push((f, c, t));
                };
                if hit != 0 {
                    // One case for each one or two children hit, naming them.
                    let lane = match hit {
                        0b0001 => 0,
                        0b0010 => 1,
                        0b0100 => 2,
                        0b1000 => 3,
                        0b0011 => nearer_of(0, 1, &t, &mut push),
                        0b0101 => nearer_of(0, 2, &t, &mut push),
                        0b1001 => nearer_of(0, 3, &t, &mut push),
                        0b0110 => nearer_of(1, 2, &t, &mut push),
                        0b1010 => nearer_of(1, 3, &t, &mut push),
                        0b1100 => nearer_of(2, 3, &t, &mut push),
                        _ => nearest_pushing_others(t.to_array(), hit, &mut push),
                    };
                    (first, count) = node.packed(lane);
                    continue;
                }
            }
            (first, count) = loop {
                let Some((f, c, t_entry)) = stack.pop() else {
                    return;
                };
                if t_entry <= range.max {
                    break (f, c);
                }
            };
        }
    }
    // ANCHOR_END: walk
}

/// Of lanes `a` and `b`, both hit, with entries `t`: hands the farther to `push`
/// and returns the nearer (lane `a` on a tie).
#[inline(always)]
fn nearer_of(a: usize, b: usize, t: &Vec4, mut push: impl FnMut(usize, f32)) -> usize {
    if t[a] <= t[b] {
        push(b, t[b]);
        a
    } else {
        push(a, t[a]);
        b
    }
}

/// Of the lanes in the bitmask `hit` (three or four), with entries `t`: hands all
/// but the nearest to `push`, farthest first, and returns the nearest.
#[inline(always)]
fn nearest_pushing_others(
    t: [f32; WIDTH],
    hit: u32,
    mut push: impl FnMut(usize, f32),
) -> usize {
    let a = hit.trailing_zeros() as usize & 3;
    let rest = hit & (hit - 1);
    let b = rest.trailing_zeros() as usize & 3;
    // By insertion, farthest first.
    let mut order = [(t[a], a), (t[b], b), (f32::NEG_INFINITY, 0), (0.0, 0)];
    if t[a] < t[b] {
        order.swap(0, 1);
    }
    let mut n = 2;
    let mut rest = rest & (rest - 1);
    while rest != 0 {
        let lane = rest.trailing_zeros() as usize & 3;
        rest &= rest - 1;
        let mut j = n;
        while j > 0 && order[j - 1].0 < t[lane] {
            order[j] = order[j - 1];
            j -= 1;
        }
        order[j] = (t[lane], lane);
        n += 1;
    }
    for &(t, lane) in &order[..n - 1] {
        push(lane, t);
    }
    order[n - 1].1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::Bvh;
    use crate::rng::Rng;

    /// A primitive that is just a box.
    struct Boxed(Vec3, Vec3);

    impl crate::bvh::Bounded for Boxed {
        fn corners(&self) -> Option<(Vec3, Vec3)> {
            Some((self.0, self.1))
        }
    }

    /// Every leaf of a tree with its box, by walking `child` from the root.
    fn leaves(
        root: ((Vec3, Vec3), Child),
        child: &dyn Fn(usize) -> Vec<((Vec3, Vec3), Child)>,
    ) -> Vec<([u32; 6], usize, usize)> {
        let mut found = Vec::new();
        let mut todo = vec![root];
        while let Some(((min, max), c)) = todo.pop() {
            match c {
                Child::Leaf { first, count } => {
                    let bits =
                        [min.x, min.y, min.z, max.x, max.y, max.z].map(f32::to_bits);
                    found.push((bits, first, count));
                }
                Child::Node(n) => todo.extend(child(n)),
            }
        }
        found.sort();
        found
    }

    /// The collapse keeps the binary tree's leaves, each with its box bit for bit,
    /// and makes nodes of two to four children, about half as many as the binary
    /// tree's.
    #[test]
    fn the_wide_tree_has_the_binary_trees_leaves() {
        let mut rng = Rng::new(0x33, 4);
        let mut next = || rng.next_f32() * 10.0;
        let boxes: Vec<Boxed> = (0..3000)
            .map(|_| {
                let a = Vec3::new(next(), next(), next());
                Boxed(a, a + Vec3::new(next(), next(), next()) / 20.0)
            })
            .collect();
        let bvh = Bvh::build(&boxes);
        let root = bvh.root().unwrap();
        let binary =
            leaves(root, &|n| [0, 1].map(|i| bvh.nodes()[n].child(i)).to_vec());
        let wide = collapse(bvh.nodes());
        let wide_child = |n: usize| {
            let node: &WideNode = &wide[n];
            (0..WIDTH)
                .filter(|&lane| node.packed(lane) != (0, 0))
                .map(|lane| {
                    let (min, max) = node.corners(lane);
                    let (first, count) = node.packed(lane);
                    let child = match count {
                        0 => Child::Node(first as usize),
                        count => Child::Leaf {
                            first: first as usize,
                            count: count as usize,
                        },
                    };
                    ((min.into(), max.into()), child)
                })
                .collect()
        };
        assert!(binary.len() > 1000, "{}", binary.len());
        assert_eq!(leaves(root, &wide_child), binary);
        let children: usize = (0..wide.len()).map(|n| wide_child(n).len()).sum();
        // Every wide node but the root is someone's child.
        assert_eq!(children, wide.len() - 1 + binary.len());
        assert!(
            (bvh.nodes().len() / 3..bvh.nodes().len() * 2 / 3).contains(&wide.len()),
            "{} wide nodes for {} binary ones",
            wide.len(),
            bvh.nodes().len()
        );
    }
}
