//! Lesson 10: no NaN and no infinity. Radiance is finite for random rays, grazing rays,
//! edge-on lights and rays far out nearly parallel to the floor, under any sampling
//! strategy, in every scene with any flags.

use crate::common;
use crate::lesson_10_path_tracing::settings;

use glam::Vec3;
use render_lessons::pathtrace::{
    Accumulator, PixelSampling, Sampling, Settings, SphereSampling, radiance,
};
use render_lessons::ray::Ray;
use render_lessons::rng::Rng;
use render_lessons::scene::Scene;
use render_lessons::scenes::path_tracing::{
    Staged, cornell, grey_furnace, interior_furnace, two_lights,
};
use render_lessons::spawn::Offset;

// ---------------------------------------------------------------- no NaN

/// Any sampling strategy, sphere-light sampling, depth and roulette.
fn any_sampling(rng: &mut common::Rng) -> Settings {
    let (s, area, rr, depth) =
        (rng.below(0, 4), rng.coin(), rng.coin(), rng.below(0, 3));
    Settings {
        sampling: [
            Sampling::UniformHemisphere,
            Sampling::Cosine,
            Sampling::NextEvent,
            Sampling::Mis,
        ][s as usize],
        sphere_lights: if area {
            SphereSampling::Area
        } else {
            SphereSampling::Cone
        },
        max_depth: [Some(1), Some(8), None][depth as usize].or(if rr {
            None
        } else {
            Some(8)
        }),
        russian_roulette: rr,
        offset: Offset::Scaled,
    }
}

fn all_scenes() -> Vec<Scene> {
    vec![
        cornell(4, 4).unwrap().scene,
        interior_furnace(4, 4).unwrap().scene,
        grey_furnace(4, 4, Vec3::ZERO).unwrap().scene,
        two_lights(4, 4).unwrap().scene,
    ]
}

fn assert_finite(scene: &Scene, ray: Ray, s: &Settings, seed: u64) {
    let mut rng = Rng::for_pixel(seed, 0, 0);
    for _ in 0..16 {
        let l = radiance(scene, ray, &mut rng, s);
        assert!(
            l.is_finite() && l.min_element() >= 0.0,
            "{l} for {ray:?}, {s:?}"
        );
    }
}

#[test]
fn radiance_is_finite_for_random_rays() {
    let scenes = all_scenes();
    common::for_cases(10, 64, |rng| {
        let s = any_sampling(rng);
        let which = rng.below(0, 4) as usize;
        let (o, d, seed) = (rng.point(1.0), rng.point(1.0), rng.bits64());
        let scene = &scenes[which];
        // Origins inside the Cornell box for it, near the origin otherwise.
        let origin = if which == 0 {
            Vec3::new(50.0, 40.0, 80.0) + o * Vec3::new(45.0, 38.0, 75.0)
        } else {
            o * 0.9
        };
        if d.length() <= 1e-3 {
            return;
        }
        assert_finite(scene, Ray::new(origin, d).unwrap(), &s, seed);
    });
}

#[test]
fn radiance_is_finite_for_grazing_rays_and_edge_on_lights() {
    let Staged { scene: cornell, .. } = cornell(4, 4).unwrap();
    let Staged { scene: lights, .. } = two_lights(4, 4).unwrap();
    common::for_cases(1010, 64, |rng| {
        let s = any_sampling(rng);
        let (x, z) = (rng.range(1.0, 99.0), rng.range(0.0, 170.0));
        let (t, seed) = (rng.range(-1.0, 1.0), rng.bits64());
        // In the plane of the ceiling light, along the floor, along the walls.
        let light_y = 81.6 - render_lessons::scenes::path_tracing::CORNELL_LIGHT_GAP;
        let rays = [
            Ray::new(Vec3::new(x, light_y, z), Vec3::new(t, 0.0, 1.0)).unwrap(),
            Ray::new(Vec3::new(x, 0.0, z), Vec3::new(1.0, 0.0, t)).unwrap(),
            Ray::new(Vec3::new(x, 1e-6, z), Vec3::new(t, -1e-7, 1.0)).unwrap(),
            Ray::new(Vec3::new(1.0, 40.0, z), Vec3::new(0.0, t, 1.0)).unwrap(),
            // Tangent to the mirror sphere (centre (27, 16.5, 47), radius 16.5).
            Ray::new(Vec3::new(27.0 + 16.5, 16.5, z), Vec3::new(0.0, t, 1.0)).unwrap(),
            // Through the glass sphere near its rim.
            Ray::new(
                Vec3::new(73.0 + 16.5 * t.abs().sqrt(), 16.5, 200.0),
                -Vec3::Z,
            )
            .unwrap(),
        ];
        for ray in rays {
            assert_finite(&cornell, ray, &s, seed);
        }
        // Tangent to the small light, and grazing the floor towards both lights.
        let tangent = Ray::new(
            Vec3::new(-1.5 + 0.05, 1.0, -3.0),
            Vec3::new(0.0, t * 1e-3, 1.0),
        )
        .unwrap();
        assert_finite(&lights, tangent, &s, seed);
        let graze = Ray::new(
            Vec3::new(x - 50.0, 1e-5, z - 85.0),
            Vec3::new(t, -1e-6, 1.0),
        )
        .unwrap();
        assert_finite(&lights, graze, &s, seed);
    });
}

#[test]
fn radiance_is_finite_for_rays_far_out_and_nearly_parallel_to_the_floor() {
    let rays = [
        Ray::new(Vec3::new(3e38, 1e28, 0.0), Vec3::new(1.0, -1e-10, 0.0)).unwrap(),
        Ray::new(Vec3::new(-3e38, 1e-30, 3e38), Vec3::new(-1.0, -1e-38, 1.0)).unwrap(),
        Ray::new(Vec3::new(0.0, 1e-30, 0.0), Vec3::new(1.0, -1e-38, 0.0)).unwrap(),
    ];
    for scene in all_scenes() {
        for sampling in [
            Sampling::UniformHemisphere,
            Sampling::Cosine,
            Sampling::NextEvent,
            Sampling::Mis,
        ] {
            for ray in rays {
                assert_finite(&scene, ray, &settings(sampling, Some(4), true), 3);
            }
        }
    }
}

#[test]
fn no_non_finite_samples_in_any_scene_with_any_flags() {
    let scenes = [
        cornell(12, 9),
        two_lights(12, 9),
        interior_furnace(6, 6),
        grey_furnace(6, 6, Vec3::ZERO),
    ];
    for made in scenes {
        let Staged { scene, camera } = made.unwrap();
        for sampling in [
            Sampling::UniformHemisphere,
            Sampling::Cosine,
            Sampling::NextEvent,
            Sampling::Mis,
        ] {
            for rr in [false, true] {
                for pixels in [PixelSampling::Independent, PixelSampling::Jittered] {
                    let s = settings(sampling, Some(6), rr);
                    let mut acc = Accumulator::new(&camera, 11);
                    acc.render_pass(&scene, &camera, &s, pixels, 4).unwrap();
                    assert_eq!(acc.non_finite(), 0, "{sampling:?} rr {rr} {pixels:?}");
                }
            }
        }
    }
}
