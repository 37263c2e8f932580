//! Your coding exercises, checked.
//!
//! One test per exercise runs its check on your function in
//! `src/course/exercises/chNN.rs` and fails, printing the exercise's number, the case,
//! the expected and the received answer and a hint, unless every case passes; a
//! function still `todo!()` fails as `NOT STARTED`. The tests are named after the
//! lesson and the exercise, `ch03::exercise_3_5_pixel_to_plane`, so that either
//! selects them:
//!
//! ```text
//! cargo test --test exercises                                 # all your exercises
//! cargo test --test exercises ch03                            # lesson 03's
//! cargo test --test exercises exercise_3_5_                   # one exercise
//! cargo test --test exercises summary -- --nocapture          # the table
//! ```
//!
//! This file holds your exercises' tests and nothing else, and a plain `cargo test`
//! does not run it (`test = false` in `Cargo.toml`): until you write them, your
//! exercises fail. The course's own tests of the checks and of the harness, which run
//! with every `cargo test`, are in `tests/exercise_checks/`.

use render_lessons::course::exercises::check::*;
use render_lessons::course::exercises::{self as yours, check_all};

/// Your exercise `$test` of lesson `$lesson`: `$exercise`'s check `$check` on your
/// function `$function`. A failed test prints the check's report (its `Err`), and no
/// backtrace of the harness even with `RUST_BACKTRACE=1`.
macro_rules! exercises {
    ($($lesson:ident { $($test:ident: $exercise:ident, $check:ident, $function:ident;)+ })+) => {
        $(
            mod $lesson {
                use super::*;
                $(
                    #[test]
                    fn $test() -> Result<(), Report> {
                        $exercise.expect_pass(&$check(yours::$lesson::$function))
                    }
                )+
            }
        )+
    };
}

exercises! {
    ch01 {
        exercise_1_5_rotation_y: ROTATION_Y, check_rotation_y, rotation_y;
        exercise_1_6_compose: COMPOSE, check_compose, compose;
    }
    ch02 {
        exercise_2_5_point_at: POINT_AT, check_point_at, point_at;
        exercise_2_6_t_closest: T_CLOSEST, check_t_closest, t_closest;
    }
    ch03 {
        exercise_3_5_pixel_to_plane: PIXEL_TO_PLANE, check_pixel_to_plane, pixel_to_plane;
        exercise_3_6_plane_to_pixel: PLANE_TO_PIXEL, check_plane_to_pixel, plane_to_pixel;
    }
    ch04 {
        exercise_4_5_to_world: TO_WORLD, check_to_world, to_world;
        exercise_4_6_to_local: TO_LOCAL, check_to_local, to_local;
    }
    ch05 {
        exercise_5_4_camera_basis: CAMERA_BASIS, check_camera_basis, camera_basis;
        exercise_5_5_ortho_ray: ORTHO_RAY, check_ortho_ray, ortho_ray;
    }
    ch06 {
        exercise_6_3_pinhole_ray: PINHOLE_RAY, check_pinhole_ray, pinhole_ray;
        exercise_6_4_project: PROJECT, check_project, project;
    }
    ch07 {
        exercise_7_16_ray_plane_t: RAY_PLANE_T, check_ray_plane_t, ray_plane_t;
        exercise_7_17_ray_sphere_roots: RAY_SPHERE_ROOTS, check_ray_sphere_roots, ray_sphere_roots;
        exercise_7_18_moller_trumbore: MOLLER_TRUMBORE, check_moller_trumbore, moller_trumbore;
    }
    ch08 {
        exercise_8_3_closest: CLOSEST, check_closest, closest;
        exercise_8_7_lambert: LAMBERT, check_lambert, lambert;
    }
    ch09 {
        exercise_9_6_covers: COVERS, check_covers, covers;
        exercise_9_7_perspective_weights: PERSPECTIVE_WEIGHTS, check_perspective_weights, perspective_weights;
    }
    ch10 {
        exercise_10_11_cosine_sample: COSINE_SAMPLE, check_cosine_sample, cosine_sample;
        exercise_10_12_bounce_weight: BOUNCE_WEIGHT, check_bounce_weight, bounce_weight;
    }
    ch11 {
        exercise_11_4_slab: SLAB, check_slab, slab;
        exercise_11_6_sah_cost: SAH_COST, check_sah_cost, sah_cost;
    }
}

/// The table of every exercise's status; never fails on your answers. See it with
/// `cargo test --test exercises summary -- --nocapture`.
#[test]
fn summary() {
    let results = check_all();
    let listed: Vec<&str> = results.iter().map(|(e, _)| e.number).collect();
    let all: Vec<&str> = ALL.iter().map(|e| e.number).collect();
    assert_eq!(
        listed, all,
        "check_all must run every exercise, in book order"
    );
    let passed = results.iter().filter(|(_, o)| *o == Outcome::Pass).count();
    println!("\nCoding exercises: {passed} of {} pass", results.len());
    for (exercise, outcome) in &results {
        println!("  {}", exercise.row(outcome));
    }
    println!();
}
