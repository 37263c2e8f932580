//! Building a BVH top-down with the surface area heuristic (SAH).
//!
//! MacDonald and Booth (1990): a random ray that passes through a box passes through
//! a box inside it with probability area(inner) / area(outer). Splitting a node's
//! primitives into L and R then costs, in expectation,
//!
//! ```text
//! C = C_trav + (A(L) N(L) + A(R) N(R)) / A(node)
//! ```
//!
//! primitive tests (A the surface area of a side's box, N its primitive count,
//! C_trav the cost of visiting a node relative to one primitive test), against
//! N(node) for leaving the node a leaf. Trying every possible split is slow, so the
//! candidates are binned (Wald 2007, "On fast construction of SAH-based bounding
//! volume hierarchies"): the centroids' range on each axis is cut into [`BINS`]
//! equal bins, and only the [`BINS`] - 1 planes between bins are tried. This file
//! grows the tree; the binned split itself is in `src/bvh/sah.rs`.

use glam::Vec3;

pub use super::sah::{ALL_AXES_ABOVE, BINS, MAX_LEAF_SIZE, TRAVERSAL_COST, split_cost};
use super::sah::{Bounds, Boxes, Item, Split, sah_split};
use crate::bvh::{Bounded, Bvh, Child, MAX_DEPTH, Node, Root};

/// A node with at most this many primitives is always a leaf.
pub const LEAF_SIZE: usize = 2;

/// How far each primitive's box is grown on every side, as a share of the largest
/// coordinate of any primitive's box: 2^-16. A primitive's own test rounds (a
/// quad's o + t d before its inside test, a sphere's discriminant), so it can
/// accept a grazing crossing a few ulps outside its exact box, where the slab test,
/// far more exact, would turn the ray away: the list would find that hit and the
/// tree would not. In lesson 10's Cornell box a path's ray from just above the lamp
/// met the lamp's back at its edge, which the lamp's flat box missed by a hair
/// (`tests/course/bvh.rs`). The rounding of those tests stays below about 10^-6 of
/// the coordinates of the ray's origin and hit point; the margin covers rays that
/// start within about ten times the scene's size of the origin. The centroids, and
/// so the binning, do not move.
pub const BOX_MARGIN: f32 = 1.0 / 65536.0;

/// How a node's primitives are divided between its two children.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Strategy {
    /// Binned SAH, the default.
    Sah,
    /// Half the primitives each side, by centroid, along the centroids' longest
    /// axis: the simple baseline the SAH is measured against.
    Median,
}

impl Bvh {
    /// A BVH over `primitives` by binned SAH. Primitives without a box go to the
    /// plain list of unbounded ones.
    pub fn build(primitives: &[impl Bounded]) -> Bvh {
        Bvh::build_with(primitives, Strategy::Sah)
    }

    /// A BVH over `primitives`, splitting nodes by `strategy`.
    pub fn build_with(primitives: &[impl Bounded], strategy: Strategy) -> Bvh {
        let mut items = Vec::with_capacity(primitives.len());
        let mut unbounded = Vec::new();
        for (index, primitive) in primitives.iter().enumerate() {
            match (primitive.corners(), u32::try_from(index)) {
                (Some((min, max)), Ok(index)) => items.push(Item {
                    bounds: Bounds {
                        min: min.into(),
                        max: max.into(),
                    },
                    centroid: (0.5 * (min + max)).into(),
                    index,
                }),
                _ => unbounded.push(index),
            }
        }
        pad_boxes(&mut items);
        let mut builder = Builder {
            nodes: Vec::with_capacity(items.len()),
            strategy,
        };
        let root = (!items.is_empty()).then(|| {
            let boxes = Boxes::of(&items);
            let (first, count) = builder.subtree(&mut items, 0, 0, boxes).packed();
            Root {
                min: boxes.bounds.min,
                max: boxes.bounds.max,
                first,
                count,
            }
        });
        Bvh {
            root,
            wide: super::wide::collapse(&builder.nodes),
            nodes: builder.nodes,
            primitives: items.iter().map(|item| item.index as usize).collect(),
            unbounded,
        }
    }

    /// The tree's SAH cost: the expected cost of a ray through the root box, in
    /// primitive tests. Each interior node adds C_trav A(node) / A(root), each leaf
    /// N(leaf) A(leaf) / A(root). `None` for an empty tree or a root box of no area.
    pub fn sah_cost(&self) -> Option<f32> {
        let (root_box, root) = self.root()?;
        let root_area = f64::from(surface_area(root_box));
        if root_area <= 0.0 {
            return None;
        }
        let weighted = |(bounds, child): ((Vec3, Vec3), Child)| {
            let weight = match child {
                Child::Leaf { count, .. } => count as f64,
                Child::Node(_) => f64::from(TRAVERSAL_COST),
            };
            weight * f64::from(surface_area(bounds))
        };
        let children = self
            .nodes
            .iter()
            .flat_map(|node| [0, 1].map(|i| node.child(i)));
        let total: f64 = std::iter::once((root_box, root))
            .chain(children)
            .map(weighted)
            .sum();
        Some((total / root_area) as f32)
    }
}

/// The area of the surface of the box with corners `min` and `max`, 2 (xy + yz + zx)
/// of its extent, as [`crate::shapes::Aabb::surface_area`] computes it.
fn surface_area((min, max): (Vec3, Vec3)) -> f32 {
    let e = max - min;
    2.0 * (e.x * e.y + e.y * e.z + e.z * e.x)
}

/// The tree as it grows.
struct Builder {
    nodes: Vec<Node>,
    strategy: Strategy,
}

impl Builder {
    // ANCHOR: build
    /// The subtree over `items`, which are `primitives[first..first + items.len()]`
    /// of the finished tree, at `depth` levels below the root: a leaf, or a new
    /// interior node; `boxes` are the items' box and their centroids' box, which the
    /// parent's split measured while it divided its items.
    ///
    /// A split reorders `items` in place, left part first, so a leaf's primitives
    /// are a contiguous run of the final order and nothing is allocated per node.
    /// The node's slot is reserved before its children are built, so that a parent
    /// comes before its children and the left subtree follows its parent; the slot
    /// is filled once both children are known. A subtree is a leaf when it holds at
    /// most [`LEAF_SIZE`] primitives, when the tree is [`MAX_DEPTH`] deep (so the
    /// traversal stack is big enough), or when [`Builder::split`] finds no split
    /// worth making.
    fn subtree(
        &mut self,
        items: &mut [Item],
        first: usize,
        depth: usize,
        boxes: Boxes,
    ) -> Child {
        let split = if items.len() > LEAF_SIZE && depth + 1 < MAX_DEPTH {
            self.split(items, &boxes)
        } else {
            None
        };
        let Some(Split { mid, left, right }) = split else {
            return Child::Leaf {
                first,
                count: items.len(),
            };
        };
        let here = self.nodes.len();
        self.nodes.push(Node::new(
            [(Vec3::ZERO, Vec3::ZERO); 2],
            [Child::Node(0); 2],
        ));
        let (l, r) = items.split_at_mut(mid);
        let children = [
            self.subtree(l, first, depth + 1, left),
            self.subtree(r, first + mid, depth + 1, right),
        ];
        let corners = |b: &Boxes| (Vec3::from(b.bounds.min), Vec3::from(b.bounds.max));
        self.nodes[here] = Node::new([corners(&left), corners(&right)], children);
        Child::Node(here)
    }
    // ANCHOR_END: build

    /// Reorders `items` into a left part `..mid` and a right part `mid..`, both
    /// non-empty, and returns `mid` with the boxes of both parts; or `None` for a leaf.
    fn split(&self, items: &mut [Item], boxes: &Boxes) -> Option<Split> {
        // With no area the SAH has nothing to weigh (0 / 0): fall back to the median.
        let mid = if self.strategy == Strategy::Median || boxes.bounds.area() <= 0.0 {
            median_split(items, &boxes.centroids)?
        } else {
            return sah_split(items, boxes);
        };
        let (left, right) = items.split_at(mid);
        Some(Split {
            mid,
            left: Boxes::of(left),
            right: Boxes::of(right),
        })
    }
}

/// The object median: the items sorted by centroid along the centroids' longest axis
/// (only as far as needed, by `select_nth_unstable`), split in two halves. `None`
/// (a leaf) if all centroids coincide.
fn median_split(items: &mut [Item], centroids: &Bounds) -> Option<usize> {
    let extent = centroids.max - centroids.min;
    let axis = extent.max_position();
    if extent[axis].is_nan() || extent[axis] <= 0.0 {
        return None;
    }
    let mid = items.len() / 2;
    items.select_nth_unstable_by(mid, |a, b| {
        a.centroid[axis].total_cmp(&b.centroid[axis])
    });
    Some(mid)
}

/// Grows every item's box by [`BOX_MARGIN`] of the largest coordinate of any box,
/// the same on every side.
fn pad_boxes(items: &mut [Item]) {
    let largest = items.iter().fold(0.0f32, |m, item| {
        m.max(item.bounds.min.abs().max_element())
            .max(item.bounds.max.abs().max_element())
    });
    let pad = largest * BOX_MARGIN;
    for item in items {
        item.bounds.min -= pad;
        item.bounds.max += pad;
    }
}
