//! The check of chapter 09's coding exercise: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's function
//! is in `ch09.rs`, beside this file; the harness is `harness.rs`.

use super::harness::{Case, Exercise, Mistake, Outcome, run};
use crate::raster::rasterize::covers;

/// Coding exercise 9.1.
pub const COVERS: Exercise = Exercise {
    number: "9.1",
    chapter: "09",
    chapter_title: "The rasterization pipeline",
    function: "covers",
    file: "src/course/exercises/ch09.rs",
};

/// A point on the rasterizer's sub-pixel grid: (column, row), rows growing downwards.
type Fixed = (i64, i64);

/// The arguments of `covers`: the vertices a, b, c and the point p.
type CoversArgs = (Fixed, Fixed, Fixed, Fixed);

/// The typical ways of getting `covers` wrong, as rules the check can run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Inside {
    /// E > 0 on every edge: no top-left rule.
    Strict,
    /// E >= 0 on every edge: no top-left rule.
    NonStrict,
    /// The top-left rule, but no swap when the area is negative.
    NoSwap,
    /// A negative area flips the signs of the edge functions, but the top-left rule
    /// still looks at the edges in their original direction.
    SignsOnly,
    /// The right rule, computed in f32.
    F32,
    /// The right rule, computed in f64.
    F64,
    /// The right rule, computed in i32 (wrapping on overflow, as in a release build).
    I32,
}

/// `covers(a, b, c, p)` gone wrong the way `rule` says.
fn covers_wrongly(rule: Inside, (a, b, c, p): CoversArgs) -> bool {
    use std::cmp::Ordering::{self, Equal, Greater, Less};
    // The sign of the edge function E_uv(q).
    let edge = |u: Fixed, v: Fixed, q: Fixed| -> Ordering {
        match rule {
            Inside::F32 => {
                let f = |x: i64| x as f32;
                let e =
                    (f(q.0) - f(u.0)) * (f(v.1) - f(u.1)) - (f(q.1) - f(u.1)) * (f(v.0) - f(u.0));
                e.partial_cmp(&0.0).unwrap_or(Equal)
            }
            Inside::F64 => {
                let f = |x: i64| x as f64;
                let e =
                    (f(q.0) - f(u.0)) * (f(v.1) - f(u.1)) - (f(q.1) - f(u.1)) * (f(v.0) - f(u.0));
                e.partial_cmp(&0.0).unwrap_or(Equal)
            }
            Inside::I32 => {
                let d = |x: i64, y: i64| (x as i32).wrapping_sub(y as i32);
                let e = d(q.0, u.0)
                    .wrapping_mul(d(v.1, u.1))
                    .wrapping_sub(d(q.1, u.1).wrapping_mul(d(v.0, u.0)));
                e.cmp(&0)
            }
            _ => ((q.0 - u.0) * (v.1 - u.1) - (q.1 - u.1) * (v.0 - u.0)).cmp(&0),
        }
    };
    let top_left = |u: Fixed, v: Fixed| (v.1 == u.1 && v.0 < u.0) || v.1 > u.1;
    let area = edge(a, b, c);
    if area == Equal {
        return false;
    }
    let clockwise = area == Less;
    let swap = clockwise && !matches!(rule, Inside::NoSwap | Inside::SignsOnly);
    let (b, c) = if swap { (c, b) } else { (b, c) };
    [(b, c), (c, a), (a, b)].into_iter().all(|(u, v)| {
        let e = edge(u, v, p);
        match rule {
            Inside::Strict => e == Greater,
            Inside::NonStrict => e != Less,
            Inside::SignsOnly if clockwise => e == Less || (e == Equal && top_left(u, v)),
            _ => e == Greater || (e == Equal && top_left(u, v)),
        }
    })
}

/// Checks `covers(a, b, c, p)`: does the triangle a, b, c (either winding, possibly
/// of zero area) cover the point p under the top-left rule?
pub fn check_covers(f: impl Fn(Fixed, Fixed, Fixed, Fixed) -> bool) -> Outcome {
    // Two triangles sharing the diagonal from (0, 0) to (8, 8), both counter-clockwise
    // on the image (positive area): `lower` has a left and a bottom edge, `upper` a
    // top and a right edge; the diagonal is lower's right edge and upper's left edge.
    let lower = ((0, 0), (0, 8), (8, 8));
    let upper = ((0, 0), (8, 8), (8, 0));
    let cw = |(a, b, c): (Fixed, Fixed, Fixed)| (a, c, b);
    // Far out on the grid, with a long, slightly slanted edge from c to a.
    let large = (
        (1_000_000, 1_000_000),
        (1_000_000, 3_000_000),
        (3_000_000, 2_999_999),
    );
    let huge = (
        (100_000_000, 100_000_000),
        (100_000_000, 500_000_000),
        (500_000_000, 499_999_999),
    );
    let ccw = "counter-clockwise on the image";
    let clockwise = "clockwise on the image";
    let cases: Vec<Case<CoversArgs>> = [
        (lower, ccw, (2, 6), "inside"),
        (
            lower,
            ccw,
            (6, 2),
            "outside (inside the triangle across the diagonal)",
        ),
        (lower, ccw, (-1, 4), "outside, just left of the left edge"),
        (lower, ccw, (0, 4), "exactly on its left edge"),
        (upper, ccw, (4, 0), "exactly on its top edge"),
        (upper, ccw, (8, 4), "exactly on its right edge"),
        (lower, ccw, (4, 8), "exactly on its bottom edge"),
        (
            lower,
            ccw,
            (4, 4),
            "exactly on its right edge, shared with (0, 0), (8, 8), (8, 0)",
        ),
        (
            upper,
            ccw,
            (4, 4),
            "exactly on its left edge, shared with (0, 0), (0, 8), (8, 8)",
        ),
        (
            lower,
            ccw,
            (0, 0),
            "exactly on its top vertex, shared with (0, 0), (8, 8), (8, 0)",
        ),
        (
            upper,
            ccw,
            (0, 0),
            "exactly on its top-left vertex, shared with (0, 0), (0, 8), (8, 8)",
        ),
        (cw(lower), clockwise, (2, 6), "inside"),
        (cw(lower), clockwise, (6, 2), "outside"),
        (cw(lower), clockwise, (0, 4), "exactly on its left edge"),
        (cw(lower), clockwise, (4, 8), "exactly on its bottom edge"),
        (cw(upper), clockwise, (4, 0), "exactly on its top edge"),
        (cw(upper), clockwise, (8, 4), "exactly on its right edge"),
        (
            cw(upper),
            clockwise,
            (4, 4),
            "exactly on its left edge, the diagonal",
        ),
        (
            ((0, 0), (4, 4), (8, 8)),
            "zero area: a segment",
            (4, 4),
            "on the segment",
        ),
        (
            ((0, 0), (4, 4), (8, 8)),
            "zero area: a segment",
            (2, 2),
            "on the segment",
        ),
        (
            ((3, 3), (3, 3), (3, 3)),
            "zero area: a point",
            (3, 3),
            "on the point",
        ),
        (large, ccw, (1_500_000, 2_500_000), "inside"),
        (
            large,
            ccw,
            (1_000_001, 1_000_001),
            "inside, E = 1 from the long edge c -> a",
        ),
        (
            huge,
            ccw,
            (100_000_001, 100_000_001),
            "inside, E = 1 from the long edge c -> a",
        ),
    ]
    .into_iter()
    .map(|((a, b, c), winding, p, place)| {
        (
            format!("triangle a = {a:?}, b = {b:?}, c = {c:?} ({winding}); p = {p:?}, {place}"),
            (a, b, c, p),
        )
    })
    .collect();
    let reference = |&(a, b, c, p): &CoversArgs| covers(a, b, c, p);
    // With yes-or-no answers every wrong rule gives the received answer wherever it
    // goes wrong: the one that explains a failure goes wrong on this case and, like the
    // implementation, right on every case before it.
    let wrong_first_here = |rule: Inside| {
        let cases = &cases;
        move |args: &CoversArgs, got: &bool| {
            *got == covers_wrongly(rule, *args)
                && cases
                    .iter()
                    .take_while(|(_, earlier)| earlier != args)
                    .all(|(_, earlier)| covers_wrongly(rule, *earlier) == reference(earlier))
        }
    };
    let strict = wrong_first_here(Inside::Strict);
    let non_strict = wrong_first_here(Inside::NonStrict);
    let no_swap = wrong_first_here(Inside::NoSwap);
    let signs_only = wrong_first_here(Inside::SignsOnly);
    let f32s = wrong_first_here(Inside::F32);
    let f64s = wrong_first_here(Inside::F64);
    let i32s = wrong_first_here(Inside::I32);
    let floats = "compute the edge functions on integers (i64), not in floating point: far out \
                  on the grid the products are rounded (f32 keeps 24 bits, f64 53), and a point \
                  just inside an edge, E = 1, rounds onto it";
    run(
        &cases,
        reference,
        |(a, b, c, p)| f(a, b, c, p),
        &[
            Mistake {
                looks_like: &strict,
                hint: "a point exactly on an edge (E = 0) is covered if that edge is top-left: \
                       with E > 0 everywhere it belongs to neither of two triangles sharing the \
                       edge, which leaves cracks in a mesh",
            },
            Mistake {
                looks_like: &non_strict,
                hint: "with E >= 0 everywhere a point on an edge shared by two triangles belongs \
                       to both, and is drawn twice (double blending): accept E = 0 only on a \
                       top-left edge",
            },
            Mistake {
                looks_like: &no_swap,
                hint: "this triangle runs clockwise on the image: its area E_ab(c) is negative, \
                       and so are its edge functions inside, so nothing is covered. Swap b and c \
                       when the area is negative",
            },
            Mistake {
                looks_like: &signs_only,
                hint: "for a clockwise triangle swap b and c, do not just flip the signs of E: \
                       the top-left rule looks at each edge's direction, which the swap reverses",
            },
            Mistake {
                looks_like: &f32s,
                hint: floats,
            },
            Mistake {
                looks_like: &f64s,
                hint: floats,
            },
            Mistake {
                looks_like: &i32s,
                hint: "the products overflow i32 (at 1e6 sub-pixel units they reach 4e12): \
                       compute in i64",
            },
        ],
        "E_uv(p) = (p_x - u_x)(v_y - u_y) - (p_y - u_y)(v_x - u_x), in i64. Nothing is covered \
         if the area E_ab(c) is 0; swap b and c if it is negative; then p is covered if on each \
         edge b -> c, c -> a, a -> b, E(p) > 0, or E(p) = 0 and the edge is top-left \
         (v_y > u_y, or v_y = u_y and v_x < u_x)",
    )
}
