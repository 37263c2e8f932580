//! Floating-point tools the intersection tests share, as pbrt-v4's `util/float.h`:
//! a bound on the error of n rounded operations, and a difference of products with
//! one rounding instead of two.

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_matches_pbrt() {
        let eps = f32::EPSILON as f64 / 2.0;
        let g3 = 3.0 * eps / (1.0 - 3.0 * eps);
        assert!((gamma(3) as f64 - g3).abs() < 1e-12);
    }
}
