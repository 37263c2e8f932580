//! Chart 9: what robustness costs a ray caster, measured, not guessed.
//!
//! Lesson 08's scene (a plane, three spheres, a box, a triangle) is cast k times
//! over (k copies of the list, one behind the other), by two casters with the same
//! structure: the crate's robust one (`raycast::shadowless`: stable sphere roots,
//! watertight triangles, NaN-safe slabs) and the plain reference of
//! [`super::plain`] (the textbook tests). Time per ray against the number of
//! primitives is a line: its slope is the cost of one primitive test, its height at
//! 0 the cost of the ray itself (making it, the per-ray set-up, the hit record).
//! The ratio of the two slopes is the robustness tax per test.

use glam::Vec3;

use super::machine::interleaved_min;
use super::plain::PlainScene;
use super::{Measured, Quality};
use crate::course::chart::{Chart, Scale, log_log_slope};
use crate::course::report::{BookNumbers, Quoted};
use crate::error::{Error, Problem, Result};
use crate::ray::Ray;
use crate::raycast::shadowless;
use crate::scene::{Object, Scene};
use crate::scenes::{still_life, still_life_pinhole};

/// Lesson 08's objects `copies` times, each copy 20 units further back.
fn copies(copies: u32) -> Result<Scene> {
    let mut objects: Vec<Object> = Vec::new();
    for k in 0..copies {
        let shift = Vec3::new(0.0, 0.0, -20.0 * k as f32);
        objects.extend(still_life(shift)?.objects().iter().cloned());
    }
    Scene::new(objects, still_life(Vec3::ZERO)?.background())
}

/// Nanoseconds per ray of `cast` over `rays`, the fastest of `rounds`, for each
/// caster in turn (interleaved).
fn ns_per_ray(
    rays: &[Ray],
    rounds: u32,
    robust: &Scene,
    plain: &PlainScene,
) -> [f64; 2] {
    let times = interleaved_min(
        rounds,
        &mut [
            &mut || {
                std::hint::black_box(
                    rays.iter().map(|r| shadowless(robust, r)).sum::<Vec3>(),
                );
            },
            &mut || {
                std::hint::black_box(
                    rays.iter().map(|r| plain.shadowless(r)).sum::<Vec3>(),
                );
            },
        ],
    );
    let ns = |i: usize| times[i].as_secs_f64() * 1e9 / rays.len().max(1) as f64;
    [ns(0), ns(1)]
}

/// Measures chart 9.
pub fn measure(quality: Quality) -> Result<Measured> {
    let (width, height) = quality.pick((240, 135), (960, 540));
    let camera = still_life_pinhole(width, height)?;
    let rays: Vec<Ray> = (0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .map(|(x, y)| camera.ray(x, y))
        .collect();
    let rounds = quality.pick(3, 7);
    let (mut robust, mut plain) = (Vec::new(), Vec::new());
    for k in [1, 2, 4, 8, 16] {
        let scene = copies(k)?;
        let textbook = PlainScene::new(&scene).ok_or(Error::Value {
            param: "scene",
            problem: Problem::Invalid {
                reason: "has a shape the plain caster does not know",
            },
        })?;
        let n = scene.objects().len() as f64;
        let [r, p] = ns_per_ray(&rays, rounds, &scene, &textbook);
        robust.push((n, r));
        plain.push((n, p));
    }
    let slope = |s: &[(f64, f64)]| {
        let (a, b) = (s[0], s[s.len() - 1]);
        (b.1 - a.1) / (b.0 - a.0)
    };
    let (sr, sp) = (slope(&robust), slope(&plain));
    let at_zero = |s: &[(f64, f64)], k: f64| s[0].1 - k * s[0].0;
    let findings = vec![
        format!(
            "one primitive test costs {sr:.2} ns robust, {sp:.2} ns plain: the robustness tax is {:.2}x per test",
            sr / sp
        ),
        format!(
            "the ray itself (camera ray, per-ray set-up, hit record) costs {:.1} ns robust, {:.1} ns plain",
            at_zero(&robust, sr),
            at_zero(&plain, sp)
        ),
        format!(
            "at lesson 08's 6 primitives the whole robust cast takes {:.2}x the plain one",
            robust[0].1 / plain[0].1
        ),
        format!(
            "log-log slopes (1 = time proportional to the primitives): robust {:.2}, plain {:.2}",
            log_log_slope(&robust).unwrap_or(f64::NAN),
            log_log_slope(&plain).unwrap_or(f64::NAN)
        ),
    ];
    let mut table = Quoted::new(
        "tax",
        true,
        &[
            "primitives",
            "robust (ns/ray)",
            "plain (ns/ray)",
            "robust / plain",
        ],
    );
    for (r, p) in robust.iter().zip(&plain) {
        table = table.row(vec![
            format!("{}", r.0),
            format!("{:.1}", r.1),
            format!("{:.1}", p.1),
            format!("{:.2}", r.1 / p.1),
        ]);
    }
    let quoted = BookNumbers::default()
        .table(table)
        .value("per_test_robust", true, format!("{sr:.2}"))
        .value("per_test_plain", true, format!("{sp:.2}"))
        .value("per_test_tax", true, format!("{:.2}", sr / sp))
        .value(
            "per_ray_robust",
            true,
            format!("{:.1}", at_zero(&robust, sr)),
        )
        .value("per_ray_plain", true, format!("{:.1}", at_zero(&plain, sp)))
        .value(
            "lesson08_tax",
            true,
            format!("{:.2}", robust[0].1 / plain[0].1),
        );
    let chart = Chart::new(
        "9. The robustness tax: time per primary ray against primitives in the list",
        ("primitives tested per ray", Scale::Log),
        ("ns per ray (1 thread)", Scale::Log),
    )
    .with("robust (this crate)", robust)
    .with("plain (textbook tests)", plain);
    Ok(Measured {
        chart,
        findings,
        quoted,
    })
}
