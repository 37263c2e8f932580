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

use clap::Parser;
use render_lessons::Result;
use render_lessons::course::compare::{TOLERANCE, agreement, reference};
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::measure::lessons::{Sweep, best_ms, lessons_measured};
use render_lessons::course::measure::runner::run_charts;
use render_lessons::course::measure::{ALL, Measure, Measured, Quality};
use render_lessons::course::report::{Table, Timings, num};
use render_lessons::error::{Error, Problem};
use render_lessons::framebuffer::Framebuffer;
use render_lessons::mesh::tessellate;
use render_lessons::progress;
use render_lessons::raster::{Shading, floor_settings, point_light, rasterize};
use render_lessons::raycast::lit;
use render_lessons::render::render;
use render_lessons::scene::Object;
use render_lessons::scenes::{Up, floor_and, mesh_on_the_floor};
use render_lessons::scenes::{still_life, still_life_pinhole, still_life_shadows};
use render_lessons::spawn::Offset;

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| match &args.mesh {
        Some(path) => {
            let (text, image) = big_mesh(path, args.up, args.subdivide.unwrap_or(0))?;
            lesson::print(&text);
            args.output.image("11_mesh.png", &image)?;
            Ok(())
        }
        None if args.subdivide.is_some() => Err(Error::Value {
            param: "subdivide",
            problem: Problem::Invalid {
                reason: "needs --mesh: it splits that mesh's triangles",
            },
        }
        .into()),
        None => {
            let quality = Quality::full_if(args.full);
            let charts = [ALL, &[("11_8_lessons", lessons as Measure)]].concat();
            lesson::stop_on_ctrl_c(); // Ctrl-C keeps the charts already written
            let only = args.only.as_deref();
            lesson::print(&run_charts(&charts, only, quality, &args.output)?);
            Ok(())
        }
    })
}

// ANCHOR: lessons
/// Chart 8, the renderers of lessons 08 and 09 on lesson 08's scene: time per frame
/// against the share of pixels (away from silhouettes) that differ from the
/// ray-traced image with shadow rays. The rasterizer's two knobs are swept: the
/// tessellation of the spheres, and the resolution of the shadow map.
pub fn lessons(quality: Quality) -> Result<Measured> {
    let scene = still_life(glam::Vec3::ZERO)?;
    let camera = still_life_pinhole(480, 270)?;
    let light = point_light(&scene)?;
    let mask = reference(&scene, &camera)?.silhouettes;
    let repeats = quality.pick(2, 5);
    let (traced_ms, traced) = best_ms(repeats, || {
        render(&camera, |r| lit(&scene, r, Offset::Scaled))
    })?;
    let raster = |segments: u32, map: Option<u32>| -> Result<(f64, f64)> {
        let instances = tessellate(&scene, segments)?;
        let shadows = map.map(|size| still_life_shadows(size, 1.0));
        let settings = floor_settings(&scene).with(Shading::PerPixel, shadows);
        let (ms, image) = best_ms(repeats, || {
            rasterize(&instances, &camera, &light, &settings)
        })?;
        let a = agreement(&image, &traced, &mask, TOLERANCE);
        Ok((ms, 100.0 - a.percent_agreeing()))
    };
    let (map, n) = (1024, 64); // lesson 09's defaults
    let segments =
        Sweep::measure(map, &[8, 16, 32, 64, 128], |s| raster(s, Some(map)))?;
    let sizes = [128, 256, 512, 1024, 2048, 4096];
    let maps = Sweep::measure(n, &sizes, |size| raster(n, Some(size)))?;
    let no_shadows = raster(n, None)?;
    let size = (camera.film().width(), camera.film().height());
    Ok(lessons_measured(
        size, traced_ms, &segments, &maps, no_shadows,
    ))
}
// ANCHOR_END: lessons

// ANCHOR: big_mesh
/// The BVH on a mesh of any size, in lesson 09's scene (the floor, and the mesh of
/// `path`, `up` up in its file, split `subdivisions` times, standing on it): read
/// the file, build the tree, ray cast 480 x 270 with shadow rays through it, each
/// step timed. Returns the tables to print and the image.
pub fn big_mesh(
    path: &Path,
    up: Up,
    subdivisions: u32,
) -> Result<(String, Framebuffer)> {
    let scene = still_life(glam::Vec3::ZERO)?;
    let camera = still_life_pinhole(480, 270)?;
    let mut t = Timings::default();
    let read = || {
        mesh_on_the_floor(path, up, subdivisions, &camera)
            .map_err(lesson::flag("--mesh"))
    };
    let mesh = t.time("read the OBJ file (and subdivide)", read)?;
    let triangles = mesh.model.mesh.triangles.len();
    let build = || mesh.model.shape(); // one shape, its triangles in its own tree
    let message = format!("building a BVH over {triangles} triangles");
    let shape = t.time("build the BVH", || progress::spinner(message, build))?;
    let nodes = shape.tree().node_count();
    let scene = floor_and(&scene, Object::diffuse(shape, mesh.model.colour))?;
    let image = t.time("ray cast with shadow rays", || {
        render(&camera, |r| lit(&scene, r, Offset::Scaled))
    })?;
    let file = path.file_name().unwrap_or_default().to_string_lossy();
    let title = format!("{file}, split in four {subdivisions} times, and its tree");
    let mut sizes = Table::new(&title, &["what", "count"]);
    let counts = mesh.counts;
    for (what, count) in [
        ("triangles", triangles),
        ("faces triangulated", counts.faces_triangulated),
        ("degenerate, skipped", counts.skipped_degenerate),
        ("under 3 corners, skipped", counts.skipped_edges),
        ("far from the rest, left out of the fit", mesh.fit.left_out),
        ("BVH nodes", nodes),
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
    /// With --mesh: the axis that points up in its file.
    #[arg(long, value_enum, default_value_t = Up::Y)]
    pub up: Up,
    #[command(flatten)]
    pub output: Output,
}
