//! Floating-point tools the intersection tests share, as pbrt-v4's `util/float.h`:
//! a bound on the error of n rounded operations, a difference of products with one
//! rounding instead of two, and the far end of a slab moved out by its rounding.

/// pbrt's gamma(n) = n eps / (1 - n eps), eps = f32::EPSILON / 2 (the unit roundoff):
/// a bound on the relative error of n rounded operations (pbrt-v4, section 6.8.1).
///
/// ```
/// use render_lessons::float::gamma;
///
/// let eps = f32::EPSILON / 2.0;
/// assert_eq!(gamma(1), eps / (1.0 - eps));
/// assert!(gamma(3) > 3.0 * eps && gamma(3) < 3.0 * eps * 1.001);
/// ```
pub const fn gamma(n: u32) -> f32 {
    let eps = f32::EPSILON / 2.0;
    let n = n as f32;
    n * eps / (1.0 - n * eps)
}

/// a b - c d with one rounding error instead of two: the product c d is rounded, its
/// rounding error recovered exactly with a fused multiply-add and added back
/// (Kahan; Jeannerod, Louvet and Muller, "Further analysis of Kahan's algorithm for
/// the accurate computation of 2x2 determinants", Math. Comp. 2013; pbrt-v4's
/// `DifferenceOfProducts`).
///
/// ```
/// use render_lessons::float::difference_of_products;
///
/// // (1 + 2^-12)^2 - (1 + 2^-11) = 2^-24: the plain difference of the rounded
/// // products loses it.
/// let x = 1.0 + 2f32.powi(-12);
/// let y = 1.0 + 2f32.powi(-11);
/// assert_eq!(x * x - y * 1.0, 0.0);
/// assert_eq!(difference_of_products(x, x, y, 1.0), 2f32.powi(-24));
/// ```
pub fn difference_of_products(a: f32, b: f32, c: f32, d: f32) -> f32 {
    let cd = c * d;
    let err = (-c).mul_add(d, cd);
    let dop = a.mul_add(b, -cd);
    dop + err
}

// ANCHOR: moved_out
/// How far a conservative slab test moves a slab's exit out, relative to itself:
/// pbrt-v4's 2 gamma(3), the most the three rounded operations behind t_far can
/// have moved it in (Ize 2013, "Robust BVH Ray Traversal").
pub(crate) const FAR_MARGIN: f32 = 2.0 * gamma(3);

/// The exit `t` moved out by [`FAR_MARGIN`] of its size: t (1 + margin) if t > 0,
/// t (1 - margin), towards 0, if t < 0; 0 and infinities stay as they are. A sum and
/// a minimum, no branch, where a product would need the sign to choose its factor.
/// The minimum keeps an exit of -infinity (a ray parallel to a slab, outside it) at
/// -infinity: -inf + inf would be NaN, and a NaN exit constrains nothing. The one
/// rule of both conservative slab tests,
/// [`Aabb::slab_conservative`](crate::shapes::Aabb::slab_conservative) and the BVH's.
#[inline(always)]
pub(crate) fn moved_out(t: f32) -> f32 {
    t + (t.abs() * FAR_MARGIN).min(f32::MAX)
}
// ANCHOR_END: moved_out

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_matches_pbrt() {
        let eps = f32::EPSILON as f64 / 2.0;
        let g3 = 3.0 * eps / (1.0 - 3.0 * eps);
        assert!((gamma(3) as f64 - g3).abs() < 1e-12);
    }

    /// The sum [`moved_out`] against the products pbrt-v4 writes (t (1 + 2 gamma(3))
    /// for t > 0, t (1 - 2 gamma(3)) for t < 0), over floats of every exponent from
    /// 1e-30 to 1e30, both signs, and their neighbours: never lower, so the box test
    /// loses no hit the product would find.
    #[test]
    fn far_end_moves_at_least_as_far_as_the_product() {
        let (up, down) = (1.0 + 2.0 * gamma(3), 1.0 - 2.0 * gamma(3));
        let mut t = 1e-30f32;
        let mut checked = 0;
        while t < 1e30 {
            for x in [
                t,
                -t,
                t.next_up(),
                -t.next_up(),
                t.next_down(),
                -t.next_down(),
            ] {
                let product = if x > 0.0 { x * up } else { x * down };
                assert!(moved_out(x) >= product, "{x:e}");
                checked += 1;
            }
            t *= 1.000_013;
        }
        assert!(checked > 1_000_000, "{checked}");
    }
}
