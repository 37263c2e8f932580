//! Lesson 02: the ray r(t) = o + t d.

use crate::common;
use crate::examples::ray_model as lesson;

use clap::Parser;
use glam::Vec3;
use render_lessons::Error;
use render_lessons::error::Problem;
use render_lessons::ray::Ray;

/// The example's default ray: origin (1, 1, 0), direction (4, 3, 0).
fn book_ray() -> Ray {
    Ray::new(Vec3::new(1.0, 1.0, 0.0), Vec3::new(4.0, 3.0, 0.0)).unwrap()
}

#[test]
fn defaults_are_the_books_values() {
    let args = lesson::Args::parse_from(["02_ray_model"]);
    assert_eq!(Ray::new(args.origin, args.direction).unwrap(), book_ray());
}

#[test]
fn numbers() {
    insta::assert_snapshot!("numbers", lesson::numbers(&book_ray()));
}

#[test]
fn direction_is_normalised_so_t_is_distance() {
    let ray = Ray::new(Vec3::new(1.0, 1.0, 0.0), Vec3::new(4.0, 3.0, 0.0)).unwrap();
    assert_eq!(ray.direction(), Vec3::new(0.8, 0.6, 0.0));
    assert_eq!(ray.at(5.0), Vec3::new(5.0, 4.0, 0.0));
    // t = -5 lies behind the origin, 5 units back.
    assert_eq!(ray.at(-5.0), Vec3::new(-3.0, -2.0, 0.0));
}

#[test]
fn bad_rays_name_their_parameter() {
    assert_eq!(
        Ray::new(Vec3::ZERO, Vec3::ZERO),
        Err(Error::Value {
            param: "direction",
            problem: Problem::ZeroLength
        })
    );
    assert_eq!(
        Ray::new(Vec3::new(f32::NAN, 0.0, 0.0), Vec3::X),
        Err(Error::Value {
            param: "origin",
            problem: Problem::NotFinite
        })
    );
    assert_eq!(
        Ray::new(Vec3::ZERO, Vec3::new(0.0, f32::INFINITY, 0.0)),
        Err(Error::Value {
            param: "direction",
            problem: Problem::NotFinite
        })
    );
}

#[test]
fn very_short_and_very_long_directions_are_normalised_not_refused() {
    // |d| underflows (1e-30 squared is 0 in f32) or overflows (3e38 squared is
    // infinite): the direction is still well defined, and Ray::new scales it first.
    let diagonal = Vec3::splat(1.0 / 3f32.sqrt());
    // Between them, 3e-22 squared is subnormal but not 0 (checked below).
    for d in [
        Vec3::splat(1e-30),
        Vec3::splat(3e-22),
        Vec3::splat(3e38),
        Vec3::splat(f32::MIN_POSITIVE),
    ] {
        let ray = Ray::new(Vec3::ZERO, d).unwrap();
        assert!((ray.direction() - diagonal).length() < 1e-6, "{d}");
    }
    // The page's "components under about 1e-19": below sqrt(f32::MIN_POSITIVE) a
    // component's square is no longer a normal f32; and "off by parts in a thousand":
    // 3e-22's length, computed plainly from its squares, is 1.8e-3 too short (the
    // squares lose bits as subnormals).
    assert!((f32::MIN_POSITIVE.sqrt() / 1.08e-19 - 1.0).abs() < 0.01);
    let short = Vec3::splat(3e-22);
    let plain = f64::from(short.dot(short).sqrt()) / (3e-22 * 3f64.sqrt());
    assert!((1.5e-3..2.0e-3).contains(&(1.0 - plain)), "{plain}");
    for scale in [3e38, 3e-22] {
        let tilted = Ray::new(Vec3::ZERO, Vec3::new(scale, scale, 0.0)).unwrap();
        let expected = Vec3::new(1.0, 1.0, 0.0).normalize();
        assert!((tilted.direction() - expected).length() < 1e-6, "{scale:e}");
        assert!(
            (tilted.direction().length() - 1.0).abs() < 1e-6,
            "{scale:e}"
        );
    }
}

#[test]
fn an_unnormalised_ray_keeps_its_direction_and_counts_t_in_its_lengths() {
    let d = Vec3::new(0.0, 0.0, -0.5);
    let ray = Ray::new_unnormalised(Vec3::new(0.0, 0.0, 4.0), d).unwrap();
    assert_eq!(ray.direction(), d);
    assert_eq!(ray.at(2.0), Vec3::new(0.0, 0.0, 3.0)); // 2 lengths of d, distance 1
    assert_eq!(ray.t_closest_to(Vec3::new(1.0, 0.0, 0.0)), 8.0);
    assert_eq!(
        Ray::new_unnormalised(Vec3::ZERO, Vec3::ZERO),
        Err(Error::Value {
            param: "direction",
            problem: Problem::ZeroLength
        })
    );
    assert_eq!(
        Ray::new_unnormalised(Vec3::NAN, Vec3::X),
        Err(Error::Value {
            param: "origin",
            problem: Problem::NotFinite
        })
    );
    assert_eq!(
        Ray::new_unnormalised(Vec3::ZERO, Vec3::new(f32::INFINITY, 0.0, 0.0)),
        Err(Error::Value {
            param: "direction",
            problem: Problem::NotFinite
        })
    );
}

#[test]
fn an_unnormalised_ray_keeps_t_through_a_transform() {
    use render_lessons::ray::Interval;
    use render_lessons::shapes::{Instance, Shape};
    use render_lessons::transform::Transform;
    // The object ray (M^-1 o, M^-1 d), not normalised, finds the world ray's t in
    // object space: the instance's own answer (which normalises and rescales), to
    // rounding. Rays aimed inside the sphere's silhouette, where t is well
    // conditioned; 1e-5 relative.
    let placements = [
        Transform::rotation_y(0.7).then(Transform::translation(0.5, -0.2, 1.0)),
        Transform::scale(2.0, 2.0, 2.0),
        Transform::scale(2.0, 0.5, 1.5)
            .then(Transform::rotation_z(0.4))
            .then(Transform::translation(0.3, 0.1, -0.7)),
    ];
    let unit = Shape::from(common::unit_sphere());
    for m in placements {
        let instance = Instance::new(unit.clone(), m).unwrap();
        let to_object = instance.to_object();
        for i in 0..100 {
            let (a, b) = ((i % 10) as f32 / 10.0 - 0.45, (i / 10) as f32 / 10.0 - 0.45);
            let o = Vec3::new(3.0, 7.0, 9.0);
            let world = Ray::new(o, m.point(Vec3::new(a, b, 0.2)) - o).unwrap();
            let expected = instance.hit(&world, Interval::AHEAD).unwrap().t;
            let object = Ray::new_unnormalised(
                to_object.point(world.origin()),
                to_object.vector(world.direction()),
            )
            .unwrap();
            let t = unit.hit(&object, Interval::AHEAD).unwrap().t;
            assert!((t - expected).abs() <= 1e-5 * expected, "{t} vs {expected}");
        }
    }
}

#[test]
fn distance_along_the_ray_is_abs_t() {
    common::for_cases(2, 256, |rng| {
        let o = rng.point(100.0);
        let d = rng.point(10.0);
        let t = rng.range(-50.0, 50.0);
        if d.length() <= 1e-3 {
            return;
        }
        let ray = Ray::new(o, d).unwrap();
        let distance = (ray.at(t) - o).length();
        let tolerance = 1e-4 * (1.0 + t.abs() + o.length());
        assert!((distance - t.abs()).abs() <= tolerance);
        assert!((ray.t_closest_to(ray.at(t)) - t).abs() <= tolerance);
    });
}

#[test]
fn figure_draws() {
    let rgba = lesson::ray_figure(&book_ray()).unwrap().rgba();
    assert!(common::blue_pixels(&rgba) > 500, "the ray is drawn in blue");
}

/// The numbers `02_ray_model.md` works out by hand, computed again with `Ray`.
#[test]
fn lesson_02_worked_numbers() {
    let ray = Ray::new(Vec3::new(1.0, 1.0, 0.0), Vec3::new(0.8, 0.6, 0.0)).unwrap();
    // r(2.5) - o = (2, 1.5, 0), of length 2.5.
    let offset = ray.at(2.5) - ray.origin();
    assert!((offset - Vec3::new(2.0, 1.5, 0.0)).length() < 1e-6);
    // The reversed ray: r(2.5) = (1 - 2, 1 - 1.5, 0).
    let reversed =
        Ray::new(Vec3::new(1.0, 1.0, 0.0), Vec3::new(-0.8, -0.6, 0.0)).unwrap();
    assert!((reversed.at(2.5) - Vec3::new(-1.0, -0.5, 0.0)).length() < 1e-6);
    // The x axis is crossed at t = -5/3, at x = -1/3.
    let crossing = ray.at(-5.0 / 3.0);
    assert!(crossing.y.abs() < 1e-6);
    assert_eq!(format!("{:.3}", crossing.x), "-0.333");
}
