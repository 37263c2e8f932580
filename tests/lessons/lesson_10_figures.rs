//! Lesson 10's figures: the recorded paths of the path figure are the estimator's
//! own, lie on their objects and sample lights only at diffuse vertices; the figures
//! draw; and each step's figure is what its command writes.

use crate::common::pages::page;
use crate::common::{bits, blue_pixels};
use crate::examples::path_tracing as lesson;
use crate::lesson_10_path_tracing::{render, settings};

use crate::examples::book_figures_10 as figures;

use clap::Parser;

use glam::{Vec2, Vec3};
use render_lessons::course::record::record_path;
use render_lessons::material::Material;
use render_lessons::pathtrace::{
    Accumulator, At, Path, PixelSampling, Sampling, Settings, radiance,
};
use render_lessons::rng::Rng;
use render_lessons::scenes::path_tracing::{Staged, cornell};

// ---------------------------------------------------------------- figures

/// The path figure's paths are recorded from the estimator itself: watching the
/// estimator's `Path` vertex by vertex (as `record_path` and the variance measurement
/// do) gives, bit for bit, the sample the plain `radiance` returns for the same
/// pixel, seed and settings, the first sample the accumulator adds to that pixel,
/// and leaves the random stream where `radiance` leaves it.
#[test]
fn the_recorded_paths_of_the_figure_are_the_estimators_paths() {
    let Staged { scene, camera } = cornell(160, 120).unwrap();
    for s in [
        settings(Sampling::NextEvent, Some(8), true),
        Settings::default(),
    ] {
        let mut acc = Accumulator::new(&camera, 1);
        let first = acc
            .render_pass(&scene, &camera, &s, PixelSampling::Independent, 1)
            .unwrap();
        let mut compared = 0;
        for y in (0..120).step_by(3) {
            for x in (0..160).step_by(3) {
                let path = record_path(&scene, &camera, &s, 1, (x, y));
                let mut rng = Rng::for_pixel(1, x, y);
                let position = Vec2::new(x as f32, y as f32) + rng.next_vec2();
                let ray = camera.ray_through(position, rng.next_vec2());
                assert_eq!(path.eye, ray.origin());
                let mut watched = rng;
                let expected = radiance(&scene, ray, &mut rng, &s);
                let vertices: Vec<_> =
                    Path::new(&scene, ray, &mut watched, &s).collect();
                let observed = vertices
                    .iter()
                    .fold(Vec3::ZERO, |sum, v| sum + v.emitted + v.direct);
                assert_eq!(bits(&path.radiance), bits(&expected), "pixel ({x}, {y})");
                assert_eq!(bits(&observed), bits(&expected), "pixel ({x}, {y})");
                assert_eq!(watched.next_u32(), rng.next_u32(), "pixel ({x}, {y})");
                let surfaces = vertices.iter().filter_map(|v| match v.at {
                    At::Surface { point, object } => {
                        Some((point, object, v.light_sample))
                    }
                    At::Escaped { .. } => None,
                });
                let recorded = path
                    .vertices
                    .iter()
                    .map(|v| (v.point, v.object, v.light_sample));
                assert!(surfaces.eq(recorded), "pixel ({x}, {y})");
                assert_eq!(bits(&first.get(x, y).unwrap()), bits(&expected));
                assert!(!path.vertices.is_empty() || path.escaped.is_some());
                compared += 1;
            }
        }
        assert_eq!(compared, 2160, "54 columns by 40 rows");
    }
}

/// What the recorder records: vertices in the box, light samples only at
/// diffuse vertices and only with a strategy that samples lights.
#[test]
fn recorded_paths_lie_on_their_objects_and_sample_lights_at_diffuse_vertices() {
    let Staged { scene, camera } = cornell(40, 30).unwrap();
    for sampling in Sampling::ALL {
        let s = settings(sampling, Some(8), true);
        let mut light_samples = 0;
        for (x, y) in [(5, 5), (20, 15), (30, 25), (10, 28), (35, 3)] {
            let path = record_path(&scene, &camera, &s, 7, (x, y));
            for v in &path.vertices {
                let object = &scene.objects()[v.object];
                // Inside the box: between the side walls, floor and ceiling, in
                // front of the back wall (up to rounding).
                let p = v.point;
                let inside = (1.0 - 1e-3..=99.0 + 1e-3).contains(&p.x)
                    && (-1e-3..=81.6 + 1e-3).contains(&p.y)
                    && p.z >= -1e-3;
                assert!(inside, "{sampling:?} {v:?}");
                let diffuse = matches!(object.material, Material::Diffuse { .. });
                let lights = matches!(sampling, Sampling::NextEvent | Sampling::Mis);
                if v.light_sample.is_some() {
                    assert!(diffuse && lights, "{sampling:?} {v:?}");
                    light_samples += 1;
                }
            }
        }
        let lights = matches!(sampling, Sampling::NextEvent | Sampling::Mis);
        assert_eq!(light_samples > 0, lights, "{sampling:?}");
    }
}

#[test]
fn the_figures_draw_paths_and_samples() {
    let rgba = figures::path_figure().unwrap().rgba();
    assert!(blue_pixels(&rgba) > 2000, "the paths");
    let rgba = figures::hemisphere_figure().unwrap().rgba();
    assert!(blue_pixels(&rgba) > 2000, "the uniform samples");
}

// Steps 2 to 8: each figure is what its command writes.

#[test]
#[ignore = "over 1 s in a debug build: the release suite runs it (.ci/run: `cargo test --release --test course --test lessons -- --ignored`)"]
fn each_step_figure_is_what_its_command_writes() {
    for (i, step) in figures::STEPS.iter().enumerate() {
        // Step i + 2's page prints the command whose flags these are.
        let command = ["cargo run --release --example 10_path_tracing", "--"]
            .into_iter()
            .chain(step.flags.iter().copied())
            .take(if step.flags.is_empty() { 1 } else { usize::MAX })
            .collect::<Vec<_>>()
            .join(" ");
        let page = std::fs::read_dir("chapters")
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .find(|name| name.starts_with(&format!("10_{}_", i + 2)))
            .unwrap();
        let printed = self::page(&page);
        assert!(printed.lines().any(|l| l == command), "{page}: {command}");
        // The figure's size is the flags' (or the default): its own image is large,
        // so the test renders a small one with every other flag the same.
        let as_written =
            lesson::Args::parse_from([&["10_path_tracing"], step.flags].concat());
        assert_eq!(
            (as_written.width, as_written.height),
            step.size,
            "{}",
            step.file
        );
        let sized = |flag: &&str| ["--width", "--height"].contains(flag);
        let skip =
            |i: usize| sized(&step.flags[i]) || (i > 0 && sized(&step.flags[i - 1]));
        let mut argv = vec!["10_path_tracing", "--width", "32", "--height", "24"];
        argv.extend(["--out", "target/test-out/10"]);
        // Nothing compared here comes from the reference: the default run's 512
        // samples per pixel would be most of the test's time.
        if !step.flags.contains(&"--reference-spp") {
            argv.extend(["--reference-spp", "16"]);
        }
        argv.extend(
            (0..step.flags.len())
                .filter(|&i| !skip(i))
                .map(|i| step.flags[i]),
        );
        let args = lesson::Args::parse_from(argv);
        let (study, renders) = render(&args).unwrap();
        assert_eq!(
            study.settings,
            step.settings(args.path.sampling),
            "{}",
            step.file
        );
        assert_eq!(study.ladder.last(), Some(&step.spp), "{}", step.file);
        assert_eq!(args.scene, step.scene, "{}", step.file);
        assert_eq!(args.lens.aperture, step.aperture, "{}", step.file);
        if step.shown.len() == 1 {
            assert_eq!(step.shown[0], args.path.sampling, "{}", step.file);
        }
        let written: Vec<&render_lessons::framebuffer::Framebuffer> = step
            .shown
            .iter()
            .map(|s| &renders.strategies.iter().find(|(t, _)| t == s).unwrap().1)
            .collect();
        let written =
            render_lessons::framebuffer::Framebuffer::beside(&written, 4).unwrap();
        assert!(written == step.render(32, 24).unwrap(), "{}", step.file);
    }
}

/// Page 10_2: "The ceiling is darker and noisier than the floor" in step 2's render
/// (`10_step_uniform.png`, the committed figure), read pixel by pixel: the ceiling's
/// pixels (where the camera's ray meets it first) have a lower mean and a larger
/// spread relative to their mean than the floor's.
#[test]
fn in_the_naive_render_the_ceiling_is_darker_and_noisier_than_the_floor() {
    use render_lessons::files::read_png_rgba;
    use render_lessons::ray::Interval;
    use render_lessons::texture::from_srgb8;
    let path = std::path::Path::new("chapters/figures/10_step_uniform.png");
    let (width, height, rgba) = read_png_rgba(path).unwrap();
    let Staged { scene, camera } = cornell(width, height).unwrap();
    // Objects 3 and 4 of the Cornell box are the floor and the ceiling.
    let (mut floor, mut ceiling) = (Vec::new(), Vec::new());
    for y in 0..height {
        for x in 0..width {
            let i = 4 * (y * width + x) as usize;
            let linear = |k: usize| f64::from(from_srgb8(rgba[i + k]));
            let value = (0..3).map(linear).sum::<f64>() / 3.0;
            match scene.closest_object(&camera.ray(x, y), Interval::AHEAD) {
                Some(3) => floor.push(value),
                Some(4) => ceiling.push(value),
                _ => {}
            }
        }
    }
    let stats = |v: &[f64]| {
        let mean = v.iter().sum::<f64>() / v.len() as f64;
        let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / v.len() as f64;
        (v.len(), mean, var.sqrt() / mean)
    };
    eprintln!("floor {:?} ceiling {:?}", stats(&floor), stats(&ceiling));
    let ((nf, mf, rf), (nc, mc, rc)) = (stats(&floor), stats(&ceiling));
    assert!(nf > 500 && nc > 500, "{nf} {nc}");
    assert!(mc < mf, "mean: ceiling {mc}, floor {mf}");
    assert!(rc > rf, "spread / mean: ceiling {rc}, floor {rf}");
}
