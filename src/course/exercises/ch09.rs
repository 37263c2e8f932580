//! Chapter 09, The rasterization pipeline: coding exercises 9.6 and 9.7.
//!
//! Check them with `cargo test --test exercises ch09`.
// The parameters are unused until you write the bodies.
#![allow(unused_variables)]

use crate::raster::ScreenVertex;

/// Coding exercise 9.6: does the triangle `a`, `b`, `c` cover the point `p` under the
/// top-left rule? All four are on the rasterizer's integer sub-pixel grid, as
/// (column, row) with rows growing downwards; the vertices may run either way round,
/// and the triangle may be degenerate.
///
/// The edge function of the directed edge a -> b at p, on integers (i64),
/// E(p) = (p_x - a_x)(b_y - a_y) - (p_y - a_y)(b_x - a_x),
/// is twice the signed area of the triangle (a, b, p). If the area E_ab(c) is
/// negative, swap b and c; if it is zero, nothing is covered. Then p is covered if,
/// for each of the edges b -> c, c -> a and a -> b, either E(p) > 0, or E(p) = 0 and
/// the edge is top-left. An edge u -> v is top-left if it runs down the image
/// (v_y > u_y), or is horizontal and runs towards -x (v_y = u_y and v_x < u_x).
pub fn covers(a: (i64, i64), b: (i64, i64), c: (i64, i64), p: (i64, i64)) -> bool {
    todo!(
        "Coding exercise 9.6 (chapter 09, The rasterization pipeline): the inside test, \
         edge functions and the top-left rule"
    )
}

/// Coding exercise 9.7: perspective-correct interpolation. The weights with which a
/// fragment mixes the attributes of the triangle's `vertices`, from its screen-space
/// barycentric weights `b` (`b[k]` belongs to `vertices[k]`; they sum to 1).
///
/// An attribute a is not affine on the screen, but a/w and 1/w are: interpolate both
/// with `b` and divide, a = (sum_k b_k a_k / w_k) / (sum_k b_k / w_k). So the weight
/// of vertex k is b_k (1/w_k) / sum_j b_j (1/w_j). Each vertex carries its 1/w as
/// `vertices[k].inv_w` (w = -Z, the depth in front of the camera).
/// (`raster::rasterize::perspective_weights` is the crate's answer.)
pub fn perspective_weights(b: [f32; 3], vertices: &[ScreenVertex; 3]) -> [f32; 3] {
    todo!(
        "Coding exercise 9.7 (chapter 09, The rasterization pipeline): perspective-correct weights"
    )
}
