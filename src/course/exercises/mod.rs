//! The coding exercises: the student's functions, and the checks that grade them.
//!
//! One file per chapter, in which the student writes the functions the lesson is
//! about, two or more per lesson ([`check::ALL`] lists them).
//!
//! The files `chNN.rs` hold the student's functions, each a `todo!()` to begin with
//! (a check says `NOT STARTED` for it, and its test fails). [`check`] holds the
//! checks, which compare an implementation with the crate's reference code (the
//! default tests run them against the reference and against typical wrong answers). A check runs the student's function on a thread of its own, each
//! case within [`harness::CASE_TIME_LIMIT`], and catches its panics. `--mine`
//! ([`crate::course::mine`]) draws a lesson's picture with a passing function. Check
//! your work with
//!
//! ```text
//! cargo test --test exercises          # every exercise
//! cargo test --test exercises ch03     # chapter 03 only
//! ```

// Each check hands the student's function on boxed, its signature spelled out in
// full (`Box<dyn Fn(&Film, u32, u32) -> Vec2 + Send + Sync>`, see `harness`):
// clippy calls such types complex; here they are the exercise's own signature.
#![allow(clippy::type_complexity)]

pub mod answer;
pub mod ch01_check;
pub mod ch02_check;
pub mod ch03_check;
pub mod ch04_check;
pub mod ch05_check;
pub mod ch06_check;
pub mod ch07_check;
pub mod ch08_check;
pub mod ch09_check;
pub mod ch10_check;
pub mod ch11_check;
pub mod ch11_sah_check;
pub mod check;
pub mod harness;

pub mod ch01;
pub mod ch02;
pub mod ch03;
pub mod ch04;
pub mod ch05;
pub mod ch06;
pub mod ch07;
pub mod ch08;
pub mod ch09;
pub mod ch10;
pub mod ch11;

/// Every exercise checked on the student's code, in book order.
pub fn check_all() -> Vec<(check::Exercise, check::Outcome)> {
    use check::*;
    vec![
        (ROTATION_Y, check_rotation_y(ch01::rotation_y)),
        (COMPOSE, check_compose(ch01::compose)),
        (POINT_AT, check_point_at(ch02::point_at)),
        (T_CLOSEST, check_t_closest(ch02::t_closest)),
        (PIXEL_TO_PLANE, check_pixel_to_plane(ch03::pixel_to_plane)),
        (PLANE_TO_PIXEL, check_plane_to_pixel(ch03::plane_to_pixel)),
        (TO_WORLD, check_to_world(ch04::to_world)),
        (TO_LOCAL, check_to_local(ch04::to_local)),
        (CAMERA_BASIS, check_camera_basis(ch05::camera_basis)),
        (ORTHO_RAY, check_ortho_ray(ch05::ortho_ray)),
        (PINHOLE_RAY, check_pinhole_ray(ch06::pinhole_ray)),
        (PROJECT, check_project(ch06::project)),
        (RAY_PLANE_T, check_ray_plane_t(ch07::ray_plane_t)),
        (
            RAY_SPHERE_ROOTS,
            check_ray_sphere_roots(ch07::ray_sphere_roots),
        ),
        (
            MOLLER_TRUMBORE,
            check_moller_trumbore(ch07::moller_trumbore),
        ),
        (CLOSEST, check_closest(ch08::closest)),
        (LAMBERT, check_lambert(ch08::lambert)),
        (COVERS, check_covers(ch09::covers)),
        (
            PERSPECTIVE_WEIGHTS,
            check_perspective_weights(ch09::perspective_weights),
        ),
        (COSINE_SAMPLE, check_cosine_sample(ch10::cosine_sample)),
        (BOUNCE_WEIGHT, check_bounce_weight(ch10::bounce_weight)),
        (SLAB, check_slab(ch11::slab)),
        (SAH_COST, check_sah_cost(ch11::sah_cost)),
    ]
}
