//! Lesson 11: speed against accuracy, measured on the machine that runs it.
//!
//! Every chart of the lesson is measured here and now: how much each robust method
//! of lessons 07-10 costs and how much accuracy it buys, where a naive method fails,
//! and when an acceleration structure starts to pay. Each chart is written as SVG
//! (to look at), CSV (to plot again) and Markdown (the numbers the book quotes,
//! which its chapters include), and a summary is printed.
//!
//!     cargo run --release --example 11_speed_vs_accuracy            # about a minute
//!     cargo run --release --example 11_speed_vs_accuracy -- --full  # publication quality
//!     cargo run --release --example 11_speed_vs_accuracy -- --only 11_1_sphere
//!     cargo run --release --example 11_speed_vs_accuracy -- --full --out chapters/figures
//!                                                # refresh the book's charts and numbers
//!     cargo run --release --example 11_speed_vs_accuracy -- --mesh assets/meshes/teapot.obj --subdivide 4
//!                                                # the BVH on a million triangles

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use render_lessons::Result;
use render_lessons::bvh::BvhScene;
use render_lessons::course::chart::{Chart, Scale};
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::measure::lessons::{best_ms, lessons_quoted};
use render_lessons::course::measure::{ALL, Measure, Measured, Quality};
use render_lessons::course::report::{Run, Table, Timings, num};
use render_lessons::error::Error;
use render_lessons::files::write_atomically;
use render_lessons::framebuffer::Framebuffer;
use render_lessons::progress;
use render_lessons::raster::{Shading, agreement, floor_settings, rasterize, reference};
use render_lessons::raster::{TOLERANCE, point_light, tessellate};
use render_lessons::raycast::lit;
use render_lessons::render::render;
use render_lessons::scenes::{lesson08, lesson08_pinhole, lesson08_shadows};
use render_lessons::scenes::{lesson09_mesh, lesson09_mesh_scene};
use render_lessons::spawn::Offset;

/// The lesson's parameters.
#[derive(Parser, Debug)]
#[command(about = "Lesson 11: speed against accuracy, charted on this machine")]
pub struct Args {
    /// Measure longer, for charts good enough to publish (several minutes).
    #[arg(long)]
    pub full: bool,
    /// Measure only the charts whose name starts with this (e.g. 11_5); each chart is
    /// written to --out as SVG, CSV and Markdown. An empty name is refused: it would
    /// match every chart.
    #[arg(long, value_parser = clap::builder::NonEmptyStringValueParser::new())]
    pub only: Option<String>,
    /// Instead of the charts: time the BVH on this mesh (a Wavefront OBJ file) in
    /// lesson 09's scene: read it, build the tree, ray cast 480 x 270 through it.
    #[arg(long, conflicts_with_all = ["full", "only"])]
    pub mesh: Option<PathBuf>,
    /// With --mesh: split every triangle in four, this many times (the teapot: 4
    /// makes a million triangles).
    #[arg(long)]
    pub subdivide: Option<u32>,
    #[command(flatten)]
    pub output: Output,
}

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| {
        if let Some(path) = &args.mesh {
            let (text, image) = big_mesh(path, args.subdivide.unwrap_or(0))?;
            lesson::print(&text);
            return args.output.image("11_mesh.png", &image);
        }
        if args.subdivide.is_some() {
            return Err(Error::Invalid {
                param: "subdivide",
                reason: "needs --mesh: it splits that mesh's triangles",
            });
        }
        let quality = if args.full {
            Quality::Full
        } else {
            Quality::Quick
        };
        let mut all: Vec<(&str, Measure)> = ALL.to_vec();
        all.push(("11_8_lessons", lessons));
        let chosen: Vec<_> = all
            .iter()
            .filter(|(stem, _)| {
                args.only
                    .as_ref()
                    .is_none_or(|o| stem.starts_with(o.as_str()))
            })
            .collect();
        if chosen.is_empty() {
            return Err(Error::NoMatch {
                param: "--only",
                value: args.only.clone().unwrap_or_default(),
                choices: all.iter().map(|(stem, _)| stem.to_string()).collect(),
            });
        }
        let mut summary = String::new();
        lesson::stop_on_ctrl_c(); // Ctrl-C keeps the charts already written
        for (stem, measure) in chosen {
            lesson::check_interrupt()?;
            let start = Instant::now();
            let run = Run::here(quality.name());
            let measured = measure(quality)?;
            for path in measured.chart.save(&args.output.out, stem)? {
                lesson::wrote(&path);
            }
            let md = args.output.file(&format!("{stem}.md"));
            write_atomically(&md, measured.quoted.markdown(stem, &run).as_bytes())?;
            lesson::wrote(&md);
            summary.push_str(&format!(
                "{} ({:.1} s)\n",
                measured.chart.title,
                start.elapsed().as_secs_f64()
            ));
            for finding in &measured.findings {
                summary.push_str(&format!("  - {finding}\n"));
            }
        }
        lesson::print(&summary);
        Ok(())
    })
}

// ANCHOR: lessons
/// Chart 8, the renderers of lessons 08 and 09 on lesson 08's scene: time per frame
/// against the share of pixels (away from silhouettes) that differ from the
/// ray-traced image with shadow rays. The rasterizer's two knobs are swept: the
/// tessellation of the spheres, and the resolution of the shadow map.
pub fn lessons(quality: Quality) -> Result<Measured> {
    let scene = lesson08(glam::Vec3::ZERO)?;
    let camera = lesson08_pinhole(480, 270)?;
    let light = point_light(&scene)?;
    let mask = reference(&scene, &camera, None)?.silhouettes;
    let repeats = quality.pick(2, 5);
    let (traced_ms, traced) = best_ms(repeats, || {
        render(&camera, None, |r| lit(&scene, r, Offset::Scaled))
    })?;
    let raster = |segments: u32, shadows| -> Result<(f64, f64)> {
        let instances = tessellate(&scene, segments)?;
        let settings = floor_settings(&scene).with(Shading::PerPixel, shadows);
        let (ms, image) = best_ms(repeats, || {
            rasterize(&instances, &camera, &light, &settings, None)
        })?;
        let a = agreement(&image, &traced, &mask, TOLERANCE);
        Ok((ms, 100.0 - a.percent_agreeing()))
    };
    let map = |size: u32| Some(lesson08_shadows(size, 1.0));
    let segments = [8, 16, 32, 64, 128]
        .into_iter()
        .map(|n| raster(n, map(1024)))
        .collect::<Result<Vec<_>>>()?;
    let maps = [128, 256, 512, 1024, 2048, 4096]
        .into_iter()
        .map(|size| raster(64, map(size)))
        .collect::<Result<Vec<_>>>()?;
    let no_shadows = raster(64, None)?;
    let chart = Chart::new(
        "Lessons 08 and 09 on lesson 08's scene, 480 x 270, every core",
        ("time per frame (ms)", Scale::Log),
        (
            "pixels differing from the ray-traced image (%)",
            Scale::Linear,
        ),
    )
    .with(
        "rasterized + 1024^2 shadow map, spheres of 8 to 128 segments",
        segments.clone(),
    )
    .with(
        "rasterized, 64 segments, shadow map of 128^2 to 4096^2",
        maps.clone(),
    )
    .with("rasterized, no shadows", vec![no_shadows])
    .with(
        "ray cast with shadow rays (the reference)",
        vec![(traced_ms, 0.0)],
    );
    let findings = vec![
        format!(
            "ray cast with shadow rays: {traced_ms:.0} ms; rasterized with 64 segments and a \
             1024^2 map: {:.0} ms, {:.2}% of pixels differ",
            segments[3].0, segments[3].1
        ),
        format!(
            "no shadows: {:.2}% differ; a 128^2 map: {:.2}%, a 4096^2 map: {:.2}% ({:.0} ms)",
            no_shadows.1, maps[0].1, maps[5].1, maps[5].0
        ),
        "lesson 10 is not on this chart: it solves the whole rendering equation (indirect light, \
         area lights), so against this direct-lighting image its difference would be the light \
         the others leave out; chart 6 is its time against error"
            .to_string(),
    ];
    let quoted = lessons_quoted(traced_ms, &segments, &maps, no_shadows);
    Ok(Measured {
        chart,
        findings,
        quoted,
    })
}
// ANCHOR_END: lessons

// ANCHOR: big_mesh
/// The BVH on a mesh of any size, in lesson 09's scene (the floor, and the mesh of
/// `path` split `subdivisions` times standing on it): read the file, build the
/// tree, ray cast 480 x 270 with shadow rays through it, each step timed. Returns
/// the tables to print and the image.
pub fn big_mesh(path: &Path, subdivisions: u32) -> Result<(String, Framebuffer)> {
    let scene = lesson08(glam::Vec3::ZERO)?;
    let camera = lesson08_pinhole(480, 270)?;
    let mut t = Timings::default();
    let read = || lesson09_mesh(path, subdivisions).map_err(lesson::flag("--mesh"));
    let mesh = t.time("read the OBJ file (and subdivide)", read)?;
    let list = lesson09_mesh_scene(&scene, &mesh.model)?;
    let primitives = list.objects().len();
    let build = || BvhScene::new(list);
    let message = format!("building a BVH over {primitives} primitives");
    let tree = t.time("build the BVH", || progress::spinner(message, build));
    let image = t.time("ray cast with shadow rays", || {
        render(&camera, None, |r| lit(&tree, r, Offset::Scaled))
    })?;
    let file = path.file_name().unwrap_or_default().to_string_lossy();
    let title = format!("{file}, split in four {subdivisions} times, and its tree");
    let mut sizes = Table::new(&title, &["what", "count"]);
    let counts = mesh.counts;
    for (what, count) in [
        ("triangles", mesh.model.mesh.triangles.len()),
        ("faces triangulated", counts.faces_triangulated),
        ("degenerate, skipped", counts.skipped_degenerate),
        ("BVH nodes", tree.bvh().nodes().len()),
    ] {
        sizes.row(vec![what.to_string(), count.to_string()]);
    }
    let rays = f64::from(camera.film().width()) * f64::from(camera.film().height());
    let seconds = t.0.last().map_or(0.0, |&(_, s)| s).max(1e-9);
    let mrays = num(rays / seconds / 1e6, 2);
    let rate = format!("{mrays} million primary rays a second");
    Ok((format!("{sizes}\n{}{rate}\n", t.table()), image))
}
// ANCHOR_END: big_mesh
