//! Lesson 10, the cameras of the path tracer (chapter 10_8): the thin lens with
//! aperture 0 is the pinhole camera bit for bit, its rays meet on the plane in focus
//! and its focus point lies in front of the eye at the focus distance; and the grey
//! furnace renders through the orthographic camera of Lecture 4.

use crate::common::pages::page;
use crate::lesson_10_path_tracing::settings;

use glam::{Vec2, Vec3};
use render_lessons::camera::{
    Camera, Film, Frame, OrthoCamera, PinholeCamera, ThinLensCamera,
};
use render_lessons::pathtrace::{Accumulator, PixelSampling, Sampling};
use render_lessons::ray::Ray;
use render_lessons::scenes::path_tracing::{Staged, cornell, grey_furnace};

// ---------------------------------------------------------------- pieces

#[test]
fn aperture_0_is_the_pinhole_camera_bit_for_bit() {
    let Staged { camera, .. } = cornell(20, 15).unwrap();
    let film = Film::new(20, 15, (-0.3, 0.3), (-0.2, 0.25)).unwrap();
    let frame = render_lessons::camera::Frame::look(
        Vec3::new(1.0, 2.0, 3.0),
        Vec3::new(0.3, -0.2, -1.0),
        Vec3::Y,
    )
    .unwrap();
    let pinhole = PinholeCamera::new(film, 1.7, frame).unwrap();
    let lens = ThinLensCamera::new(pinhole, 0.0, 5.0).unwrap();
    for y in 0..15 {
        for x in 0..20 {
            let centre = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            assert_eq!(
                lens.ray_through(centre, Vec2::new(0.3, 0.7)),
                pinhole.ray(x, y)
            );
        }
    }
    let _ = camera;
}

#[test]
fn thin_lens_rays_meet_on_the_plane_in_focus() {
    let film = Film::new(8, 8, (-0.5, 0.5), (-0.5, 0.5)).unwrap();
    let pinhole = PinholeCamera::at_origin(film, 1.0).unwrap();
    let lens = ThinLensCamera::new(pinhole, 0.2, 4.0).unwrap();
    let pixel = Vec2::new(2.3, 5.6);
    let centre_ray = lens.ray_through(pixel, Vec2::ZERO);
    let target = centre_ray.at(4.0 / -centre_ray.direction().z);
    for u in render_lessons::sampling::grid(4) {
        let r = lens.ray_through(pixel, u);
        assert!(r.origin().z == 0.0 && r.origin().length() <= 0.2 + 1e-6);
        let p = r.at((-4.0 - r.origin().z) / r.direction().z);
        assert!((p - target).length() < 1e-5, "{p} vs {target}");
    }
}

/// Where the lines of two rays come closest, in f64 (the lens rays of one pixel are
/// nearly parallel): the midpoint of the two closest points, and their distance.
fn closest_approach(a: &Ray, b: &Ray) -> (glam::DVec3, f64) {
    let (oa, ob) = (a.origin().as_dvec3(), b.origin().as_dvec3());
    let (da, db) = (a.direction().as_dvec3(), b.direction().as_dvec3());
    let w = oa - ob;
    let (k, d, e) = (da.dot(db), da.dot(w), db.dot(w));
    let denom = da.length_squared() * db.length_squared() - k * k;
    let s = (k * e - d * db.length_squared()) / denom;
    let t = (da.length_squared() * e - k * d) / denom;
    let (pa, pb) = (oa + s * da, ob + t * db);
    ((pa + pb) / 2.0, (pa - pb).length())
}

#[test]
fn the_thin_lens_focus_point_is_in_front_of_the_eye_at_the_focus_distance() {
    // A placed camera (eye away from the origin, looking down and to the side), screen
    // distance s = 1.7, focus distance z_f = 5: the page's p_f = s z_f / s.
    let (s, z_f) = (1.7, 5.0);
    let film = Film::new(20, 15, (-0.3, 0.3), (-0.2, 0.25)).unwrap();
    let eye = Vec3::new(1.0, 2.0, 3.0);
    let frame = Frame::look(eye, Vec3::new(0.3, -0.2, -1.0), Vec3::Y).unwrap();
    let pinhole = PinholeCamera::new(film, s, frame).unwrap();
    let lens = ThinLensCamera::new(pinhole, 0.3, z_f).unwrap();
    let w = frame.basis().w();
    for (x, y) in [(0u32, 0u32), (7, 11), (19, 14)] {
        let pixel = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
        // The point in focus as the page computes it, in world space.
        let screen_cam = pinhole.screen_point(pixel);
        assert!((screen_cam.z + s).abs() < 1e-6, "screen point z = -s");
        let focus = frame.point_to_world(screen_cam * (z_f / s));
        // In front of the eye (the camera looks along -w), at the focus distance.
        assert!(
            ((focus - eye).dot(w) + z_f).abs() < 1e-4,
            "(p_f - eye) . w = {}",
            (focus - eye).dot(w)
        );
        // The mistaken s z_f / s_z, with s_z = -s, is the mirror image behind the eye.
        let behind = frame.point_to_world(screen_cam * (z_f / screen_cam.z));
        assert!(((behind - eye).dot(w) - z_f).abs() < 1e-4);
        // Every lens ray of the pixel passes through p_f, ahead of its origin; where
        // it crosses the pinhole ray is p_f too; no ray comes near the point behind.
        let pinhole_ray = pinhole.ray(x, y);
        for u in render_lessons::sampling::grid(3) {
            let r = lens.ray_through(pixel, u);
            assert!((r.origin() - eye).dot(w).abs() < 1e-5, "starts on the lens");
            let t = r.t_closest_to(focus);
            assert!(t > 0.0, "p_f ahead of the lens ray: t = {t}");
            assert!((r.at(t) - focus).length() < 1e-4, "{} vs {focus}", r.at(t));
            let (meet, gap) = closest_approach(&r, &pinhole_ray);
            assert!(gap < 1e-4, "the lens ray misses the pinhole ray by {gap}");
            assert!((meet - focus.as_dvec3()).length() < 1e-2, "meets at {meet}");
            let miss = r.at(r.t_closest_to(behind).max(0.0));
            assert!((miss - behind).length() > 1.0);
        }
    }
    // The page states the formula with the positive screen distance.
    let text = page("10_8_thin_lens.md");
    assert!(text.contains(r"\mathbf{p}_f = \mathbf{s}\,\frac{z_f}{s}"));
}

/// The path tracer renders through the cameras of Lecture 4 too: the grey furnace
/// through an orthographic camera is 0.5 wherever the pixel sees only the sphere and
/// 1 (the environment) wherever it sees none of it; at pixel centres its rays are the
/// camera's own, bit for bit.
#[test]
fn the_grey_furnace_renders_through_an_orthographic_camera() {
    let Staged { scene, .. } = grey_furnace(4, 4, Vec3::ZERO).unwrap();
    let film = Film::new(24, 24, (-1.5, 1.5), (-1.5, 1.5)).unwrap();
    let frame = Frame::look(3.0 * Vec3::Z, -Vec3::Z, Vec3::Y).unwrap();
    let camera = Camera::Ortho(OrthoCamera::new(film, frame));
    let centre = |x: u32, y: u32| Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
    for (x, y) in [(0, 0), (5, 17), (23, 23), (12, 11)] {
        assert_eq!(
            camera.ray_through(centre(x, y), Vec2::splat(0.3)),
            camera.ray(x, y)
        );
    }
    let s = settings(Sampling::Cosine, Some(8), false);
    let mut acc = Accumulator::new(&camera, 3);
    let image = acc
        .render_pass(&scene, &camera, &s, PixelSampling::Jittered, 16)
        .unwrap();
    assert_eq!(acc.non_finite(), 0);
    let (mut inside, mut outside) = (0, 0);
    for y in 0..24 {
        for x in 0..24 {
            // The pixel's nearest and farthest points from the axis, in world units.
            let p = (centre(x, y) - Vec2::splat(12.0)) * 0.125;
            let (near, far) =
                (p.abs() - Vec2::splat(0.0625), p.abs() + Vec2::splat(0.0625));
            let value = image.get(x, y).unwrap();
            if far.length() < 1.0 {
                assert!(
                    (value - Vec3::splat(0.5)).abs().max_element() < 1e-6,
                    "{value}"
                );
                inside += 1;
            } else if near.max(Vec2::ZERO).length() > 1.0 {
                assert_eq!(value, Vec3::ONE, "({x}, {y})");
                outside += 1;
            }
        }
    }
    assert!(
        inside > 150 && outside > 150,
        "{inside} inside, {outside} outside"
    );
    // The sphere covers pi of the film's 9 square units: the mean is 1 - 0.5 pi / 9.
    let exact = 1.0 - 0.5 * std::f64::consts::PI / 9.0;
    assert!(
        (image.mean() - exact).abs() < 0.01,
        "{} vs {exact}",
        image.mean()
    );
    // A pinhole `Camera` renders as the thin lens of aperture 0, bit for bit.
    let pinhole = PinholeCamera::at_origin(
        Film::new(8, 6, (-1.0, 1.0), (-0.75, 0.75)).unwrap(),
        1.0,
    )
    .unwrap();
    let (u, pixel) = (Vec2::new(0.2, 0.9), Vec2::new(3.3, 4.7));
    let lens = ThinLensCamera::new(pinhole, 0.0, 1.0).unwrap();
    assert_eq!(
        Camera::Pinhole(pinhole).ray_through(pixel, u),
        Camera::ThinLens(lens).ray_through(pixel, u)
    );
}
