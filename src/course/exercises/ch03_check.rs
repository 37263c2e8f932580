//! The check of chapter 03's coding exercise: the cases, the reference
//! answer for each, and the hints for the typical mistakes. The student's function
//! is in `ch03.rs`, beside this file; the harness is `harness.rs`.

use glam::Vec2;

use super::harness::{Answer, Case, Exercise, Mistake, Outcome, gives, run};
use crate::camera::Film;

/// Coding exercise 3.1.
pub const PIXEL_TO_PLANE: Exercise = Exercise {
    number: "3.1",
    chapter: "03",
    chapter_title: "The orthographic camera",
    function: "pixel_to_plane",
    file: "src/course/exercises/ch03.rs",
};

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
