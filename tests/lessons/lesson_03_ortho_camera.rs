//! Lesson 03: the orthographic camera at the origin.

use crate::common::{self, slide_camera};
use crate::examples::ortho_camera as lesson;

use clap::Parser;
use glam::{Vec2, Vec3};
use render_lessons::Error;
use render_lessons::camera::{Film, OrthoCamera};
use render_lessons::error::Problem;
use render_lessons::limits::MAX_RESOLUTION;

#[test]
fn numbers() {
    insta::assert_snapshot!("numbers", lesson::numbers(&slide_camera()));
}

#[test]
fn the_flags_default_to_the_slide_camera() {
    let args = lesson::Args::parse_from(["03_ortho_camera"]);
    let (x, y) = ((args.x_min, args.x_max), (args.y_min, args.y_max));
    let cam = lesson::camera(args.width, args.height, x, y).unwrap();
    assert_eq!(cam, slide_camera());
}

#[test]
fn a_long_table_says_how_many_pixels_it_leaves_out() {
    let cam =
        OrthoCamera::at_origin(Film::new(8, 6, (-8.0, 8.0), (-6.0, 6.0)).unwrap());
    let text = lesson::numbers(&cam);
    assert_eq!(text.lines().filter(|l| l.starts_with('(')).count(), 24);
    assert!(text.ends_with("... (24 more pixels)\n"));
}

#[test]
fn pixel_0_0_is_the_slides_ray() {
    let ray = slide_camera().ray(0, 0);
    assert_eq!(ray.origin(), Vec3::new(-6.0, 4.0, 0.0));
    assert_eq!(ray.direction(), Vec3::new(0.0, 0.0, -1.0));
}

#[test]
fn the_literal_slide_formula_counts_rows_from_the_bottom() {
    // The slide's formula with y_pixel = 0 gives the bottom row, y = -4: only with
    // row 0 at the top does pixel (0,0) land at y = 4, as the slide says.
    let (x_pixel, y_pixel, res_x, res_y) = (0.0f32, 0.0f32, 4.0f32, 3.0f32);
    let literal = Vec2::new(
        (x_pixel + 0.5) / res_x * 16.0 - 8.0,
        (y_pixel + 0.5) / res_y * 12.0 - 6.0,
    );
    assert_eq!(literal, Vec2::new(-6.0, -4.0));
    assert_eq!(slide_camera().ray(0, 2).origin(), literal.extend(0.0));
    // The film counts rows from the top: the top row's centre is 0.5 pixels down.
    let top_left = slide_camera().film().film_point(Vec2::new(0.5, 0.5));
    assert_eq!(top_left, Vec2::new(-6.0, 4.0));
}

#[test]
fn pixel_centres_round_trip_through_the_plane() {
    let film = Film::new(7, 5, (-3.0, 11.0), (2.0, 4.5)).unwrap();
    for y in 0..5 {
        for x in 0..7 {
            let back = film.plane_to_pixel(film.pixel_to_plane(x, y));
            assert!(
                (back - Vec2::new(x as f32 + 0.5, y as f32 + 0.5))
                    .abs()
                    .max_element()
                    < 1e-5
            );
        }
    }
}

#[test]
fn bad_films_name_their_parameter() {
    let x = (-8.0, 8.0);
    let y = (-6.0, 6.0);
    assert_eq!(
        Film::new(0, 3, x, y),
        Err(Error::Value {
            param: "width",
            problem: Problem::Resolution {
                value: 0,
                max: MAX_RESOLUTION
            }
        })
    );
    assert_eq!(
        Film::new(4, MAX_RESOLUTION + 1, x, y),
        Err(Error::Value {
            param: "height",
            problem: Problem::Resolution {
                value: MAX_RESOLUTION + 1,
                max: MAX_RESOLUTION
            }
        })
    );
    assert_eq!(
        Film::new(4, 3, (1.0, 1.0), y).unwrap_err().param(),
        "x extent"
    );
    assert_eq!(
        Film::new(4, 3, x, (6.0, -6.0)).unwrap_err().param(),
        "y extent"
    );
    assert_eq!(
        Film::new(4, 3, (f32::NAN, 1.0), y),
        Err(Error::Value {
            param: "x extent",
            problem: Problem::NotFinite
        })
    );
    assert_eq!(
        Film::new(4, 3, (-f32::MAX, f32::MAX), y)
            .unwrap_err()
            .param(),
        "x extent"
    );
}

#[test]
fn every_ray_starts_inside_the_plane_and_points_down_minus_z() {
    common::for_cases(3, 256, |rng| {
        let (w, h) = (rng.below(1, 64), rng.below(1, 64));
        let (x0, dx) = (rng.range(-100.0, 100.0), rng.range(0.01, 100.0));
        let (y0, dy) = (rng.range(-100.0, 100.0), rng.range(0.01, 100.0));
        let (px, py) = (rng.below(0, w), rng.below(0, h));
        let film = Film::new(w, h, (x0, x0 + dx), (y0, y0 + dy)).unwrap();
        let ray = OrthoCamera::at_origin(film).ray(px, py);
        let o = ray.origin();
        assert!(o.x > x0 && o.x < x0 + dx && o.y > y0 && o.y < y0 + dy && o.z == 0.0);
        assert_eq!(ray.direction(), Vec3::NEG_Z);
    });
}

#[test]
fn origin_image_is_green_at_the_top_and_red_at_the_right() {
    let film = Film::new(32, 24, (-8.0, 8.0), (-6.0, 6.0)).unwrap();
    let image = lesson::origin_image(&film).unwrap();
    let (top_left, bottom_left, top_right) = (
        image.get(0, 0).unwrap(),
        image.get(0, 23).unwrap(),
        image.get(31, 0).unwrap(),
    );
    assert!(top_left.y > 0.95 && bottom_left.y < 0.05);
    assert!(top_left.x < 0.05 && top_right.x > 0.95);
}

#[test]
fn figures_draw() {
    let cam = slide_camera();
    for d in [
        lesson::plane_figure(cam.film()).unwrap(),
        lesson::rays_figure(&cam).unwrap(),
    ] {
        assert!(common::red_pixels(&d.rgba()) > 200);
    }
}

/// The numbers `03_ortho_camera.md` works out by hand: on a 3 x 3 film over
/// [-8, 8] x [-6, 6] the middle pixel's centre, 1.5 pixels in, is the plane's centre,
/// and its neighbours are 16/3 apart in x.
#[test]
fn lesson_03_worked_numbers() {
    let (x, y) = (1.5f64 / 3.0 * 16.0 - 8.0, 1.5f64 / 3.0 * 12.0 - 6.0);
    assert_eq!((x, y), (0.0, 0.0));
    assert_eq!(format!("{:.3}", 16.0f64 / 3.0), "5.333");
    assert_eq!(MAX_RESOLUTION, 16384, "the largest width or height");
}

#[test]
fn mine_draws_the_origin_image_with_the_given_pixel_to_plane() {
    // The crate's formula, in the shape of exercise 3.5, draws the lesson's image.
    fn reference(film: &Film, px: u32, py: u32) -> Vec2 {
        film.pixel_to_plane(px, py)
    }
    let film = Film::new(32, 24, (-8.0, 8.0), (-6.0, 6.0)).unwrap();
    let mine = lesson::my_origin_image(&film, reference).unwrap();
    assert_eq!(mine, lesson::origin_image(&film).unwrap());
}
