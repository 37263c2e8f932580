//! The checks of the coding exercises.
//!
//! Each `check_*` function takes an implementation of one exercise as a function
//! argument, runs it on a few cases, and compares every answer with the crate's own
//! reference code (the code the book includes as the worked solution). It returns
//! [`Outcome::Pass`], [`Outcome::Fail`] with the first wrong case, the expected and
//! the received answer and a hint, or [`Outcome::NotStarted`] while the function is
//! still a `todo!()`.
//!
//! This module is compiled without the `exercises` feature too: the default test
//! suite runs every check against the reference implementation (it must pass) and
//! against a deliberately wrong one (it must fail with a hint), so a wrong check
//! fails CI.

use std::cell::Cell;
use std::fmt;
use std::panic::{self, AssertUnwindSafe};
use std::sync::Once;

use glam::{Mat4, Vec2, Vec3};

use crate::basis::Basis;
use crate::camera::{Film, Frame, PinholeCamera, camera_basis};
use crate::raster::rasterize::covers;
use crate::ray::Ray;
use crate::scene::{Object, Scene};
use crate::shapes::{Plane, Shape, Sphere};

/// The result of checking one exercise.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// Every case gave the expected answer.
    Pass,
    /// The first case that did not.
    Fail {
        /// The case, in words.
        case: String,
        /// What the reference code answers.
        expected: String,
        /// What the implementation answered (or how it panicked).
        got: String,
        /// What is probably wrong.
        hint: String,
    },
    /// The function still panics with `todo!()`.
    NotStarted,
}

impl Outcome {
    /// `PASS`, `FAIL` or `NOT STARTED`.
    pub fn status(&self) -> &'static str {
        match self {
            Outcome::Pass => "PASS",
            Outcome::Fail { .. } => "FAIL",
            Outcome::NotStarted => "NOT STARTED",
        }
    }
}

impl fmt::Display for Outcome {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Outcome::Pass => write!(f, "PASS: every case gives the expected answer"),
            Outcome::NotStarted => write!(f, "NOT STARTED: the function is still todo!()"),
            Outcome::Fail {
                case,
                expected,
                got,
                hint,
            } => write!(
                f,
                "FAIL\n  case:     {case}\n  expected: {expected}\n  got:      {got}\n  hint:     {hint}"
            ),
        }
    }
}

/// One coding exercise: where the student writes it and what it is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Exercise {
    /// "3.1": chapter 3, first coding exercise.
    pub number: &'static str,
    /// The chapter's number, "03".
    pub chapter: &'static str,
    /// The chapter's title.
    pub chapter_title: &'static str,
    /// The function the student writes.
    pub function: &'static str,
    /// The file it is in.
    pub file: &'static str,
}

impl Exercise {
    /// A full report of `outcome` for this exercise, several lines.
    pub fn report(&self, outcome: &Outcome) -> String {
        let head = format!(
            "Coding exercise {} `{}` (chapter {}, {}; in {})",
            self.number, self.function, self.chapter, self.chapter_title, self.file
        );
        match outcome {
            Outcome::NotStarted => format!(
                "{head}\nNOT STARTED: replace the todo!() in `{}` in {} with your code,\n  \
                 then run `cargo test --features exercises --test exercises ch{}`.",
                self.function, self.file, self.chapter
            ),
            other => format!("{head}\n{other}"),
        }
    }

    /// One line of a summary table: number, chapter, function, status.
    pub fn row(&self, outcome: &Outcome) -> String {
        format!(
            "{:<5} ch{}  {:<18} {}",
            self.number,
            self.chapter,
            self.function,
            outcome.status()
        )
    }
}

/// Coding exercise 2.1.
pub const POINT_AT: Exercise = Exercise {
    number: "2.1",
    chapter: "02",
    chapter_title: "The ray",
    function: "point_at",
    file: "src/course/exercises/ch02.rs",
};

/// Coding exercise 1.1.
pub const ROTATION_Y: Exercise = Exercise {
    number: "1.1",
    chapter: "01",
    chapter_title: "Geometric transformations",
    function: "rotation_y",
    file: "src/course/exercises/ch01.rs",
};

/// Coding exercise 3.1.
pub const PIXEL_TO_PLANE: Exercise = Exercise {
    number: "3.1",
    chapter: "03",
    chapter_title: "The orthographic camera",
    function: "pixel_to_plane",
    file: "src/course/exercises/ch03.rs",
};

/// Coding exercise 4.1.
pub const TO_WORLD: Exercise = Exercise {
    number: "4.1",
    chapter: "04",
    chapter_title: "Change of basis",
    function: "to_world",
    file: "src/course/exercises/ch04.rs",
};

/// Coding exercise 4.2.
pub const TO_LOCAL: Exercise = Exercise {
    number: "4.2",
    chapter: "04",
    chapter_title: "Change of basis",
    function: "to_local",
    file: "src/course/exercises/ch04.rs",
};

/// Coding exercise 5.1.
pub const CAMERA_BASIS: Exercise = Exercise {
    number: "5.1",
    chapter: "05",
    chapter_title: "An arbitrary orthographic camera",
    function: "camera_basis",
    file: "src/course/exercises/ch05.rs",
};

/// Coding exercise 6.1.
pub const PINHOLE_RAY: Exercise = Exercise {
    number: "6.1",
    chapter: "06",
    chapter_title: "The pinhole camera",
    function: "pinhole_ray",
    file: "src/course/exercises/ch06.rs",
};

/// Coding exercise 7.1.
pub const RAY_PLANE_T: Exercise = Exercise {
    number: "7.1",
    chapter: "07",
    chapter_title: "Ray/primitive intersections",
    function: "ray_plane_t",
    file: "src/course/exercises/ch07.rs",
};

/// Coding exercise 7.2.
pub const RAY_SPHERE_ROOTS: Exercise = Exercise {
    number: "7.2",
    chapter: "07",
    chapter_title: "Ray/primitive intersections",
    function: "ray_sphere_roots",
    file: "src/course/exercises/ch07.rs",
};

/// Coding exercise 8.1.
pub const CLOSEST: Exercise = Exercise {
    number: "8.1",
    chapter: "08",
    chapter_title: "Ray casting",
    function: "closest",
    file: "src/course/exercises/ch08.rs",
};

/// Coding exercise 9.1.
pub const COVERS: Exercise = Exercise {
    number: "9.1",
    chapter: "09",
    chapter_title: "The rasterization pipeline",
    function: "covers",
    file: "src/course/exercises/ch09.rs",
};

/// Every coding exercise, in book order.
pub const ALL: [Exercise; 11] = [
    ROTATION_Y,
    POINT_AT,
    PIXEL_TO_PLANE,
    TO_WORLD,
    TO_LOCAL,
    CAMERA_BASIS,
    PINHOLE_RAY,
    RAY_PLANE_T,
    RAY_SPHERE_ROOTS,
    CLOSEST,
    COVERS,
];

// ---------------------------------------------------------------------------
// Comparing and printing answers.

/// Relative (and, near zero, absolute) tolerance of every comparison.
pub const TOLERANCE: f32 = 1e-4;

/// An answer that can be compared with tolerance and printed.
pub trait Answer {
    /// Equal within [`TOLERANCE`].
    fn close(&self, other: &Self) -> bool;
    /// Short, readable form: numbers with at most four decimals.
    fn show(&self) -> String;
}

impl Answer for f32 {
    fn close(&self, other: &f32) -> bool {
        *self == *other || (self - other).abs() <= TOLERANCE * 1f32.max(self.abs()).max(other.abs())
    }
    fn show(&self) -> String {
        if !self.is_finite() {
            return format!("{self}");
        }
        let s = format!("{self:.4}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        if s == "-0" { "0".into() } else { s.into() }
    }
}

impl Answer for bool {
    fn close(&self, other: &bool) -> bool {
        self == other
    }
    fn show(&self) -> String {
        self.to_string()
    }
}

impl Answer for usize {
    fn close(&self, other: &usize) -> bool {
        self == other
    }
    fn show(&self) -> String {
        self.to_string()
    }
}

impl Answer for Vec2 {
    fn close(&self, other: &Vec2) -> bool {
        self.x.close(&other.x) && self.y.close(&other.y)
    }
    fn show(&self) -> String {
        format!("({}, {})", self.x.show(), self.y.show())
    }
}

impl Answer for Vec3 {
    fn close(&self, other: &Vec3) -> bool {
        self.x.close(&other.x) && self.y.close(&other.y) && self.z.close(&other.z)
    }
    fn show(&self) -> String {
        format!("({}, {}, {})", self.x.show(), self.y.show(), self.z.show())
    }
}

impl Answer for Mat4 {
    fn close(&self, other: &Mat4) -> bool {
        let (a, b) = (self.to_cols_array(), other.to_cols_array());
        a.iter().zip(&b).all(|(x, y)| x.close(y))
    }
    fn show(&self) -> String {
        let rows: Vec<String> = (0..4)
            .map(|i| {
                let r = self.row(i);
                format!(
                    "[{}, {}, {}, {}]",
                    r.x.show(),
                    r.y.show(),
                    r.z.show(),
                    r.w.show()
                )
            })
            .collect();
        format!("rows {}", rows.join(" "))
    }
}

impl<T: Answer> Answer for Option<T> {
    fn close(&self, other: &Option<T>) -> bool {
        match (self, other) {
            (Some(a), Some(b)) => a.close(b),
            (None, None) => true,
            _ => false,
        }
    }
    fn show(&self) -> String {
        match self {
            Some(a) => format!("Some({})", a.show()),
            None => "None".into(),
        }
    }
}

impl<A: Answer, B: Answer> Answer for (A, B) {
    fn close(&self, other: &(A, B)) -> bool {
        self.0.close(&other.0) && self.1.close(&other.1)
    }
    fn show(&self) -> String {
        format!("({}, {})", self.0.show(), self.1.show())
    }
}

impl<A: Answer, B: Answer, C: Answer> Answer for (A, B, C) {
    fn close(&self, other: &(A, B, C)) -> bool {
        self.0.close(&other.0) && self.1.close(&other.1) && self.2.close(&other.2)
    }
    fn show(&self) -> String {
        format!("({}, {}, {})", self.0.show(), self.1.show(), self.2.show())
    }
}

// ---------------------------------------------------------------------------
// Running an implementation.

thread_local! {
    /// True while this thread runs a student's function: its panics are reported in
    /// the outcome, not printed.
    static QUIET: Cell<bool> = const { Cell::new(false) };
}

static INSTALL_HOOK: Once = Once::new();

/// Runs `f`, catching a panic and returning its message.
///
/// The panic hook is replaced once by one that stays silent on a thread while it
/// runs a check and otherwise calls the previous hook. (Swapping the hook in and out
/// around every call would race between tests running in parallel.)
fn quietly<T>(f: impl FnOnce() -> T) -> Result<T, String> {
    INSTALL_HOOK.call_once(|| {
        let previous = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            if !QUIET.with(Cell::get) {
                previous(info);
            }
        }));
    });
    QUIET.with(|q| q.set(true));
    let result = panic::catch_unwind(AssertUnwindSafe(f));
    QUIET.with(|q| q.set(false));
    result.map_err(|payload| {
        if let Some(s) = payload.downcast_ref::<&str>() {
            (*s).to_string()
        } else if let Some(s) = payload.downcast_ref::<String>() {
            s.clone()
        } else {
            "a panic without a message".to_string()
        }
    })
}

/// A typical mistake: does the answer `got` for these arguments look like it?
struct Mistake<'a, A, R> {
    looks_like: &'a dyn Fn(&A, &R) -> bool,
    hint: &'static str,
}

/// A mistake recognised by the wrong answer it gives.
fn gives<'a, A, R: Answer>(wrong: &'a dyn Fn(&A) -> Option<R>) -> impl Fn(&A, &R) -> bool + 'a {
    move |a, got| wrong(a).is_some_and(|w| got.close(&w))
}

/// One case: its description and its arguments.
type Case<A> = (String, A);

/// Runs `student` on every case and compares with `reference`.
fn run<A: Clone, R: Answer>(
    cases: &[Case<A>],
    reference: impl Fn(&A) -> R,
    student: impl Fn(A) -> R,
    mistakes: &[Mistake<'_, A, R>],
    hint: &str,
) -> Outcome {
    for (case, args) in cases {
        let expected = reference(args);
        let got = match quietly(|| student(args.clone())) {
            Ok(got) => got,
            Err(message) if message.contains("not yet implemented") => {
                return Outcome::NotStarted;
            }
            Err(message) => {
                return Outcome::Fail {
                    case: case.clone(),
                    expected: expected.show(),
                    got: format!("a panic: {message}"),
                    hint: format!("the function must not panic on this input. {hint}"),
                };
            }
        };
        if !got.close(&expected) {
            let hint = mistakes
                .iter()
                .find(|m| (m.looks_like)(args, &got))
                .map_or(hint, |m| m.hint);
            return Outcome::Fail {
                case: case.clone(),
                expected: expected.show(),
                got: got.show(),
                hint: hint.to_string(),
            };
        }
    }
    Outcome::Pass
}

fn v(x: f32, y: f32, z: f32) -> Vec3 {
    Vec3::new(x, y, z)
}

// ---------------------------------------------------------------------------
// Chapter 01.

/// Checks `rotation_y(theta)`: the slide's 4x4 rotation about Y, `theta` in radians.
pub fn check_rotation_y(f: impl Fn(f32) -> Mat4) -> Outcome {
    let cases: Vec<Case<f32>> = [0.5f32, 1.0, -0.3, 2.0, std::f32::consts::FRAC_PI_2]
        .into_iter()
        .map(|theta| (format!("theta = {} rad", theta.show()), theta))
        .collect();
    let reference = |theta: f32| {
        crate::transform::Transform::rotation_y(theta)
            .map(|t| t.matrix())
            .unwrap_or(Mat4::NAN)
    };
    run(
        &cases,
        |&theta| reference(theta),
        f,
        &[
            Mistake {
                looks_like: &gives(&|&theta: &f32| Some(reference(-theta))),
                hint: "the -sin belongs in the bottom-left corner (row 3, column 1) for Y: the rotation \
                       turns z towards x. If you passed the slide's rows to Mat4::from_cols_array_2d, \
                       glam read them as columns: transpose, or use transform::from_rows",
            },
            Mistake {
                looks_like: &gives(&|&theta: &f32| Some(reference(theta.to_radians()))),
                hint: "theta is already in radians: do not convert it",
            },
        ],
        "x' = x cos + z sin, y' = y, z' = -x sin + z cos, written as a 4x4 matrix with w untouched",
    )
}

// ---------------------------------------------------------------------------
// Chapter 02.

/// Checks `point_at(o, d, t)`: the point r(t) = o + t d/|d|, `t` a distance.
pub fn check_point_at(f: impl Fn(Vec3, Vec3, f32) -> Vec3) -> Outcome {
    let cases: Vec<Case<(Vec3, Vec3, f32)>> = [
        (v(1.0, 1.0, 0.0), v(4.0, 3.0, 0.0), 0.0),
        (v(1.0, 1.0, 0.0), v(4.0, 3.0, 0.0), 5.0),
        (v(1.0, 1.0, 0.0), v(4.0, 3.0, 0.0), -2.0),
        (v(1.0, 1.0, 0.0), v(8.0, 6.0, 0.0), 2.5),
        (v(1.0, 2.0, 3.0), v(0.0, 0.0, -2.0), 4.0),
        (v(-1.0, 0.5, 2.0), v(1.0, 2.0, 2.0), 3.0),
    ]
    .into_iter()
    .map(|(o, d, t)| {
        (
            format!("o = {}, d = {}, t = {}", o.show(), d.show(), t.show()),
            (o, d, t),
        )
    })
    .collect();
    run(
        &cases,
        |&(o, d, t)| Ray::new(o, d).expect("valid ray").at(t),
        |(o, d, t)| f(o, d, t),
        &[
            Mistake {
                looks_like: &gives(&|&(o, d, t): &(Vec3, Vec3, f32)| Some(o + t * d)),
                hint: "t is a distance only along a unit direction: use d / |d| (d.normalize()), not d",
            },
            Mistake {
                looks_like: &gives(&|&(_, d, t): &(Vec3, Vec3, f32)| Some(t * d.normalize())),
                hint: "the ray starts at o: r(t) = o + t d/|d|",
            },
            Mistake {
                looks_like: &gives(&|&(o, d, t): &(Vec3, Vec3, f32)| Some(o - t * d.normalize())),
                hint: "positive t goes forward, along d: r(t) = o + t d/|d|",
            },
        ],
        "r(t) = o + t d/|d|",
    )
}

// ---------------------------------------------------------------------------
// Chapter 03.

/// The arguments of `pixel_to_plane`: x extent, y extent, width, height, px, py.
type PixelArgs = ((f32, f32), (f32, f32), u32, u32, u32, u32);

/// `pixel_to_plane` with rows counted as given, `offset` added to the pixel index.
fn plane_point(a: &PixelArgs, y_pixel: f32, offset: f32) -> Vec2 {
    let &((x_min, x_max), (y_min, y_max), w, h, px, _) = a;
    Vec2::new(
        (px as f32 + offset) / w as f32 * (x_max - x_min) + x_min,
        (y_pixel + offset) / h as f32 * (y_max - y_min) + y_min,
    )
}

/// Checks `pixel_to_plane(x, y, width, height, px, py)`: the centre of pixel
/// (`px`, `py`) on the plane, `py` counted from the top row.
pub fn check_pixel_to_plane(
    f: impl Fn((f32, f32), (f32, f32), u32, u32, u32, u32) -> Vec2,
) -> Outcome {
    let slide = ((-8.0, 8.0), (-6.0, 6.0), 4, 3);
    let odd = ((0.0, 10.0), (-1.0, 3.0), 5, 4);
    let cases: Vec<Case<PixelArgs>> = [
        (slide, 0, 0),
        (slide, 3, 2),
        (slide, 1, 0),
        (slide, 2, 1),
        (((-8.0, 8.0), (-6.0, 6.0), 8, 6), 0, 0),
        (((-8.0, 8.0), (-6.0, 6.0), 2, 2), 1, 1),
        (odd, 4, 0),
        (odd, 0, 3),
        (((2.0, 4.0), (5.0, 6.0), 1, 1), 0, 0),
    ]
    .into_iter()
    .map(|((x, y, w, h), px, py)| {
        (
            format!(
                "pixel ({px}, {py}) of a {w}x{h} image over x in [{}, {}], y in [{}, {}]",
                x.0.show(),
                x.1.show(),
                y.0.show(),
                y.1.show()
            ),
            (x, y, w, h, px, py),
        )
    })
    .collect();
    run(
        &cases,
        |&(x, y, w, h, px, py)| {
            Film::new(w, h, x, y)
                .expect("valid film")
                .pixel_to_plane(px, py)
        },
        |(x, y, w, h, px, py)| f(x, y, w, h, px, py),
        &[
            Mistake {
                looks_like: &gives(&|a: &PixelArgs| Some(plane_point(a, a.5 as f32, 0.5))),
                hint: "py counts rows from the top of the image, the slide's formula counts \
                       them from the bottom: use y_pixel = height - 1 - py (the row flip)",
            },
            Mistake {
                looks_like: &gives(&|a: &PixelArgs| {
                    Some(plane_point(a, a.3 as f32 - a.5 as f32, 0.5))
                }),
                hint: "off by one row: the bottom row is y_pixel = 0, so y_pixel = height - 1 - py, \
                       not height - py",
            },
            Mistake {
                looks_like: &gives(&|a: &PixelArgs| {
                    Some(plane_point(a, (a.3 - 1 - a.5) as f32, 0.0))
                }),
                hint: "that is the pixel's corner: the ray goes through its centre, so add 0.5 to \
                       the pixel index before dividing by the resolution",
            },
        ],
        "x = (px + 0.5) / width * (x_max - x_min) + x_min, and the same for y with \
         y_pixel = height - 1 - py",
    )
}

// ---------------------------------------------------------------------------
// Chapter 04.

/// The bases the chapter 04 checks use: standard, turned by 30° and 90° about Z, a
/// camera's basis, and a left-handed one.
fn bases() -> Vec<(&'static str, Basis)> {
    let turned = |deg: f32| {
        let (s, c) = deg.to_radians().sin_cos();
        Basis::new(v(c, s, 0.0), v(-s, c, 0.0), Vec3::Z).expect("orthonormal")
    };
    vec![
        ("the standard basis", Basis::STANDARD),
        ("the basis turned by 30 degrees about Z", turned(30.0)),
        ("the basis turned by 90 degrees about Z", turned(90.0)),
        (
            "the camera basis of d = (-1, 0, -1), k = (0, 1, 0)",
            camera_basis(v(-1.0, 0.0, -1.0), Vec3::Y).expect("valid camera"),
        ),
        (
            "the left-handed basis u = (0, 1, 0), v = (1, 0, 0), w = (0, 0, 1)",
            Basis::new(Vec3::Y, Vec3::X, Vec3::Z).expect("orthonormal"),
        ),
    ]
}

type BasisArgs = (Vec3, Vec3, Vec3, Vec3);

fn basis_cases(name: &str) -> Vec<Case<BasisArgs>> {
    let coords = [
        v(1.0, 0.0, 0.0),
        v(0.0, 1.0, 0.0),
        v(1.0, 2.0, 3.0),
        v(3.0, 4.0, 0.0),
    ];
    bases()
        .into_iter()
        .flat_map(|(what, b)| {
            coords.into_iter().map(move |x| {
                (
                    format!(
                        "{name} = {} in {what}: u = {}, v = {}, w = {}",
                        x.show(),
                        b.u().show(),
                        b.v().show(),
                        b.w().show()
                    ),
                    (b.u(), b.v(), b.w(), x),
                )
            })
        })
        .collect()
}

fn basis(&(u, v, w, _): &BasisArgs) -> Basis {
    Basis::new(u, v, w).expect("orthonormal")
}

/// Checks `to_world(u, v, w, b)`: a = B b, from coordinates in the basis [u v w] to
/// world coordinates.
pub fn check_to_world(f: impl Fn(Vec3, Vec3, Vec3, Vec3) -> Vec3) -> Outcome {
    run(
        &basis_cases("b"),
        |a| basis(a).to_world(a.3),
        |(u, v, w, b)| f(u, v, w, b),
        &[Mistake {
            looks_like: &gives(&|a: &BasisArgs| Some(basis(a).to_local(a.3))),
            hint: "dot products with u, v, w compute B^T a, the way back (to_local). a = B b \
                   weights the basis vectors: b.x u + b.y v + b.z w",
        }],
        "a = B b = b.x u + b.y v + b.z w, the basis vectors as the columns of B",
    )
}

/// Checks `to_local(u, v, w, a)`: b = B^T a, from world coordinates to coordinates
/// in the orthonormal basis [u v w].
pub fn check_to_local(f: impl Fn(Vec3, Vec3, Vec3, Vec3) -> Vec3) -> Outcome {
    run(
        &basis_cases("a"),
        |a| basis(a).to_local(a.3),
        |(u, v, w, a)| f(u, v, w, a),
        &[Mistake {
            looks_like: &gives(&|a: &BasisArgs| Some(basis(a).to_world(a.3))),
            hint: "a.x u + a.y v + a.z w is B a, the other direction (to_world). The way back is \
                   B^T a: one dot product per basis vector, (a . u, a . v, a . w)",
        }],
        "b = B^T a = (a . u, a . v, a . w): B is orthonormal, so its inverse is its transpose",
    )
}

// ---------------------------------------------------------------------------
// Chapter 05.

type Uvw = (Vec3, Vec3, Vec3);

/// Checks `camera_basis(d, k)`: the camera basis (u, v, w) from a view direction `d`
/// and an up vector `k`, neither necessarily of unit length.
pub fn check_camera_basis(f: impl Fn(Vec3, Vec3) -> Uvw) -> Outcome {
    let cases: Vec<Case<(Vec3, Vec3)>> = [
        (v(0.0, 0.0, -1.0), Vec3::Y),
        (v(-1.0, 0.0, -1.0), Vec3::Y),
        (v(0.0, -1.0, 0.0), v(0.0, 0.0, -1.0)),
        (v(0.0, -1.0, -2.0), Vec3::Y),
        (v(0.0, 0.0, -5.0), v(0.0, 3.0, 0.0)),
        (v(1.0, 1.0, 1.0), v(0.0, 0.0, 1.0)),
    ]
    .into_iter()
    .map(|(d, k)| (format!("d = {}, k = {}", d.show(), k.show()), (d, k)))
    .collect();
    let wrong = |slide: bool| {
        move |&(d, k): &(Vec3, Vec3)| -> Option<Uvw> {
            let w = if slide { d.normalize() } else { -d.normalize() };
            let u = k.cross(w).normalize();
            Some((u, w.cross(u), w))
        }
    };
    run(
        &cases,
        |&(d, k)| {
            let b = camera_basis(d, k).expect("valid camera");
            (b.u(), b.v(), b.w())
        },
        |(d, k)| f(d, k),
        &[
            Mistake {
                looks_like: &gives(&wrong(true)),
                hint: "w must point from the scene back to the eye, w = -d/|d|. With the slides' \
                       w = d/|d| the local direction (0, 0, -1) becomes -d: the camera looks \
                       backwards",
            },
            Mistake {
                looks_like: &|&(d, k): &(Vec3, Vec3), got: &Uvw| {
                    got.1.close(&k.normalize()) && !got.1.close(&wrong(false)(&(d, k)).unwrap().1)
                },
                hint: "v is not the up vector: k need not be perpendicular to d. Take v = w x u",
            },
            Mistake {
                looks_like: &|&(d, k): &(Vec3, Vec3), got: &Uvw| {
                    let (u, v, w) = wrong(false)(&(d, k)).unwrap();
                    got.close(&(-u, v, w)) || got.close(&(-u, -v, w))
                },
                hint: "the order of a cross product matters: u = k x w (w x k points the other \
                       way and mirrors the image), then v = w x u",
            },
            Mistake {
                looks_like: &|_: &(Vec3, Vec3), got: &Uvw| {
                    !(got.0.length().close(&1.0)
                        && got.1.length().close(&1.0)
                        && got.2.length().close(&1.0))
                },
                hint: "u, v and w must have length 1: normalise d (for w) and k x w (for u)",
            },
        ],
        "w = -d/|d|, u = (k x w)/|k x w|, v = w x u",
    )
}

// ---------------------------------------------------------------------------
// Chapter 06.

type PinholeArgs = (Film, f32, Frame, u32, u32);

/// Checks `pinhole_ray(film, s, frame, px, py)`: the world-space (origin, unit
/// direction) of the pinhole ray of pixel (`px`, `py`), screen at distance `s`.
pub fn check_pinhole_ray(f: impl Fn(&Film, f32, &Frame, u32, u32) -> (Vec3, Vec3)) -> Outcome {
    let film = Film::new(4, 3, (-8.0, 8.0), (-6.0, 6.0)).expect("valid film");
    let placed = Frame::look(v(0.0, 3.0, 6.0), v(0.0, -1.0, -2.0), Vec3::Y).expect("valid frame");
    let origin = Frame::AT_ORIGIN;
    let cases: Vec<Case<PinholeArgs>> = [
        (origin, 8.0, 0, 0, "at the origin"),
        (origin, 8.0, 2, 1, "at the origin"),
        (origin, 8.0, 3, 2, "at the origin"),
        (origin, 4.0, 2, 1, "at the origin"),
        (
            placed,
            8.0,
            0,
            0,
            "at (0, 3, 6) looking along (0, -1, -2), up (0, 1, 0)",
        ),
        (
            placed,
            8.0,
            3,
            2,
            "at (0, 3, 6) looking along (0, -1, -2), up (0, 1, 0)",
        ),
        (
            placed,
            2.0,
            1,
            1,
            "at (0, 3, 6) looking along (0, -1, -2), up (0, 1, 0)",
        ),
    ]
    .into_iter()
    .map(|(frame, s, px, py, where_)| {
        (
            format!(
                "pixel ({px}, {py}), 4x3 film over [-8, 8] x [-6, 6], s = {}, camera {where_}",
                s.show()
            ),
            (film, s, frame, px, py),
        )
    })
    .collect();
    let screen = |&(film, s, _, px, py): &PinholeArgs| film.pixel_to_plane(px, py).extend(-s);
    run(
        &cases,
        |&(film, s, frame, px, py)| {
            let ray = PinholeCamera::new(film, s, frame)
                .expect("valid camera")
                .ray(px, py);
            (ray.origin(), ray.direction())
        },
        |(film, s, frame, px, py)| f(&film, s, &frame, px, py),
        &[
            Mistake {
                looks_like: &gives(&|a: &PinholeArgs| {
                    let frame = a.2;
                    let p = a.0.pixel_to_plane(a.3, a.4).extend(0.0);
                    Some((frame.point_to_world(p), frame.vector_to_world(-Vec3::Z)))
                }),
                hint: "that is the orthographic ray (the slides' erratum). A pinhole ray starts at \
                       the eye e and goes through the screen point s = (x, y, -s): direction \
                       (s - e)/|s - e|",
            },
            Mistake {
                looks_like: &|_: &PinholeArgs, got: &(Vec3, Vec3)| !got.1.length().close(&1.0),
                hint: "the direction must have length 1: (s - e)/|s - e|",
            },
            Mistake {
                looks_like: &|a: &PinholeArgs, got: &(Vec3, Vec3)| {
                    let d = a.2.vector_to_world(screen(a).normalize());
                    got.1.close(&d) && !got.0.close(&a.2.position())
                },
                hint: "the direction is right, the origin is not: the ray starts at the eye, the \
                       camera position p (the camera-space origin carried to the world)",
            },
            Mistake {
                looks_like: &gives(&|a: &PinholeArgs| {
                    Some((a.2.position(), screen(a).normalize()))
                }),
                hint: "carry the camera-space direction to the world with the basis: B d \
                       (frame.vector_to_world), not the camera-space direction itself",
            },
            Mistake {
                looks_like: &|a: &PinholeArgs, got: &(Vec3, Vec3)| {
                    let mut s = screen(a);
                    s.z = -s.z;
                    got.1.close(&a.2.vector_to_world(s.normalize()))
                },
                hint: "the screen lies in front of the eye, on the plane z = -s (the camera looks \
                       down its -Z)",
            },
        ],
        "screen point s = (x, y, -s) with (x, y) the pixel centre on the film; eye e = 0; \
         direction (s - e)/|s - e|; then origin B e + p, direction B d",
    )
}

// ---------------------------------------------------------------------------
// Chapter 07.

type PlaneArgs = (Vec3, Vec3, Vec3, Vec3);

/// Checks `ray_plane_t(o, d, p0, n)`: the `t` where the line o + t d meets the plane
/// through `p0` with normal `n` (`d` and `n` of unit length), `None` if parallel.
pub fn check_ray_plane_t(f: impl Fn(Vec3, Vec3, Vec3, Vec3) -> Option<f32>) -> Outcome {
    let diagonal = v(1.0, 1.0, 1.0).normalize();
    let cases: Vec<Case<PlaneArgs>> = [
        (v(0.0, 3.0, 0.0), -Vec3::Y, Vec3::ZERO, Vec3::Y),
        (
            v(0.0, 3.0, 9.0),
            v(0.0, -2.2, -9.0).normalize(),
            Vec3::ZERO,
            Vec3::Y,
        ),
        (v(0.0, 3.0, 0.0), -Vec3::Y, Vec3::ZERO, -Vec3::Y),
        (v(0.0, -2.0, 0.0), -Vec3::Y, Vec3::ZERO, Vec3::Y),
        (v(0.0, 3.0, 0.0), Vec3::X, Vec3::ZERO, Vec3::Y),
        (Vec3::ZERO, diagonal, v(1.0, 2.0, 3.0), diagonal),
        (
            v(5.0, 1.0, -2.0),
            v(0.6, 0.0, 0.8),
            v(0.0, 0.0, 4.0),
            Vec3::Z,
        ),
    ]
    .into_iter()
    .map(|(o, d, p0, n)| {
        (
            format!(
                "o = {}, d = {}, plane through {} with normal {}",
                o.show(),
                d.show(),
                p0.show(),
                n.show()
            ),
            (o, d, p0, n),
        )
    })
    .collect();
    run(
        &cases,
        |&(o, d, p0, n)| {
            Plane::new(p0, n)
                .expect("valid plane")
                .t(&Ray::new(o, d).expect("valid ray"))
        },
        |(o, d, p0, n)| f(o, d, p0, n),
        &[
            Mistake {
                looks_like: &|a: &PlaneArgs, got: &Option<f32>| {
                    a.1.dot(a.3) == 0.0 && got.is_some()
                },
                hint: "the ray is parallel to the plane (d . n = 0): return None, never a NaN or an \
                       infinity",
            },
            Mistake {
                looks_like: &gives(&|&(o, d, p0, n): &PlaneArgs| {
                    Some(Some((o - p0).dot(n) / d.dot(n)))
                }),
                hint: "the sign is wrong: t = (p0 - o) . n / (d . n)",
            },
            Mistake {
                looks_like: &|&(o, d, p0, n): &PlaneArgs, got: &Option<f32>| {
                    got.is_none() && (p0 - o).dot(n) / d.dot(n) < 0.0
                },
                hint: "return the crossing even when t < 0 (behind the origin): choosing \
                       t_min < t < t_max is the hit function's job",
            },
        ],
        "t = (p0 - o) . n / (d . n), None when d . n = 0",
    )
}

type SphereArgs = (Vec3, Vec3, Vec3, f32);

/// Checks `ray_sphere_roots(o, d, c, r)`: both `t` where the line o + t d (`d` of
/// unit length) meets the sphere, ascending, or `None` when it misses.
pub fn check_ray_sphere_roots(f: impl Fn(Vec3, Vec3, Vec3, f32) -> Option<(f32, f32)>) -> Outcome {
    let cases: Vec<Case<SphereArgs>> = [
        (v(-3.0, 0.0, 0.0), Vec3::X, Vec3::ZERO, 1.0),
        (Vec3::ZERO, Vec3::X, Vec3::ZERO, 1.0),
        (v(-3.0, 1.0, 0.0), Vec3::X, Vec3::ZERO, 1.0),
        (v(-3.0, 2.0, 0.0), Vec3::X, Vec3::ZERO, 1.0),
        (v(3.0, 0.0, 0.0), Vec3::X, Vec3::ZERO, 1.0),
        (v(1.0, 2.0, -5.0), Vec3::Z, v(1.0, 2.0, 3.0), 2.0),
        (v(0.0, 0.0, 5.0), v(0.0, 0.6, -0.8), v(0.0, 1.0, 0.0), 1.5),
    ]
    .into_iter()
    .map(|(o, d, c, r)| {
        (
            format!(
                "o = {}, d = {}, sphere around {} with radius {}",
                o.show(),
                d.show(),
                c.show(),
                r.show()
            ),
            (o, d, c, r),
        )
    })
    .collect();
    let reference = |&(o, d, c, r): &SphereArgs| {
        Sphere::new(c, r)
            .expect("valid sphere")
            .roots_stable(&Ray::new(o, d).expect("valid ray"))
    };
    run(
        &cases,
        reference,
        |(o, d, c, r)| f(o, d, c, r),
        &[
            Mistake {
                looks_like: &gives(&|a: &SphereArgs| Some(reference(a).map(|(t0, t1)| (t1, t0)))),
                hint: "return the roots in ascending order, (t0, t1) with t0 <= t1",
            },
            Mistake {
                looks_like: &gives(&|a: &SphereArgs| Some(reference(a).map(|(t0, t1)| (-t1, -t0)))),
                hint: "the signs are flipped: f = o - c goes from the centre to the ray's origin, \
                       and b = 2 f . d",
            },
            Mistake {
                looks_like: &|a: &SphereArgs, got: &Option<(f32, f32)>| {
                    got.is_none() && reference(a).is_some_and(|(t0, _)| t0 < 0.0)
                },
                hint: "return both roots of the line, even negative ones (behind the origin); \
                       choosing t_min < t < t_max is the hit function's job",
            },
        ],
        "with f = o - c: a = d . d, b = 2 f . d, c = f . f - r^2; no roots when \
         b^2 - 4ac < 0; otherwise (-b -+ sqrt(b^2 - 4ac)) / 2a, ascending",
    )
}

// ---------------------------------------------------------------------------
// Chapter 08.

type ClosestArgs = (Ray, Vec<Shape>, f32, f32);

/// Checks `closest(ray, shapes, t_min, t_max)`: the index and `t` of the closest hit
/// with `t_min < t < t_max` over all `shapes`, or `None`.
pub fn check_closest(f: impl Fn(&Ray, &[Shape], f32, f32) -> Option<(usize, f32)>) -> Outcome {
    let sphere =
        |z: f32, r: f32| Shape::Sphere(Sphere::new(v(0.0, 0.0, z), r).expect("valid sphere"));
    let floor = Shape::Plane(Plane::new(v(0.0, -1.0, 0.0), Vec3::Y).expect("valid plane"));
    let down = Ray::new(v(0.0, 0.0, 5.0), -Vec3::Z).expect("valid ray");
    let up = Ray::new(v(0.0, 0.0, 5.0), Vec3::Z).expect("valid ray");
    let slanted = Ray::new(v(0.0, 0.0, 5.0), v(0.0, -1.0, -2.0)).expect("valid ray");
    let on_surface = Ray::new(v(0.0, 0.0, 1.0), -Vec3::Z).expect("valid ray");
    let inf = f32::INFINITY;
    let cases: Vec<Case<ClosestArgs>> = [
        ("ray from (0, 0, 5) along -Z; spheres at z = 0 (r 1) then z = -5 (r 1)", down, vec![sphere(0.0, 1.0), sphere(-5.0, 1.0)], 0.0, inf),
        ("ray from (0, 0, 5) along -Z; spheres at z = -5 (r 1) then z = 0 (r 1)", down, vec![sphere(-5.0, 1.0), sphere(0.0, 1.0)], 0.0, inf),
        ("ray from (0, 0, 5) along -Z; spheres at z = -5, z = 0, z = -10", down, vec![sphere(-5.0, 1.0), sphere(0.0, 1.0), sphere(-10.0, 1.0)], 0.0, inf),
        ("ray from (0, 0, 5) along (0, -1, -2); floor y = -1, sphere at z = 0 (r 1)", slanted, vec![floor.clone(), sphere(0.0, 1.0)], 0.0, inf),
        ("ray from (0, 0, 5) along (0, -1, -2); sphere at z = -8 (r 1), floor y = -1", slanted, vec![sphere(-8.0, 1.0), floor.clone()], 0.0, inf),
        ("ray from (0, 0, 5) along +Z, away from both spheres", up, vec![sphere(0.0, 1.0), sphere(-5.0, 1.0)], 0.0, inf),
        ("no shapes at all", down, vec![], 0.0, inf),
        ("ray from (0, 0, 5) along -Z, t_max = 3: the sphere at z = 0 is beyond it", down, vec![sphere(0.0, 1.0)], 0.0, 3.0),
        ("ray from (0, 0, 1), on the sphere at z = 0, along -Z, t_min = 0.001; sphere at z = -5 too", on_surface, vec![sphere(-5.0, 1.0), sphere(0.0, 1.0)], 1e-3, inf),
    ]
    .into_iter()
    .map(|(case, ray, shapes, t_min, t_max)| (format!("{case}; t in ({}, {})", t_min.show(), t_max.show()), (ray, shapes, t_min, t_max)))
    .collect();
    run(
        &cases,
        |(ray, shapes, t_min, t_max)| {
            let objects = shapes
                .iter()
                .map(|shape| Object::diffuse(shape.clone(), Vec3::ONE))
                .collect();
            // A closest-hit query needs no light.
            let scene = Scene::new(objects, Vec3::ZERO).expect("valid scene");
            scene
                .closest(ray, *t_min, *t_max)
                .map(|(hit, index)| (index, hit.t))
        },
        |(ray, shapes, t_min, t_max)| f(&ray, &shapes, t_min, t_max),
        &[
            Mistake {
                looks_like: &gives(&|(ray, shapes, t_min, t_max): &ClosestArgs| {
                    Some(
                        shapes
                            .iter()
                            .enumerate()
                            .find_map(|(i, s)| s.hit(ray, *t_min, *t_max).map(|h| (i, h.t))),
                    )
                }),
                hint: "that is the first hit in list order, not the closest: keep looking after a hit, \
                   and shrink t_max to its t so that only nearer hits count",
            },
            Mistake {
                looks_like: &gives(&|(ray, shapes, t_min, t_max): &ClosestArgs| {
                    Some(
                        shapes
                            .iter()
                            .enumerate()
                            .filter_map(|(i, s)| s.hit(ray, *t_min, *t_max).map(|h| (i, h.t)))
                            .next_back(),
                    )
                }),
                hint: "that is the last hit in list order, not the closest: the last hit found is \
                       the closest only if you shrink t_max to each hit's t, so that only nearer \
                       hits count",
            },
        ],
        "test every shape with shape.hit(ray, t_min, t_max); after each hit set t_max = hit.t \
         and remember its index; return the last one remembered",
    )
}

// ---------------------------------------------------------------------------
// Chapter 09.

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
