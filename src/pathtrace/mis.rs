//! Multiple importance sampling (Veach and Guibas 1995; Veach's thesis 1997,
//! chapter 9): a sample drawn by one strategy is weighted by how likely each
//! strategy was to draw it, so that every strategy counts most where it is best and
//! the weights of any one direction add up to 1.

// ANCHOR: power_heuristic
/// Veach's power heuristic with the exponent 2 (Veach writes it beta): the weight p_a^2 / (p_a^2 + p_b^2) of a
/// sample drawn by strategy a, written as 1 / (1 + (p_b / p_a)^2) so that large
/// densities cannot overflow. 0 when p_a is 0 (a could not have drawn the sample).
pub fn power_heuristic(pdf_a: f32, pdf_b: f32) -> f32 {
    if pdf_a.is_nan() || pdf_a <= 0.0 {
        return 0.0;
    }
    let r = pdf_b / pdf_a;
    if r.is_finite() {
        1.0 / (1.0 + r * r)
    } else {
        0.0
    }
}
// ANCHOR_END: power_heuristic
