//! The roots of a t^2 + b t + c = 0: the equation a sphere or any quadric surface
//! becomes once the ray o + t d is put into it (Lecture 4). Solved two ways, the
//! school formula and the stable one; each shape forms its own a, b, c and
//! discriminant, and both shapes share these solvers (STABILITY S1, S2, S9).

use crate::float::gamma;
use crate::ray::Crossings;

// ANCHOR: textbook
/// The roots by the school formula t = (-b +- sqrt(b^2 - 4ac)) / 2a, ascending, the
/// non-finite ones dropped.
///
/// Two cancellations break it in f32. When b^2 and 4ac are nearly equal (a small
/// sphere far away) their difference is lost to rounding (S1); when a -> 0 (a ray
/// nearly parallel to a paraboloid's axis) the root that matters is
/// -b + sqrt(b^2 - 4ac) with b^2 >> 4ac, two nearly equal numbers subtracted and
/// then divided by the tiny 2a (S9). Kept to show those failures.
///
/// ```
/// use render_lessons::quadratic::textbook;
///
/// // (t - 1)(t - 3) = t^2 - 4t + 3
/// assert_eq!(textbook(1.0, -4.0, 3.0).as_slice(), [1.0, 3.0]);
/// assert!(textbook(1.0, 0.0, 1.0).is_empty()); // t^2 + 1 has no real root
/// ```
pub fn textbook(a: f32, b: f32, c: f32) -> Crossings {
    let disc = b * b - 4.0 * a * c;
    if disc.is_nan() || disc < 0.0 {
        return Crossings::NONE;
    }
    let s = disc.sqrt();
    Crossings::two((-b - s) / (2.0 * a), (-b + s) / (2.0 * a))
}
// ANCHOR_END: textbook

// ANCHOR: stable
/// The roots computed so that neither cancels, from the discriminant `disc` =
/// b^2 - 4ac that the caller formed in its own careful way; ascending, the
/// non-finite ones dropped.
///
/// Numerical Recipes (section 5.6): q = -(b + sign(b) sqrt(disc)) / 2 with
/// sign(0) = +1, then t = c/q and t = q/a. The sum b + sign(b) sqrt(disc) adds two
/// numbers of the same sign, so nothing cancels. As a -> 0, q -> -b and c/q -> -c/b,
/// the root of the linear equation b t + c = 0; at a = 0 exactly, q/a is infinite and
/// dropped, leaving one root (S9).
///
/// q = 0 means b = 0 and disc = 0: a double root at 0 if a != 0 (a ray starting on a
/// sphere, tangent to it: S2); if a = 0 as well, the line lies on the surface or off
/// it everywhere, and there is no crossing.
///
/// ```
/// use render_lessons::quadratic::stable;
///
/// let (a, b, c) = (1.0, -4.0, 3.0);
/// assert_eq!(stable(a, b, c, b * b - 4.0 * a * c).as_slice(), [1.0, 3.0]);
/// // a = 0: the line 2t - 4 = 0 crosses once, at t = 2.
/// assert_eq!(stable(0.0, 2.0, -4.0, 4.0).as_slice(), [2.0]);
/// ```
pub fn stable(a: f32, b: f32, c: f32, disc: f32) -> Crossings {
    match stable_pair(a, b, c, disc) {
        Some((t0, t1)) => Crossings::two(t0, t1),
        None => Crossings::NONE,
    }
}

/// The two roots c/q and q/a of [`stable`] as they come: unordered, and either may be
/// infinite (a line nearly parallel to a cylinder's axis leaves it that far away).
/// `None` for a negative or NaN discriminant, and for q = 0 with a = 0.
pub fn stable_pair(a: f32, b: f32, c: f32, disc: f32) -> Option<(f32, f32)> {
    if disc.is_nan() || disc < 0.0 {
        return None;
    }
    let sign = if b >= 0.0 { 1.0 } else { -1.0 };
    let q = -0.5 * (b + sign * disc.sqrt());
    if q == 0.0 {
        return (a != 0.0).then_some((0.0, 0.0));
    }
    Some((c / q, q / a))
}
// ANCHOR_END: stable

/// The discriminant `disc` = b^2 - 4ac, set to 0 when it is negative by no more than
/// the rounding of a, b and c can explain, gamma(8) (b^2 + |4ac|). A tangent ray's
/// discriminant is exactly 0, but a, b and c are rounded before it is formed: for
/// The Ray Tracer Challenge's ray along (1, 1, 1) tangent to a cone it comes out a
/// few ulps below 0 in f32, and the hit would be lost.
pub fn tangent_as_zero(disc: f32, b2: f32, four_ac: f32) -> f32 {
    if disc < 0.0 && -disc <= gamma(8) * (b2 + four_ac.abs()) {
        0.0
    } else {
        disc
    }
}
