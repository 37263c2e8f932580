//! Clipping in homogeneous clip space (Sutherland and Hodgman 1974): before the
//! divide by w, cut each triangle against the planes of the view volume, so that
//! nothing behind the eye (w <= 0) ever reaches the divide.
//!
//! A point (x, y, z, w) is inside the near plane when z >= -w and inside the far
//! plane when z <= w (NDC depth -1 .. 1, see `pipeline`). The side planes are a guard
//! band |x|, |y| <= [`GUARD_BAND`] w, far outside the image: they only keep pixel
//! coordinates small enough for the rasterizer's exact integer edge functions; the
//! image border itself is handled by the rasterizer's bounding box.

use glam::Vec4;

use super::vertex::ClipVertex;

/// The guard band in NDC units: |x|, |y| <= 64 w. NDC spans 2 units across the image,
/// so that is 32 image widths from the centre, 31.5 beyond each edge. With the largest
/// film (16384 pixels) a clipped vertex's pixel coordinates stay within -63 * 8192 and
/// 65 * 8192 = 532 480, just above 2^19.
pub const GUARD_BAND: f32 = 64.0;

/// The clip planes as signed distances d(p): p is inside when d(p) >= 0.
const PLANES: [fn(Vec4) -> f32; 6] = [
    |p| p.z + p.w,              // near: z >= -w
    |p| p.w - p.z,              // far: z <= w
    |p| GUARD_BAND * p.w + p.x, // x >= -g w
    |p| GUARD_BAND * p.w - p.x, // x <= g w
    |p| GUARD_BAND * p.w + p.y, // y >= -g w
    |p| GUARD_BAND * p.w - p.y, // y <= g w
];

// ANCHOR: clip_triangle
/// The triangle `t` clipped to the view volume and cut into a fan of triangles:
/// none if it lies wholly outside, one if wholly inside, and up to seven after
/// clipping (a triangle crossing only the near plane gives one or two). Every vertex
/// of the result has w > 0. Degenerate or non-finite input gives no triangles.
pub fn clip_triangle(t: &[ClipVertex; 3]) -> Vec<[ClipVertex; 3]> {
    if t.iter().any(|v| !v.clip.is_finite()) {
        return Vec::new();
    }
    // Most triangles lie wholly inside every plane: nothing to cut.
    if t.iter()
        .all(|v| v.clip.w > 0.0 && PLANES.iter().all(|d| d(v.clip) >= 0.0))
    {
        return vec![*t];
    }
    let mut polygon = t.to_vec();
    for plane in PLANES {
        polygon = clip_polygon(&polygon, plane);
        if polygon.len() < 3 {
            return Vec::new();
        }
    }
    if polygon.iter().any(|v| v.clip.w <= 0.0) {
        return Vec::new();
    }
    (1..polygon.len() - 1)
        .map(|i| [polygon[0], polygon[i], polygon[i + 1]])
        .collect()
}
// ANCHOR_END: clip_triangle

// ANCHOR: clip_polygon
/// One Sutherland-Hodgman pass: walk the polygon's edges, keep the vertices inside
/// the plane and add the crossing point of every edge that crosses it.
///
/// The crossing is always computed from the inside vertex towards the outside one,
/// t = d_in / (d_in - d_out), so two triangles sharing an edge compute the very same
/// point and no crack opens between them.
fn clip_polygon(polygon: &[ClipVertex], distance: fn(Vec4) -> f32) -> Vec<ClipVertex> {
    let mut out = Vec::with_capacity(polygon.len() + 1);
    for (i, current) in polygon.iter().enumerate() {
        let next = &polygon[(i + 1) % polygon.len()];
        let (d_cur, d_next) = (distance(current.clip), distance(next.clip));
        if d_cur >= 0.0 {
            out.push(*current);
        }
        if (d_cur >= 0.0) != (d_next >= 0.0) {
            let (inside, outside, d_in, d_out) = if d_cur >= 0.0 {
                (current, next, d_cur, d_next)
            } else {
                (next, current, d_next, d_cur)
            };
            out.push(inside.lerp(outside, d_in / (d_in - d_out)));
        }
    }
    out
}
// ANCHOR_END: clip_polygon
