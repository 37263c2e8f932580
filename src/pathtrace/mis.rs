//! Multiple importance sampling (Veach and Guibas 1995; Veach's thesis 1997,
//! chapter 9): a sample drawn by one strategy is weighted by how likely each
//! strategy was to draw it, so that every strategy counts most where it is best and
//! the weights of any one direction add up to 1. A point light takes no part: only
//! its shadow ray can find it, so that strategy's weight is 1.
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
/// Veach's power heuristic with the exponent 2 (Veach writes it beta): the weight p_a^2
/// / (p_a^2 + p_b^2) of a sample drawn by strategy a, written as 1 / (1 + (p_b /
/// p_a)^2) so that large densities cannot overflow. 0 when p_a is 0 (a could not have
/// drawn the sample). One sample from each strategy: [`power_heuristic_with_counts`]
/// with n_a = n_b = 1.
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_heuristic_is_the_counted_form_with_one_sample_each() {
        let values = [
            0.0f32,
            -1.0,
            1e-30,
            0.2,
            0.3,
            1.0,
            6.535,
            1e30,
            f32::INFINITY,
            f32::NAN,
        ];
        for a in values {
            for b in values {
                let one = power_heuristic(a, b);
                let counted = power_heuristic_with_counts(1, a, 1, b);
                assert_eq!(one.to_bits(), counted.to_bits(), "{a} {b}");
            }
        }
        // Veach's form with counts, against f64: (n_a p_a)^2 / ((n_a p_a)^2 + (n_b
        // p_b)^2), and the weights of one direction add up to 1.
        for (n_a, p_a, n_b, p_b) in
            [(4, 0.5f32, 1, 1.5f32), (1, 2.0, 16, 0.1), (3, 0.7, 5, 0.7)]
        {
            let w_a = power_heuristic_with_counts(n_a, p_a, n_b, p_b);
            let w_b = power_heuristic_with_counts(n_b, p_b, n_a, p_a);
            let (a, b) = (
                f64::from(n_a) * f64::from(p_a),
                f64::from(n_b) * f64::from(p_b),
            );
            let exact = a * a / (a * a + b * b);
            assert!((f64::from(w_a) - exact).abs() < 1e-6, "{w_a} vs {exact}");
            assert!((w_a + w_b - 1.0).abs() < 1e-6);
        }
        // A strategy that drew no sample gets no weight.
        assert_eq!(power_heuristic_with_counts(0, 1.0, 1, 1.0), 0.0);
        assert_eq!(power_heuristic_with_counts(1, 1.0, 0, 1.0), 1.0);
    }
}
