//! The binned surface area heuristic: where a node of the BVH is split.
//!
//! `src/bvh/build.rs` grows the tree top-down; for each node it asks [`sah_split`]
//! which plane between bins divides its primitives most cheaply by the SAH's
//! expected cost (Wald 2007, "On fast construction of SAH-based bounding volume
//! hierarchies"), and this file moves the primitives to their sides.

use glam::Vec3A;

/// The cost of visiting a node, relative to testing one primitive (pbrt-v4's 1/2).
pub const TRAVERSAL_COST: f32 = 0.5;

/// The number of bins per axis (Wald 2007 uses 8 to 32; 12 is pbrt-v4's count).
pub const BINS: usize = 12;

/// A node of more primitives than this is binned on all three axes; a smaller one
/// only along the longest axis of its centroids' box, as Wald (2007) and pbrt-v4 bin
/// every node. Three axes find a cheaper split now and then; on one axis the binning
/// pass does a third of the work. The threshold is measured, not derived: the
/// trade of build time against trace time is in BENCHMARKS.md.
pub const ALL_AXES_ABOVE: usize = 128;

/// A node with more primitives than this is split even when the SAH says a leaf
/// would be cheaper (pbrt-v4's rule), so one bad box cannot make a huge leaf.
pub const MAX_LEAF_SIZE: usize = 8;

/// A box while the tree is built: it starts empty (min = +inf, max = -inf) and
/// grows, with no check and no `Option`, because the build grows millions of them.
///
/// Its corners are 4-wide vectors (one lane unused), so that growing it is two SIMD
/// instructions.
#[derive(Clone, Copy, Debug)]
pub(super) struct Bounds {
    pub(super) min: Vec3A,
    pub(super) max: Vec3A,
}

impl Bounds {
    pub(super) const EMPTY: Bounds = Bounds {
        min: Vec3A::INFINITY,
        max: Vec3A::NEG_INFINITY,
    };

    #[inline(always)]
    pub(super) fn grow(&mut self, other: &Bounds) {
        self.min = self.min.min(other.min);
        self.max = self.max.max(other.max);
    }

    #[inline(always)]
    pub(super) fn grow_point(&mut self, p: Vec3A) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }

    /// 2 (xy + yz + zx) of the extent; 0 for an empty box.
    pub(super) fn area(&self) -> f32 {
        let e = (self.max - self.min).max(Vec3A::ZERO);
        2.0 * (e.x * e.y + e.y * e.z + e.z * e.x)
    }
}

/// A primitive while the tree is built: its box, the box's centre and its object
/// index.
#[derive(Clone, Copy, Debug)]
pub(super) struct Item {
    pub(super) bounds: Bounds,
    pub(super) centroid: Vec3A,
    pub(super) index: u32,
}

/// The box around some items' boxes, and the box around their centroids (the range
/// the bins divide).
#[derive(Clone, Copy, Debug)]
pub(super) struct Boxes {
    pub(super) bounds: Bounds,
    pub(super) centroids: Bounds,
}

impl Boxes {
    pub(super) const EMPTY: Boxes = Boxes {
        bounds: Bounds::EMPTY,
        centroids: Bounds::EMPTY,
    };

    /// Both boxes of `items`, in one pass.
    pub(super) fn of(items: &[Item]) -> Boxes {
        let mut boxes = Boxes::EMPTY;
        for item in items {
            boxes.grow(item);
        }
        boxes
    }

    #[inline(always)]
    pub(super) fn grow(&mut self, item: &Item) {
        self.bounds.grow(&item.bounds);
        self.centroids.grow_point(item.centroid);
    }
}

/// A node's items divided: the left part is `..mid`, the right `mid..`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Split {
    pub(super) mid: usize,
    pub(super) left: Boxes,
    pub(super) right: Boxes,
}

/// The primitives that fall into one bin: how many, and the box around them.
#[derive(Clone, Copy, Debug)]
struct Bin {
    count: u32,
    bounds: Bounds,
}

impl Bin {
    const EMPTY: Bin = Bin {
        count: 0,
        bounds: Bounds::EMPTY,
    };
}

/// Which bin a centroid falls into on each axis: `lo` and `scale` = [`BINS`] /
/// extent map the centroids' range onto 0..BINS; the last edge is clamped into the
/// last bin. (An axis of zero extent gives nonsense here, and is never split.)
#[derive(Clone, Copy, Debug)]
struct Binning {
    lo: Vec3A,
    scale: Vec3A,
}

impl Binning {
    /// Whether a centroid falls into bin `k` or one before it on `axis`: the same
    /// answer as `bins(c)[axis] <= k`, without making the bin an integer. The bin is
    /// the position (c - lo) scale cut down to an integer and clamped to 0..BINS, so
    /// for `k` < BINS - 1 it is at most `k` exactly when the position is below
    /// `k + 1` (or not a number, which the conversion makes bin 0).
    #[inline(always)]
    fn at_most(&self, axis: usize, k: usize) -> impl Fn(&Item) -> bool {
        let (lo, scale, end) = (self.lo[axis], self.scale[axis], (k + 1) as f32);
        move |item| {
            let position = (item.centroid[axis] - lo) * scale;
            position < end || position.is_nan()
        }
    }

    #[inline(always)]
    fn bins(&self, c: Vec3A) -> [usize; 3] {
        let f = ((c - self.lo) * self.scale)
            .clamp(Vec3A::ZERO, Vec3A::splat((BINS - 1) as f32));
        [
            f.x as i32 as usize,
            f.y as i32 as usize,
            f.z as i32 as usize,
        ]
    }
}

// ANCHOR: sah_split
/// The binned SAH split (Wald 2007), on all three axes at once in a node of more
/// than [`ALL_AXES_ABOVE`] primitives, else on the longest.
///
/// One pass drops every item into the bin of its centroid on each axis; then, per
/// axis, one sweep from the right and one from the left give, for each of the
/// [`BINS`] - 1 planes between bins, the count and box on each side, and the plane's
/// cost C_trav + (A(L) N(L) + A(R) N(R)) / A(node). The cheapest plane wins unless a
/// leaf, costing N(node), is cheaper and the node is small enough
/// ([`MAX_LEAF_SIZE`]). Axes on which all centroids coincide are skipped; if all
/// three are, the node is a leaf (every split would put everything on one side).
pub(super) fn sah_split(items: &mut [Item], boxes: &Boxes) -> Option<Split> {
    let extent = boxes.centroids.max - boxes.centroids.min;
    let binning = Binning {
        lo: boxes.centroids.min,
        scale: Vec3A::splat(BINS as f32) / extent,
    };
    let axes = if items.len() > ALL_AXES_ABOVE {
        0..3
    } else {
        let longest = extent.max_position();
        longest..longest + 1
    };
    let mut bins = [[Bin::EMPTY; BINS]; 3];
    for item in items.iter() {
        let b = binning.bins(item.centroid);
        for axis in axes.clone() {
            let bin = &mut bins[axis][b[axis]];
            bin.count += 1;
            bin.bounds.grow(&item.bounds);
        }
    }
    let mut best: Option<(f32, usize, usize)> = None; // (cost, axis, last left bin)
    for axis in axes.filter(|&axis| extent[axis] > 0.0) {
        if let Some((cost, k)) = cheapest_plane(&bins[axis], boxes.bounds.area())
            && best.is_none_or(|(c, ..)| cost < c)
        {
            best = Some((cost, axis, k));
        }
    }
    let (cost, axis, k) = best?;
    if cost >= items.len() as f32 && items.len() <= MAX_LEAF_SIZE {
        return None;
    }
    Some(partition(items, binning.at_most(axis, k)))
}

/// The cheapest plane between bins whose two sides are both non-empty, as (cost,
/// last bin on the left), for a node of surface area `area > 0`.
fn cheapest_plane(bins: &[Bin; BINS], area: f32) -> Option<(f32, usize)> {
    // right[k]: count and area of bins k + 1.. (the right side of plane k).
    // An empty bin k + 1 leaves the right side as it was; an empty bin k makes plane
    // k cost what plane k - 1 did, and the earlier plane wins a tie: neither area is
    // computed again (in a small node most bins are empty).
    let mut right = [(0u32, 0.0f32); BINS];
    let mut acc = Bin::EMPTY;
    let mut area_right = 0.0;
    for k in (0..BINS - 1).rev() {
        if bins[k + 1].count > 0 {
            acc.count += bins[k + 1].count;
            acc.bounds.grow(&bins[k + 1].bounds);
            area_right = acc.bounds.area();
        }
        right[k] = (acc.count, area_right);
    }
    let mut left = Bin::EMPTY;
    let mut best: Option<(f32, usize)> = None;
    for k in 0..BINS - 1 {
        if bins[k].count == 0 {
            continue; // the same split as plane k - 1, or none
        }
        left.count += bins[k].count;
        left.bounds.grow(&bins[k].bounds);
        let (right_count, right_area) = right[k];
        if right_count == 0 {
            break; // the right side is empty from here on: no more splits
        }
        let cost = split_cost(
            area,
            (left.bounds.area(), left.count),
            (right_area, right_count),
        );
        if best.is_none_or(|(c, _)| cost < c) {
            best = Some((cost, k));
        }
    }
    best
}

// ANCHOR: split_cost
/// The surface area heuristic's cost of splitting a node of surface area `area` into
/// two children, each given as (surface area, primitive count), in primitive tests:
/// C_trav + (A(L) N(L) + A(R) N(R)) / A(node). A ray that hits the node hits a child
/// with probability about A(child) / A(node) (MacDonald and Booth 1990).
pub fn split_cost(area: f32, left: (f32, u32), right: (f32, u32)) -> f32 {
    let weighted = left.0 * left.1 as f32 + right.0 * right.1 as f32;
    TRAVERSAL_COST + weighted / area
}
// ANCHOR_END: split_cost
// ANCHOR_END: sah_split

/// Moves the items for which `goes_left` holds to the front, keeping none of the
/// orders, and measures both parts' boxes on the way.
fn partition(items: &mut [Item], goes_left: impl Fn(&Item) -> bool) -> Split {
    let (mut mid, mut left, mut right) = (0, Boxes::EMPTY, Boxes::EMPTY);
    for i in 0..items.len() {
        if goes_left(&items[i]) {
            left.grow(&items[i]);
            items.swap(i, mid);
            mid += 1;
        } else {
            right.grow(&items[i]);
        }
    }
    Split { mid, left, right }
}
