//! Lesson 06: the pinhole camera, the slide erratum, and handedness (S11) for both
//! cameras.

use crate::common::{self, bits, slide_film};
use crate::examples::pinhole_camera as lesson;

use clap::Parser;
use glam::{Vec2, Vec3};
use render_lessons::Error;
use render_lessons::camera::{Camera, Film, Frame, OrthoCamera, PinholeCamera};
use render_lessons::error::Problem;
use render_lessons::ray::Ray;

/// The example's flags with `extra` added, the frame they give and its two 4 x 3
/// cameras (at the origin, and placed by the frame).
fn example(extra: &[&str]) -> (lesson::Args, Frame, PinholeCamera, PinholeCamera) {
    let args = lesson::Args::parse_from([&["06_pinhole_camera"], extra].concat());
    let frame = Frame::look(args.position, args.direction, args.up).unwrap();
    let [at_origin, placed] = lesson::cameras(args.screen_distance, frame).unwrap();
    assert_eq!(
        at_origin,
        PinholeCamera::at_origin(slide_film(), 8.0).unwrap()
    );
    (args, frame, at_origin, placed)
}

#[test]
fn numbers() {
    let (args, _, at_origin, placed) = example(&[]);
    let text = lesson::numbers(&at_origin, &placed, args.direction, args.up);
    insta::assert_snapshot!("numbers", text);
}

#[test]
fn screen_point_is_c_plus_u_a_plus_v_b() {
    // The slide's vectors, written out independently of the film code.
    let (s, res_x, res_y) = (8.0f32, 4.0f32, 3.0f32);
    let a = Vec3::X * 16.0;
    let b = Vec3::Y * 12.0;
    let c = -8.0 * Vec3::X - 6.0 * Vec3::Y - s * Vec3::Z;
    let cam = PinholeCamera::at_origin(slide_film(), s).unwrap();
    for py in 0..3u32 {
        for px in 0..4u32 {
            let y_from_bottom = 2 - py; // the slides count rows from the bottom
            let (u, v) = (
                (px as f32 + 0.5) / res_x,
                (y_from_bottom as f32 + 0.5) / res_y,
            );
            assert!(
                (cam.screen_point(Film::pixel_centre(px, py)) - (c + u * a + v * b))
                    .length()
                    < 1e-6
            );
        }
    }
}

#[test]
fn pixel_0_0_ray_by_hand() {
    // Screen point (-6, 4, -8); |(-6, 4, -8)| = sqrt(116).
    let ray = PinholeCamera::at_origin(slide_film(), 8.0)
        .unwrap()
        .ray(0, 0);
    assert_eq!(ray.origin(), Vec3::ZERO);
    let expected = Vec3::new(-6.0, 4.0, -8.0) / 116f32.sqrt();
    assert!((ray.direction() - expected).length() < 1e-6);
}

#[test]
fn erratum_the_slides_repeated_orthographic_rays_are_parallel() {
    // Literally as on the arbitrary-pinhole slide: origin (x, y, 0), direction (0, 0,
    // -1).
    let literal = OrthoCamera::at_origin(slide_film());
    let pinhole = PinholeCamera::at_origin(slide_film(), 8.0).unwrap();
    let (a, b) = (literal.ray(0, 0), literal.ray(3, 2));
    assert_eq!(
        a.direction(),
        b.direction(),
        "parallel: no centre of projection"
    );
    // The literal rays do not pass through the eye e = 0; the pinhole rays all do.
    assert!(a.origin().length() > 1.0);
    for (px, py) in [(0, 0), (3, 2)] {
        let r = pinhole.ray(px, py);
        assert!((r.at(r.t_closest_to(Vec3::ZERO))).length() < 1e-6);
    }
    // Depth: a point and the same point ten times farther land on the same pixel with
    // the literal rays, but not with the pinhole.
    let (near, far) = (Vec3::new(4.0, 2.0, -5.0), Vec3::new(4.0, 2.0, -50.0));
    assert_eq!(literal.project(near), literal.project(far));
    let (pn, pf) = (
        pinhole.project(near).unwrap(),
        pinhole.project(far).unwrap(),
    );
    assert!((pn - pf).length() > 0.5);
    assert!(
        (pf - Vec2::new(2.0, 1.5)).length() < (pn - Vec2::new(2.0, 1.5)).length(),
        "far things move to the centre"
    );
}

#[test]
fn s11_right_is_right_and_up_is_up_for_both_cameras() {
    let frame = Frame::look(Vec3::ZERO, Vec3::NEG_Z, Vec3::Y).unwrap();
    let film = Film::new(64, 48, (-4.0, 4.0), (-3.0, 3.0)).unwrap();
    let cameras: [Camera; 2] = [
        OrthoCamera::new(film, frame).into(),
        PinholeCamera::new(film, 2.0, frame).unwrap().into(),
    ];
    let b = frame.basis();
    assert!((b.u().cross(b.v()) - b.w()).length() < 1e-6);
    for camera in cameras {
        let right = camera.project(Vec3::new(1.0, 0.0, -5.0)).unwrap();
        let up = camera.project(Vec3::new(0.0, 1.0, -5.0)).unwrap();
        assert!(right.x > 32.0, "{camera:?}: (1,0,-5) in the right half");
        assert!(
            up.y < 24.0,
            "{camera:?}: (0,1,-5) in the upper half (rows count from the top)"
        );
    }
}

#[test]
fn bad_screen_distance_is_named() {
    assert_eq!(
        PinholeCamera::at_origin(slide_film(), 0.0),
        Err(Error::Value {
            param: "screen distance",
            problem: Problem::NotPositive { value: 0.0 }
        })
    );
    assert_eq!(
        PinholeCamera::at_origin(slide_film(), -2.0)
            .unwrap_err()
            .param(),
        "screen distance"
    );
    assert_eq!(
        PinholeCamera::at_origin(slide_film(), f32::NAN),
        Err(Error::Value {
            param: "screen distance",
            problem: Problem::NotFinite
        })
    );
}

#[test]
fn every_pinhole_ray_passes_through_its_screen_point() {
    common::for_cases(6, 256, |rng| {
        let (d, k, p) = (rng.direction(), rng.direction(), rng.point(50.0));
        let s = rng.range(0.1, 20.0);
        let (w, h) = (rng.below(1, 40), rng.below(1, 40));
        let (px, py) = (rng.below(0, w), rng.below(0, h));
        if d.normalize().cross(k.normalize()).length() <= 1e-3 {
            return;
        }
        let frame = Frame::look(p, d, k).unwrap();
        let film = Film::new(w, h, (-2.0, 3.0), (-1.0, 1.5)).unwrap();
        let cam = PinholeCamera::new(film, s, frame).unwrap();
        let ray = cam.ray(px, py);
        let target = frame.point_to_world(cam.screen_point(Film::pixel_centre(px, py)));
        let t = ray.t_closest_to(target);
        assert!(t > 0.0, "the screen is in front of the eye");
        assert!((ray.at(t) - target).length() < 1e-4 * (1.0 + target.length()));
        assert!(ray.direction().is_finite() && ray.origin() == frame.position());
        // And projecting the screen point gives back the pixel centre.
        let back = cam.project(target).unwrap();
        assert!((back - Vec2::new(px as f32 + 0.5, py as f32 + 0.5)).length() < 1e-2);
    });
}

#[test]
fn side_by_side_orthographic_sees_only_floor_and_pinhole_sees_the_sky() {
    let (args, frame, ..) = example(&["--view-width", "64"]);
    let views =
        lesson::views(frame, args.view_width, args.screen_distance * 0.5).unwrap();
    let image = lesson::side_by_side(&views).unwrap();
    let sky = glam::Vec3::new(0.6, 0.75, 0.95);
    // Every orthographic ray points along d = (0, -1, -2): all of them reach the floor.
    assert!((0..64).all(|x| image.get(x, 0).unwrap() != sky));
    // The pinhole's top row looks above the horizon.
    assert!((64..128).all(|x| image.get(x, 0).unwrap() == sky));
}

#[test]
fn figure_draws() {
    let rgba = lesson::fan_figure(&example(&[]).2).unwrap().rgba();
    assert!(common::blue_pixels(&rgba) > 300);
}

/// The numbers `06_pinhole_camera.md` and `06_1_placed_pinhole.md` work out by hand:
/// lesson 03's film [-8, 8] x [-6, 6] at 4 x 3 pixels and screen distance 8.
#[test]
fn lesson_06_worked_numbers() {
    let degrees = |x: f64| x.to_degrees();
    // Pixel (0, 0): u = 0.5/4, v = 2.5/3 of the film, the screen point (-6, 4, -8).
    let (u, v) = (0.5f64 / 4.0, 2.5f64 / 3.0);
    assert_eq!(format!("{u:.3} {v:.4}"), "0.125 0.8333");
    assert_eq!(-8.0 + u * 16.0, -6.0);
    assert!((-6.0 + v * 12.0 - 4.0).abs() < 1e-12);
    // The field of view at screen distance 8, and at 4.
    assert_eq!(
        format!("{:.1}", degrees(2.0 * (6.0f64 / 8.0).atan())),
        "73.7"
    );
    assert_eq!(
        format!("{:.1}", degrees(2.0 * (6.0f64 / 4.0).atan())),
        "112.6"
    );
    // Exercise: (1.5, -1) on the orthographic film, in pixel units.
    assert_eq!((1.5 + 8.0) / 16.0 * 4.0, 2.375);
    assert_eq!((-1.0 + 6.0) / 12.0 * 3.0, 1.25);
    // 06_1: the placed camera looks down at atan(1/2), and the top row is atan(4/8) up.
    assert_eq!(format!("{:.1}", degrees(0.5f64.atan())), "26.6");
    assert_eq!(format!("{:.2}", degrees((4.0f64 / 8.0).atan())), "26.57");
    // 06_1: vfov 60° on 4 x 3 pixels reaches tan 30° up and 4/3 of that across.
    let up = 30f64.to_radians().tan();
    assert_eq!(format!("{up:.4} {:.4}", up * 4.0 / 3.0), "0.5774 0.7698");
}

#[test]
fn mine_draws_the_pinhole_view_with_the_given_pinhole_ray() {
    // The crate's pinhole ray, in the shape of exercise 6.3, draws the right half of
    // the lesson's comparison, bit for bit.
    fn reference(film: &Film, s: f32, frame: &Frame, px: u32, py: u32) -> (Vec3, Vec3) {
        let ray = PinholeCamera::new(*film, s, *frame).unwrap().ray(px, py);
        (ray.origin(), ray.direction())
    }
    let args = lesson::Args::parse_from(["06_pinhole_camera", "--view-width", "64"]);
    let frame = Frame::look(args.position, args.direction, args.up).unwrap();
    let s = args.screen_distance * 0.5;
    let mine = lesson::my_pinhole_view(frame, 64, s, reference).unwrap();
    let both = lesson::side_by_side(&lesson::views(frame, 64, s).unwrap()).unwrap();
    for y in 0..mine.height() {
        for x in 0..mine.width() {
            assert_eq!(mine.get(x, y), both.get(64 + x, y), "pixel ({x}, {y})");
        }
    }
}

#[test]
fn row_rays_are_the_slides_rays_bit_for_bit() {
    // Lesson 08's camera, a camera at the origin (p = 0: B 0 + p is then -0 or 0 by
    // the signs of B), one placed at -0 coordinates, and a tilted one far away.
    let cameras = [
        *render_lessons::scenes::still_life_pinhole(96, 54)
            .unwrap()
            .pinhole()
            .unwrap(),
        PinholeCamera::at_origin(slide_film(), 8.0).unwrap(),
        PinholeCamera::new(
            slide_film(),
            3.0,
            Frame::look(
                Vec3::new(-0.0, 0.0, -0.0),
                Vec3::new(1.0, -2.0, -0.5),
                Vec3::Y,
            )
            .unwrap(),
        )
        .unwrap(),
        PinholeCamera::look_at(
            Vec3::new(1e4, -3e3, 7.5),
            Vec3::new(0.3, 0.2, -0.1),
            Vec3::new(0.1, 1.0, 0.2),
            37.0,
            31,
            17,
        )
        .unwrap(),
    ];
    let ortho = Camera::from(OrthoCamera::new(slide_film(), *cameras[2].frame()));
    for py in 0..slide_film().height() {
        let mut rays = ortho.row(py);
        for px in 0..slide_film().width() {
            assert_eq!(bits(&rays.next_ray()), bits(&ortho.ray(px, py)));
        }
    }
    for camera in cameras {
        let lens = Camera::from(camera).with_lens(0.0, 1.0).unwrap();
        for py in 0..camera.film().height() {
            for px in 0..camera.film().width() {
                let readable = bits(&camera.ray(px, py));
                let centre = render_lessons::camera::Film::pixel_centre(px, py);
                // The slide's ray, from the eye at the camera-space origin, carried
                // to the world whole: the eye made once (B 0 + p) changes no bit.
                let screen = camera.screen_point(centre);
                let slide = camera.frame().ray_to_world(
                    &Ray::new_unnormalised(Vec3::ZERO, screen.normalize()).unwrap(),
                );
                assert_eq!(bits(&slide), readable);
                assert_eq!(bits(&Camera::from(camera).ray(px, py)), readable);
                assert_eq!(bits(&lens.ray(px, py)), readable);
            }
            let whole = Camera::from(camera);
            let (mut rays, mut lens_rays) = (whole.row(py), lens.row(py));
            let row: Vec<_> = (0..camera.film().width())
                .map(|_| bits(&rays.next_ray()))
                .collect();
            let lens_row: Vec<_> = (0..camera.film().width())
                .map(|_| bits(&lens_rays.next_ray()))
                .collect();
            assert_eq!(lens_row, row, "row {py} through a lens of aperture 0");
            let readable: Vec<_> = (0..camera.film().width())
                .map(|px| bits(&camera.ray(px, py)))
                .collect();
            assert_eq!(row, readable, "row {py}");
        }
    }
}
