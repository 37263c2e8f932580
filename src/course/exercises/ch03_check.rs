//! The checks of chapter 03's coding exercises: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's functions
//! are in `ch03.rs`, beside this file; the harness is `harness.rs`.

use glam::Vec2;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run};
use crate::camera::Film;

/// Coding exercise 3.5.
pub const PIXEL_TO_PLANE: Exercise = Exercise {
    number: "3.5",
    chapter: "03",
    chapter_title: "The orthographic camera",
    function: "pixel_to_plane",
    file: "src/course/exercises/ch03.rs",
};
/// Coding exercise 3.6.
pub const PLANE_TO_PIXEL: Exercise = Exercise {
    number: "3.6",
    chapter: "03",
    chapter_title: "The orthographic camera",
    function: "plane_to_pixel",
    file: "src/course/exercises/ch03.rs",
};

// ANCHOR: solution
/// A worked solution of exercise 3.5: the slide's formula, with the row counted from
/// the bottom first (the crate's `Film::pixel_to_plane` does the same).
pub fn pixel_to_plane_solution(film: &Film, px: u32, py: u32) -> Vec2 {
    let ((x_min, x_max), (y_min, y_max)) = (film.x_extent(), film.y_extent());
    let (width, height) = (film.width() as f32, film.height() as f32);
    let x_pixel = px as f32;
    let y_pixel = (film.height() - 1 - py) as f32;
    Vec2::new(
        (x_pixel + 0.5) / width * (x_max - x_min) + x_min,
        (y_pixel + 0.5) / height * (y_max - y_min) + y_min,
    )
}
// ANCHOR_END: solution

/// The arguments of `pixel_to_plane`: the film and the pixel.
type PixelArgs = (Film, u32, u32);

/// `pixel_to_plane` with the row `y_pixel` used as given, `offset` added to the pixel
/// index.
fn plane_point(&(film, px, _): &PixelArgs, y_pixel: f32, offset: f32) -> Vec2 {
    let ((x_min, x_max), (y_min, y_max)) = (film.x_extent(), film.y_extent());
    Vec2::new(
        (px as f32 + offset) / film.width() as f32 * (x_max - x_min) + x_min,
        (y_pixel + offset) / film.height() as f32 * (y_max - y_min) + y_min,
    )
}

/// The films the checks of chapter 03 use, with the cases' pixels: the slide's, finer
/// and coarser ones, an odd one and a single pixel.
fn films() -> Vec<(Film, Vec<(u32, u32)>)> {
    let film = |w, h, x, y| Film::new(w, h, x, y).expect("valid film");
    let slide = film(4, 3, (-8.0, 8.0), (-6.0, 6.0));
    vec![
        (slide, vec![(0, 0), (3, 2), (1, 0), (2, 1)]),
        (film(8, 6, (-8.0, 8.0), (-6.0, 6.0)), vec![(0, 0)]),
        (film(2, 2, (-8.0, 8.0), (-6.0, 6.0)), vec![(1, 1)]),
        (film(5, 4, (0.0, 10.0), (-1.0, 3.0)), vec![(4, 0), (0, 3)]),
        (film(1, 1, (2.0, 4.0), (5.0, 6.0)), vec![(0, 0)]),
    ]
}

/// "a 4x3 image over x in [-8, 8], y in [-6, 6]".
fn describe(film: &Film) -> String {
    let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
    format!(
        "a {}x{} image over x in [{}, {}], y in [{}, {}]",
        film.width(),
        film.height(),
        x0.show(),
        x1.show(),
        y0.show(),
        y1.show()
    )
}

/// Checks `pixel_to_plane(film, px, py)`: the centre of pixel (`px`, `py`) on the
/// plane, `py` counted from the top row.
pub fn check_pixel_to_plane(
    f: impl Fn(&Film, u32, u32) -> Vec2 + Send + Sync + 'static,
) -> Outcome {
    pixel_to_plane_checked(Box::new(f))
}

/// [`check_pixel_to_plane`] for the answer as a trait object: compiled once, here, not
/// again for every closure a test passes (see [`super::harness`]).
fn pixel_to_plane_checked(
    f: Box<dyn Fn(&Film, u32, u32) -> Vec2 + Send + Sync>,
) -> Outcome {
    let cases: Vec<Case<PixelArgs>> = films()
        .into_iter()
        .flat_map(|(film, pixels)| {
            pixels.into_iter().map(move |(px, py)| {
                let case = format!("pixel ({px}, {py}) of {}", describe(&film));
                (case, (film, px, py))
            })
        })
        .collect();
    run(
        &cases,
        |&(film, px, py)| film.pixel_to_plane(px, py),
        move |(film, px, py)| f(&film, px, py),
        &[
            Mistake {
                looks_like: &gives(&|a: &PixelArgs| {
                    Some(plane_point(a, a.2 as f32, 0.5))
                }),
                hint: "py counts rows from the top of the image, the slide's formula counts \
                       them from the bottom: use y_pixel = height - 1 - py (the row flip)",
            },
            Mistake {
                looks_like: &gives(&|a: &PixelArgs| {
                    Some(plane_point(a, a.0.height() as f32 - a.2 as f32, 0.5))
                }),
                hint: "off by one row: the bottom row is y_pixel = 0, so y_pixel = height - 1 - py, \
                       not height - py",
            },
            Mistake {
                looks_like: &|&(film, px, py): &PixelArgs, got: &Vec2| {
                    // Square pixels of the columns' size, counted from the top or from
                    // the bottom edge.
                    let ((x_min, x_max), (y_min, y_max)) =
                        (film.x_extent(), film.y_extent());
                    let size = (x_max - x_min) / film.width() as f32;
                    let x = (px as f32 + 0.5) * size + x_min;
                    let from_top = y_max - (py as f32 + 0.5) * size;
                    let from_bottom =
                        ((film.height() - 1 - py) as f32 + 0.5) * size + y_min;
                    got.close(&Vec2::new(x, from_top))
                        || got.close(&Vec2::new(x, from_bottom))
                },
                hint: "the rows used the columns' pixel size: a pixel is (x_max - x_min) / width \
                       wide but (y_max - y_min) / height high, and the two differ when the pixels \
                       are not square (this film's are not)",
            },
            Mistake {
                looks_like: &gives(&|a: &PixelArgs| {
                    Some(plane_point(a, (a.0.height() - 1 - a.2) as f32, 0.0))
                }),
                hint: "that is the pixel's corner: the ray goes through its centre, so add 0.5 to \
                       the pixel index before dividing by the resolution",
            },
        ],
        "x = (px + 0.5) / width * (x_max - x_min) + x_min, and the same for y with \
         y_pixel = height - 1 - py",
    )
}

/// The arguments of `plane_to_pixel`: the film and the point on the plane.
type PlaneArgs = (Film, Vec2);

/// (sx, sy): the point's distance from the film's left and bottom edges, in pixels.
fn from_bottom_left(&(film, p): &PlaneArgs) -> Vec2 {
    let ((x_min, x_max), (y_min, y_max)) = (film.x_extent(), film.y_extent());
    Vec2::new(
        (p.x - x_min) / (x_max - x_min) * film.width() as f32,
        (p.y - y_min) / (y_max - y_min) * film.height() as f32,
    )
}

/// Checks `plane_to_pixel(film, p)`: continuous pixel coordinates of the plane point
/// `p`, rows counted from the top, a pixel centre at (px + 0.5, py + 0.5).
pub fn check_plane_to_pixel(
    f: impl Fn(&Film, Vec2) -> Vec2 + Send + Sync + 'static,
) -> Outcome {
    plane_to_pixel_checked(Box::new(f))
}

/// [`check_plane_to_pixel`] for the answer as a trait object: compiled once, here, not
/// again for every closure a test passes (see [`super::harness`]).
fn plane_to_pixel_checked(
    f: Box<dyn Fn(&Film, Vec2) -> Vec2 + Send + Sync>,
) -> Outcome {
    let mut cases: Vec<Case<PlaneArgs>> = Vec::new();
    for (film, pixels) in films() {
        let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
        let centres = pixels.iter().map(|&(px, py)| {
            let what = format!("the centre of pixel ({px}, {py})");
            (what, film.pixel_to_plane(px, py))
        });
        let corners = [
            ("the top-left corner".to_string(), Vec2::new(x0, y1)),
            ("the bottom-right corner".to_string(), Vec2::new(x1, y0)),
        ];
        let beyond = [(
            "a point right of the film, level with its middle".to_string(),
            Vec2::new(x1 + (x1 - x0) / 4.0, 0.5 * (y0 + y1)),
        )];
        for (what, p) in corners.into_iter().chain(beyond).chain(centres) {
            let case = format!("p = {}, {what} of {}", p.show(), describe(&film));
            cases.push((case, (film, p)));
        }
    }
    run(
        &cases,
        |&(film, p)| film.plane_to_pixel(p),
        move |(film, p)| f(&film, p),
        &[
            Mistake {
                looks_like: &gives(&|a: &PlaneArgs| Some(from_bottom_left(a))),
                hint: "rows count from the top of the image, but y grows upwards on the plane: \
                       the row is height - sy, where sy = (y - y_min) / (y_max - y_min) * height",
            },
            Mistake {
                looks_like: &gives(&|a: &PlaneArgs| {
                    let s = from_bottom_left(a);
                    Some(Vec2::new(s.x, a.0.height() as f32 - 1.0 - s.y))
                }),
                hint: "height - 1 - row flips whole row numbers; a continuous coordinate flips \
                       as height - sy (the top edge, sy = height, becomes 0)",
            },
            Mistake {
                looks_like: &gives(&|a: &PlaneArgs| {
                    let s = from_bottom_left(a);
                    Some(Vec2::new(s.x, a.0.height() as f32 - s.y) - 0.5)
                }),
                hint: "do not subtract the half pixel: in continuous coordinates the centre of \
                       pixel (px, py) is (px + 0.5, py + 0.5), and the corner (x_min, y_max) is \
                       (0, 0)",
            },
            Mistake {
                looks_like: &|a: &PlaneArgs, got: &Vec2| {
                    let s = from_bottom_left(a);
                    let right = Vec2::new(s.x, a.0.height() as f32 - s.y);
                    *got == got.floor()
                        && (got.close(&right.floor()) || got.close(&right.round()))
                },
                hint: "continuous coordinates, not the index of the pixel: do not round or \
                       floor them (the centre of pixel (0, 0) is (0.5, 0.5))",
            },
        ],
        "column = (x - x_min) / (x_max - x_min) * width; row = height - sy with \
         sy = (y - y_min) / (y_max - y_min) * height",
    )
}
