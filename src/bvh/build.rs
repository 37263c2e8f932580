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
//! equal bins, and only the [`BINS`] - 1 planes between bins are tried.

use glam::Vec3;

use crate::bvh::{Bvh, MAX_DEPTH, Node, NodeKind};
use crate::scene::Object;
use crate::shapes::Aabb;

/// The cost of visiting a node, relative to testing one primitive (pbrt-v4's 1/2).
pub const TRAVERSAL_COST: f32 = 0.5;

/// The number of bins per axis (Wald 2007 uses 8 to 32; 12 is pbrt-v4's count).
pub const BINS: usize = 12;

/// A node with at most this many primitives is always a leaf.
pub const LEAF_SIZE: usize = 2;

/// A node with more primitives than this is split even when the SAH says a leaf
/// would be cheaper (pbrt-v4's rule), so one bad box cannot make a huge leaf.
pub const MAX_LEAF_SIZE: usize = 8;

/// How a node's primitives are divided between its two children.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Strategy {
    /// Binned SAH, the default.
    Sah,
    /// Half the primitives each side, by centroid, along the centroids' longest
    /// axis: the simple baseline the SAH is measured against.
    Median,
}

/// A primitive while the tree is built: its object index, box and box centre.
#[derive(Clone, Copy, Debug)]
struct Item {
    index: usize,
    bounds: Aabb,
    centroid: Vec3,
}

impl Bvh {
    /// A BVH over `objects` by binned SAH. Objects without a box go to the plain
    /// list of unbounded ones.
    pub fn build(objects: &[Object]) -> Bvh {
        Bvh::build_with(objects, Strategy::Sah)
    }

    /// A BVH over `objects`, splitting nodes by `strategy`.
    pub fn build_with(objects: &[Object], strategy: Strategy) -> Bvh {
        let mut items = Vec::new();
        let mut unbounded = Vec::new();
        for (index, object) in objects.iter().enumerate() {
            match object.shape.bounds() {
                Some(bounds) => items.push(Item {
                    index,
                    bounds,
                    centroid: bounds.centre(),
                }),
                None => unbounded.push(index),
            }
        }
        let mut builder = Builder {
            nodes: Vec::new(),
            primitives: Vec::new(),
            strategy,
        };
        if !items.is_empty() {
            builder.subtree(&mut items, 0);
        }
        Bvh {
            nodes: builder.nodes,
            primitives: builder.primitives,
            unbounded,
        }
    }

    /// The tree's SAH cost: the expected cost of a ray through the root box, in
    /// primitive tests. Each interior node adds C_trav A(node) / A(root), each leaf
    /// N(leaf) A(leaf) / A(root). `None` for an empty tree or a root box of no area.
    pub fn sah_cost(&self) -> Option<f32> {
        let root_area = f64::from(self.nodes.first()?.bounds.surface_area());
        if root_area <= 0.0 {
            return None;
        }
        let total: f64 = self
            .nodes
            .iter()
            .map(|node| {
                let weight = match node.kind {
                    NodeKind::Leaf { count, .. } => count as f64,
                    NodeKind::Interior { .. } => f64::from(TRAVERSAL_COST),
                };
                weight * f64::from(node.bounds.surface_area())
            })
            .sum();
        Some((total / root_area) as f32)
    }
}

/// The tree as it grows: nodes in depth-first order, leaf primitives in leaf order.
struct Builder {
    nodes: Vec<Node>,
    primitives: Vec<usize>,
    strategy: Strategy,
}

impl Builder {
    // ANCHOR: build
    /// Appends the subtree over `items` (at `depth` levels below the root) and
    /// returns its root's index.
    ///
    /// Depth first: the node itself, then its whole left subtree, which therefore
    /// starts at the next index, then the right subtree, whose index is stored in
    /// the node once it is known. A node becomes a leaf when it holds at most
    /// [`LEAF_SIZE`] primitives, when the tree is [`MAX_DEPTH`] deep (so the
    /// traversal stack is big enough), or when [`Builder::split`] finds no split
    /// worth making.
    fn subtree(&mut self, items: &mut [Item], depth: usize) -> usize {
        let here = self.nodes.len();
        let bounds = union(items);
        let split = if items.len() > LEAF_SIZE && depth + 1 < MAX_DEPTH {
            self.split(items, &bounds)
        } else {
            None
        };
        let Some((mid, axis)) = split else {
            let first = self.primitives.len();
            self.primitives.extend(items.iter().map(|item| item.index));
            let count = items.len();
            self.nodes.push(Node {
                bounds,
                kind: NodeKind::Leaf { first, count },
            });
            return here;
        };
        let (left, right) = items.split_at_mut(mid);
        self.nodes.push(Node {
            bounds,
            kind: NodeKind::Interior { right: 0, axis }, // right is set below
        });
        self.subtree(left, depth + 1);
        let right = self.subtree(right, depth + 1);
        self.nodes[here].kind = NodeKind::Interior { right, axis };
        here
    }
    // ANCHOR_END: build

    /// Reorders `items` into a left part `..mid` and a right part `mid..`, both
    /// non-empty, and returns `(mid, axis)`; or `None` for a leaf.
    fn split(&self, items: &mut [Item], bounds: &Aabb) -> Option<(usize, usize)> {
        // With no area the SAH has nothing to weigh (0 / 0): fall back to the median.
        if self.strategy == Strategy::Median || bounds.surface_area() <= 0.0 {
            median_split(items)
        } else {
            sah_split(items, bounds)
        }
    }
}

/// The box around every item's box.
fn union(items: &[Item]) -> Aabb {
    let first = items[0].bounds;
    items[1..]
        .iter()
        .fold(first, |acc, item| acc.union(&item.bounds))
}

/// The box around the items' centroids; `None` never happens for a non-empty slice
/// of finite boxes.
fn centroid_bounds(items: &[Item]) -> Option<Aabb> {
    Aabb::around(items.iter().map(|item| item.centroid))
}

/// The primitives that fall into one bin: how many, and the box around them.
#[derive(Clone, Copy, Debug, Default)]
struct Bin {
    count: usize,
    bounds: Option<Aabb>,
}

impl Bin {
    fn add(&mut self, bounds: &Aabb) {
        self.count += 1;
        self.bounds = Some(grow(self.bounds, bounds));
    }
}

/// `acc` grown to hold `b` (or `b` itself if `acc` is empty).
fn grow(acc: Option<Aabb>, b: &Aabb) -> Aabb {
    acc.map_or(*b, |a| a.union(b))
}

/// The bin of a centroid coordinate `c`, with the centroids spanning
/// `lo..=lo + extent`, `extent > 0`. (c - lo) / extent lies in [0, 1] even after
/// rounding, so the index is at most [`BINS`] and clamped to the last bin.
fn bin_index(c: f32, lo: f32, extent: f32) -> usize {
    let b = ((c - lo) / extent * BINS as f32) as usize;
    b.min(BINS - 1)
}

/// The best split found so far: its SAH cost, axis and last bin on the left.
#[derive(Clone, Copy, Debug)]
struct Candidate {
    cost: f32,
    axis: usize,
    last_left_bin: usize,
}

// ANCHOR: sah_split
/// The binned SAH split (Wald 2007), on all three axes.
///
/// Per axis: drop every item into the bin of its centroid, then sweep the bins once
/// from each end to know, for each of the [`BINS`] - 1 planes between bins, the count
/// and box on each side; the plane's cost is
/// C_trav + (A(L) N(L) + A(R) N(R)) / A(node). The cheapest plane wins unless a leaf,
/// costing N(node), is cheaper and the node is small enough ([`MAX_LEAF_SIZE`]).
/// Axes on which all centroids coincide are skipped; if all three are, the node is
/// a leaf (every split would put everything on one side).
fn sah_split(items: &mut [Item], bounds: &Aabb) -> Option<(usize, usize)> {
    let centroids = centroid_bounds(items)?;
    let (lo, extent) = (centroids.min(), centroids.max() - centroids.min());
    let mut best: Option<Candidate> = None;
    for axis in 0..3 {
        if extent[axis] <= 0.0 {
            continue;
        }
        let mut bins = [Bin::default(); BINS];
        for item in items.iter() {
            bins[bin_index(item.centroid[axis], lo[axis], extent[axis])].add(&item.bounds);
        }
        for (last_left_bin, cost) in plane_costs(&bins, bounds.surface_area()) {
            if best.is_none_or(|b| cost < b.cost) {
                best = Some(Candidate {
                    cost,
                    axis,
                    last_left_bin,
                });
            }
        }
    }
    let best = best?;
    let leaf_cost = items.len() as f32;
    if best.cost >= leaf_cost && items.len() <= MAX_LEAF_SIZE {
        return None;
    }
    let (axis, k) = (best.axis, best.last_left_bin);
    let mid = partition(items, |item| {
        bin_index(item.centroid[axis], lo[axis], extent[axis]) <= k
    });
    Some((mid, axis))
}

/// The SAH cost of each plane between bins whose two sides are both non-empty, as
/// (last bin on the left, cost), for a node of surface area `area > 0`.
fn plane_costs(bins: &[Bin; BINS], area: f32) -> Vec<(usize, f32)> {
    // right[k]: count and box of bins k + 1.. (the right side of plane k).
    let mut right = [Bin::default(); BINS];
    let mut acc = Bin::default();
    for k in (0..BINS - 1).rev() {
        acc = merge(acc, bins[k + 1]);
        right[k] = acc;
    }
    let mut left = Bin::default();
    let mut costs = Vec::with_capacity(BINS - 1);
    for k in 0..BINS - 1 {
        left = merge(left, bins[k]);
        let (Some(lb), Some(rb)) = (left.bounds, right[k].bounds) else {
            continue; // one side empty: not a split
        };
        let weighted =
            lb.surface_area() * left.count as f32 + rb.surface_area() * right[k].count as f32;
        costs.push((k, TRAVERSAL_COST + weighted / area));
    }
    costs
}
// ANCHOR_END: sah_split

/// Two bins' contents together.
fn merge(a: Bin, b: Bin) -> Bin {
    let bounds = match (a.bounds, b.bounds) {
        (Some(x), Some(y)) => Some(x.union(&y)),
        (x, None) => x,
        (None, y) => y,
    };
    Bin {
        count: a.count + b.count,
        bounds,
    }
}

/// The object median: the items sorted by centroid along the centroids' longest axis
/// (only as far as needed, by `select_nth_unstable`), split in two halves. `None`
/// (a leaf) if all centroids coincide.
fn median_split(items: &mut [Item]) -> Option<(usize, usize)> {
    let centroids = centroid_bounds(items)?;
    let extent = centroids.max() - centroids.min();
    let axis = extent.max_position();
    if extent[axis] <= 0.0 {
        return None;
    }
    let mid = items.len() / 2;
    items.select_nth_unstable_by(mid, |a, b| a.centroid[axis].total_cmp(&b.centroid[axis]));
    Some((mid, axis))
}

/// Moves the items for which `goes_left` holds to the front, keeping none of the
/// orders, and returns how many there are.
fn partition(items: &mut [Item], goes_left: impl Fn(&Item) -> bool) -> usize {
    let mut mid = 0;
    for i in 0..items.len() {
        if goes_left(&items[i]) {
            items.swap(i, mid);
            mid += 1;
        }
    }
    mid
}
