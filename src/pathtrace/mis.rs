//! Multiple importance sampling (Veach and Guibas 1995; Veach's thesis 1997,
//! chapter 9): a sample drawn by one strategy is weighted by how likely each
//! strategy was to draw it, so that every strategy counts most where it is best and
//! the weights of any one direction add up to 1.
//!
//! ```
//! use render_lessons::pathtrace::mis::{power_heuristic, power_heuristic_with_counts};
//!
//! // One sample each (the path tracer's case): the two forms agree bit for bit.
//! assert_eq!(power_heuristic(0.2, 0.3), power_heuristic_with_counts(1, 0.2, 1, 0.3));
//! // Four light samples (density 0.5) against one BSDF sample (density 1.5): each
//! // weight is (n p)^2 / ((n_a p_a)^2 + (n_b p_b)^2), and a direction's weights add up to 1.
//! let light = power_heuristic_with_counts(4, 0.5, 1, 1.5);
//! let bsdf = power_heuristic_with_counts(1, 1.5, 4, 0.5);
//! assert!((light - 4.0 / 6.25).abs() < 1e-6 && (light + bsdf - 1.0).abs() < 1e-6);
//! ```

// ANCHOR: power_heuristic
/// Veach's power heuristic with the exponent 2 (Veach writes it beta): the weight p_a^2 / (p_a^2 + p_b^2) of a
/// sample drawn by strategy a, written as 1 / (1 + (p_b / p_a)^2) so that large
/// densities cannot overflow. 0 when p_a is 0 (a could not have drawn the sample).
/// One sample from each strategy: [`power_heuristic_with_counts`] with n_a = n_b = 1.
pub fn power_heuristic(pdf_a: f32, pdf_b: f32) -> f32 {
    power_heuristic_with_counts(1, pdf_a, 1, pdf_b)
}

/// The general form, for `n_a` samples drawn by strategy a and `n_b` by b (Veach
/// 1997, eq. 9.13; pbrt's `PowerHeuristic(nf, fPdf, ng, gPdf)`): the weight
/// (n_a p_a)^2 / ((n_a p_a)^2 + (n_b p_b)^2), as 1 / (1 + (n_b p_b / n_a p_a)^2).
/// 0 when n_a p_a is 0. With counts of 1 the products are the densities themselves,
/// exactly.
pub fn power_heuristic_with_counts(n_a: u32, pdf_a: f32, n_b: u32, pdf_b: f32) -> f32 {
    let (a, b) = (n_a as f32 * pdf_a, n_b as f32 * pdf_b);
    if a.is_nan() || a <= 0.0 {
        return 0.0;
    }
    let r = b / a;
    if r.is_finite() {
        1.0 / (1.0 + r * r)
    } else {
        0.0
    }
}
// ANCHOR_END: power_heuristic
