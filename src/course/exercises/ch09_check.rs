//! The checks of chapter 09's coding exercises: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's functions
//! are in `ch09.rs`, beside this file; the harness is `harness.rs`.

use glam::Vec2;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run};
use crate::raster::rasterize::{covers, perspective_weights};
use crate::raster::{ScreenVertex, Varyings};

/// Coding exercise 9.6.
pub const COVERS: Exercise = Exercise {
    number: "9.6",
    chapter: "09",
    chapter_title: "The rasterization pipeline",
    function: "covers",
    file: "src/course/exercises/ch09.rs",
};
/// Coding exercise 9.7.
pub const PERSPECTIVE_WEIGHTS: Exercise = Exercise {
    number: "9.7",
    chapter: "09",
    chapter_title: "The rasterization pipeline",
    function: "perspective_weights",
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
                let e = (f(q.0) - f(u.0)) * (f(v.1) - f(u.1))
                    - (f(q.1) - f(u.1)) * (f(v.0) - f(u.0));
                e.partial_cmp(&0.0).unwrap_or(Equal)
            }
            Inside::F64 => {
                let f = |x: i64| x as f64;
                let e = (f(q.0) - f(u.0)) * (f(v.1) - f(u.1))
                    - (f(q.1) - f(u.1)) * (f(v.0) - f(u.0));
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
            Inside::SignsOnly if clockwise => {
                e == Less || (e == Equal && top_left(u, v))
            }
            _ => e == Greater || (e == Equal && top_left(u, v)),
        }
    })
}

/// Checks `covers(a, b, c, p)`: does the triangle a, b, c (either winding, possibly
/// of zero area) cover the point p under the top-left rule?
pub fn check_covers(
    f: impl Fn(Fixed, Fixed, Fixed, Fixed) -> bool + Send + Sync + 'static,
) -> Outcome {
    covers_checked(Box::new(f))
}

/// [`check_covers`] for the answer as a trait object: compiled once, here, not again
/// for every closure a test passes (see [`super::harness`]).
fn covers_checked(
    f: Box<dyn Fn(Fixed, Fixed, Fixed, Fixed) -> bool + Send + Sync>,
) -> Outcome {
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
                && cases.iter().take_while(|(_, earlier)| earlier != args).all(
                    |(_, earlier)| covers_wrongly(rule, *earlier) == reference(earlier),
                )
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
        move |(a, b, c, p)| f(a, b, c, p),
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

/// The arguments of `perspective_weights`: the screen weights and the vertices.
type WeightsArgs = ([f32; 3], [ScreenVertex; 3]);

/// The vertices' 1/w.
fn inv_w(a: &WeightsArgs) -> [f32; 3] {
    a.1.map(|v| v.inv_w)
}

/// `b_k x_k / sum_j b_j y_j`: the weights with `x` on top and `y` below.
fn ratio(b: [f32; 3], x: [f32; 3], y: [f32; 3]) -> [f32; 3] {
    let sum: f32 = (0..3).map(|k| b[k] * y[k]).sum();
    [0, 1, 2].map(|k| b[k] * x[k] / sum)
}

/// Checks `perspective_weights(b, vertices)`: b_k (1/w_k) / sum_j b_j (1/w_j).
pub fn check_perspective_weights(
    f: impl Fn([f32; 3], &[ScreenVertex; 3]) -> [f32; 3] + Send + Sync + 'static,
) -> Outcome {
    perspective_weights_checked(Box::new(f))
}

/// [`check_perspective_weights`] for the answer as a trait object: compiled once, here,
/// not again for every closure a test passes (see [`super::harness`]).
fn perspective_weights_checked(
    f: Box<dyn Fn([f32; 3], &[ScreenVertex; 3]) -> [f32; 3] + Send + Sync>,
) -> Outcome {
    let vertex = |w: f32| ScreenVertex {
        pixel: Vec2::ZERO,
        depth: 0.5,
        inv_w: 1.0 / w,
        varyings: Varyings::default(),
    };
    let cases: Vec<Case<WeightsArgs>> = [
        (
            "the midpoint of the edge from w = 1 to w = 4",
            [0.5, 0.5, 0.0],
            [1.0, 4.0, 2.0],
        ),
        (
            "the centre of a triangle parallel to the screen",
            [1.0 / 3.0; 3],
            [2.0, 2.0, 2.0],
        ),
        (
            "an orthographic camera, every w = 1",
            [0.2, 0.3, 0.5],
            [1.0, 1.0, 1.0],
        ),
        ("a receding triangle", [0.2, 0.3, 0.5], [2.0, 5.0, 8.0]),
        ("on a vertex", [0.0, 1.0, 0.0], [1.5, 3.0, 9.0]),
        (
            "one vertex a hundred times as far",
            [0.4, 0.4, 0.2],
            [1.0, 100.0, 10.0],
        ),
    ]
    .into_iter()
    .map(|(what, b, w)| {
        let case = format!("{what}: b = {}, w = {}", b.show(), w.show());
        (case, (b, w.map(vertex)))
    })
    .collect();
    run(
        &cases,
        |a| perspective_weights(a.0, inv_w(a)),
        move |(b, vertices)| f(b, &vertices),
        &[
            Mistake {
                looks_like: &gives(&|a: &WeightsArgs| Some(a.0)),
                hint: "those are the screen weights b, right only when every w is the same: \
                       under perspective an attribute is not affine on the screen, a/w and \
                       1/w are. Weight vertex k by b_k (1/w_k), then divide by the sum",
            },
            Mistake {
                looks_like: &gives(&|a: &WeightsArgs| {
                    let w = inv_w(a).map(|i| 1.0 / i);
                    Some(ratio(a.0, w, w))
                }),
                hint: "inv_w is 1/w: multiply by it, so that a far vertex (large w) counts less, \
                       b_k (1/w_k) / sum_j b_j (1/w_j)",
            },
            Mistake {
                looks_like: &gives(&|a: &WeightsArgs| {
                    let i = inv_w(a);
                    Some([0, 1, 2].map(|k| a.0[k] * i[k]))
                }),
                hint: "the weights must sum to 1: divide each b_k (1/w_k) by \
                       sum_j b_j (1/w_j)",
            },
            Mistake {
                looks_like: &gives(&|a: &WeightsArgs| {
                    let i = inv_w(a);
                    let sum: f32 = i.iter().sum();
                    Some([0, 1, 2].map(|k| a.0[k] * i[k] / sum))
                }),
                hint: "divide by sum_j b_j (1/w_j), the interpolated 1/w at the fragment, not \
                       by the sum of the vertices' 1/w",
            },
        ],
        "weight_k = b_k inv_w_k / (b_0 inv_w_0 + b_1 inv_w_1 + b_2 inv_w_2)",
    )
}
