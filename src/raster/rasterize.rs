//! Primitive rasterization (Lecture 2, "Rasterization Pipeline: Primitive
//! rasterization"): which pixels a triangle covers, and the attributes at each.
//!
//! Coverage uses edge functions (Pineda 1988) evaluated at pixel centres, on vertex
//! positions snapped to a grid of 1/256 pixel and held in integers, so the test is
//! exact: two triangles sharing an edge get edge values of exactly opposite sign,
//! and the top-left rule settles the pixels whose centre lies on the edge.

use std::ops::Range;

use glam::{Vec2, Vec4};

use super::projection::CameraTransforms;
use super::vertex::{ClipVertex, Varyings};

/// Bits of sub-pixel precision: vertices snap to 1/256 of a pixel.
pub const SUBPIXEL_BITS: u32 = 8;
const SUBPIXELS: i64 = 1 << SUBPIXEL_BITS;
/// The largest pixel coordinate accepted (2^21): keeps every edge-function product
/// below 2^61, safe in i64. Clipping to the guard band keeps vertices well inside.
const MAX_COORDINATE: f32 = (1 << 21) as f32;

/// Which triangles to skip.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Cull {
    /// Draw both sides (the default: a mesh need not be closed).
    #[default]
    None,
    /// Skip triangles whose vertices appear clockwise on screen, i.e. seen from
    /// behind, given the counter-clockwise-outside winding of [`crate::mesh::Mesh`].
    Back,
}

/// A vertex after the perspective divide and the viewport.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScreenVertex {
    /// Continuous pixel position (column, row from the top).
    pub pixel: Vec2,
    /// Depth in [0, 1], 0 on the near plane.
    pub depth: f32,
    /// 1/w: needed to interpolate the attributes perspective-correctly.
    pub inv_w: f32,
    /// The attributes.
    pub varyings: Varyings,
}

impl ScreenVertex {
    /// The screen vertex of a clipped vertex, or `None` if w <= 0 (clip first).
    pub fn from_clip(
        transforms: &CameraTransforms,
        v: &ClipVertex,
    ) -> Option<ScreenVertex> {
        let screen = transforms.to_screen(v.clip)?;
        Some(ScreenVertex {
            pixel: screen.truncate(),
            depth: screen.z,
            inv_w: 1.0 / v.clip.w,
            varyings: v.varyings,
        })
    }
}

/// One covered pixel of one triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    /// Column.
    pub x: u32,
    /// Row from the top.
    pub y: u32,
    /// Depth in [0, 1], interpolated linearly in screen space (NDC z is affine there).
    pub depth: f32,
    /// The attributes, interpolated perspective-correctly.
    pub varyings: Varyings,
}

type Fixed = (i64, i64);

// ANCHOR: edge_function
/// The edge function of the directed edge a -> b at p:
/// E(p) = (p_x - a_x)(b_y - a_y) - (p_y - a_y)(b_x - a_x),
/// twice the signed area of the triangle (a, b, p). With rows growing downwards it
/// is positive when a, b, p run counter-clockwise as seen on the image.
fn edge(a: Fixed, b: Fixed, p: Fixed) -> i64 {
    (p.0 - a.0) * (b.1 - a.1) - (p.1 - a.1) * (b.0 - a.0)
}
// ANCHOR_END: edge_function

// ANCHOR: top_left
/// The top-left rule for a triangle with positive area: a pixel centre exactly on an
/// edge belongs to the triangle only if that edge is a top edge (horizontal, the
/// triangle below it: rows grow downwards, so the edge runs towards -x) or a left
/// edge (the triangle to its right: the edge runs towards +y, down the image).
/// The neighbour across the edge runs it the other way, so exactly one owns it.
fn is_top_left(a: Fixed, b: Fixed) -> bool {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    (dy == 0 && dx < 0) || dy > 0
}
// ANCHOR_END: top_left

// ANCHOR: covers
/// Does the triangle a, b, c cover the point p (all on the sub-pixel grid)? The
/// vertices may run either way round: if the area E_ab(c) is negative, two of them
/// are swapped so that the edge functions are positive inside. A triangle of zero
/// area covers nothing. p is covered if it is strictly inside every edge (E > 0), or
/// exactly on an edge (E = 0) that is top-left. Exact for coordinates up to 2^29 in
/// absolute value (every product stays below 2^61).
pub fn covers(a: (i64, i64), b: (i64, i64), c: (i64, i64), p: (i64, i64)) -> bool {
    let area = edge(a, b, c);
    if area == 0 {
        return false;
    }
    let (b, c) = if area < 0 { (c, b) } else { (b, c) };
    [(b, c), (c, a), (a, b)].into_iter().all(|(u, v)| {
        let e = edge(u, v, p);
        e > 0 || (e == 0 && is_top_left(u, v))
    })
}
// ANCHOR_END: covers

/// A pixel position on the sub-pixel grid, or `None` if not finite or too far out.
fn snap(p: Vec2) -> Option<Fixed> {
    if !p.is_finite() || p.abs().max_element() > MAX_COORDINATE {
        return None;
    }
    let s = SUBPIXELS as f32;
    Some(((p.x * s).round() as i64, (p.y * s).round() as i64))
}

/// The pixel columns (or rows) whose centre i + 1/2 lies in [lo, hi] (sub-pixel units).
fn centres_between(lo: i64, hi: i64) -> (i64, i64) {
    let half = SUBPIXELS / 2;
    let first = -(-(lo - half)).div_euclid(SUBPIXELS);
    let last = (hi - half).div_euclid(SUBPIXELS);
    (first, last)
}

// ANCHOR: rasterize_triangle
/// Calls `emit` for every pixel of `rows` (and columns 0 .. `width`) whose centre the
/// triangle covers. Barycentric weights come from the edge functions, b_k = E_k / A;
/// attributes are interpolated perspective-correctly,
/// a = (sum_k b_k a_k / w_k) / (sum_k b_k / w_k),
/// because a/w and 1/w (not a itself) are affine in screen space.
pub fn rasterize_triangle(
    t: &[ScreenVertex; 3],
    cull: Cull,
    width: u32,
    rows: Range<u32>,
    mut emit: impl FnMut(Fragment),
) {
    let [Some(a), Some(b), Some(c)] = t.each_ref().map(|v| snap(v.pixel)) else {
        return;
    };
    let mut p = [a, b, c];
    let mut order = [0, 1, 2];
    let mut area = edge(p[0], p[1], p[2]);
    if area == 0 || (area < 0 && cull == Cull::Back) {
        return;
    }
    if area < 0 {
        // Seen from behind: swap two vertices so the edge functions are positive
        // inside.
        p.swap(1, 2);
        order.swap(1, 2);
        area = -area;
    }
    let v = order.map(|k| t[k]);
    let edges = [(p[1], p[2]), (p[2], p[0]), (p[0], p[1])];
    let xs = centres_between(
        p.iter().map(|q| q.0).min().unwrap_or(0),
        p.iter().map(|q| q.0).max().unwrap_or(0),
    );
    let ys = centres_between(
        p.iter().map(|q| q.1).min().unwrap_or(0),
        p.iter().map(|q| q.1).max().unwrap_or(0),
    );
    let x_range = xs.0.max(0)..=xs.1.min(i64::from(width) - 1);
    let y_range = ys.0.max(i64::from(rows.start))..=ys.1.min(i64::from(rows.end) - 1);
    let inv_w = Vec4::new(v[0].inv_w, v[1].inv_w, v[2].inv_w, 0.0);
    for y in y_range {
        for x in x_range.clone() {
            let centre = (x * SUBPIXELS + SUBPIXELS / 2, y * SUBPIXELS + SUBPIXELS / 2);
            if covers(p[0], p[1], p[2], centre) {
                let e = edges.map(|(a, b)| edge(a, b, centre));
                let b = e.map(|e_k| (e_k as f64 / area as f64) as f32);
                emit(fragment(x as u32, y as u32, &v, b, inv_w));
            }
        }
    }
}
// ANCHOR_END: rasterize_triangle

// ANCHOR: perspective_correct
/// The fragment at pixel (x, y) with screen-space barycentric weights `b`.
fn fragment(
    x: u32,
    y: u32,
    v: &[ScreenVertex; 3],
    b: [f32; 3],
    inv_w: Vec4,
) -> Fragment {
    let depth = b[0] * v[0].depth + b[1] * v[1].depth + b[2] * v[2].depth;
    let weights = perspective_weights(b, [inv_w.x, inv_w.y, inv_w.z]);
    Fragment {
        x,
        y,
        depth,
        varyings: Varyings::weighted(&v.map(|v| v.varyings), weights),
    }
}

// ANCHOR: perspective_weights
/// The weights that interpolate an attribute perspective-correctly, from the screen
/// weights `b` and the vertices' 1/w: b_k (1/w_k) / sum_j b_j (1/w_j), so that
/// sum_k weights_k a_k = (sum_k b_k a_k / w_k) / (sum_k b_k / w_k). The screen
/// weights themselves if that sum is not positive (no vertex in front of the eye).
pub fn perspective_weights(b: [f32; 3], inv_w: [f32; 3]) -> [f32; 3] {
    let over_w = [b[0] * inv_w[0], b[1] * inv_w[1], b[2] * inv_w[2]];
    let sum = over_w[0] + over_w[1] + over_w[2];
    if sum > 0.0 {
        over_w.map(|o| o / sum)
    } else {
        b
    }
}
// ANCHOR_END: perspective_weights
// ANCHOR_END: perspective_correct
