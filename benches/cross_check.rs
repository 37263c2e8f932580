//! Lesson 10's path tracer for `scripts/cross-check`, which compares it with Mitsuba 3:
//! a scene as the crate builds it, written out so that the script can build the same
//! scene in Mitsuba from the crate's own numbers, and raw radiance images rendered
//! with Russian roulette off (the script's Mitsuba runs have none either).
//!
//!     cargo run --release -p render-benches --bin cross-check -- describe --scene cornell
//!     cargo run --release -p render-benches --bin cross-check -- render --scene cornell \
//!         --sampling mis --max-depth 2 --spp 64 --seed 3 --out target/cornell.pfm
//!
//! `describe` prints JSON: the camera (eye, basis, the film's extents on a screen at
//! distance 1) and every object (its shape, material, emission and whether it emits
//! from its front only; a quad by its corner q and the ends q + a, q + b of its
//! edges). `render` writes the mean of `--spp` samples per pixel as a
//! PFM and prints one line: the samples, the seconds and the samples dropped as NaN.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use clap::{Parser, Subcommand};
use glam::Vec3;
use render_lessons::camera::Camera;
use render_lessons::framebuffer::pfm::save_pfm;
use render_lessons::material::Material;
use render_lessons::pathtrace::{Accumulator, PixelSampling, Sampling, Settings};
use render_lessons::render::with_threads;
use render_lessons::scene::{Object, Scene};
use render_lessons::scenes::path_tracing::{SceneName, Staged};
use render_lessons::shapes::Shape;

#[derive(Parser, Debug)]
#[command(about = "Lesson 10's scenes and renders for scripts/cross-check")]
struct Args {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Print the scene and its camera as JSON.
    Describe {
        #[command(flatten)]
        view: View,
    },
    /// Render the scene without Russian roulette and write a PFM.
    Render {
        #[command(flatten)]
        view: View,
        /// How directions are chosen at diffuse surfaces.
        #[arg(long, value_enum)]
        sampling: Sampling,
        /// The most bounces a path may take.
        #[arg(long)]
        max_depth: u32,
        /// Samples per pixel.
        #[arg(long)]
        spp: u32,
        /// Seed of the per-pixel random streams.
        #[arg(long)]
        seed: u64,
        /// Worker threads (default: every core); the image does not depend on it.
        #[arg(long)]
        threads: Option<usize>,
        /// The PFM file to write.
        #[arg(long)]
        out: PathBuf,
    },
}

/// The scene and the image size.
#[derive(clap::Args, Debug)]
struct View {
    #[arg(long, value_enum)]
    scene: SceneName,
    #[arg(long, default_value_t = 64)]
    width: u32,
    #[arg(long, default_value_t = 48)]
    height: u32,
}

fn main() -> ExitCode {
    match run(Args::parse()) {
        Ok(line) => {
            println!("{line}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("cross-check: {e}");
            ExitCode::from(2)
        }
    }
}

fn run(args: Args) -> Result<String, String> {
    match args.command {
        Command::Describe { view } => {
            let Staged { scene, camera } = staged(&view)?;
            describe(&scene, &camera)
        }
        Command::Render {
            view,
            sampling,
            max_depth,
            spp,
            seed,
            threads,
            out,
        } => {
            let Staged { scene, camera } = staged(&view)?;
            let settings = Settings {
                sampling,
                max_depth: Some(max_depth),
                russian_roulette: false,
                ..Settings::default()
            };
            let start = Instant::now();
            let mut acc = Accumulator::new(&camera, seed);
            let image = with_threads(threads, || {
                acc.render_pass(
                    &scene,
                    &camera,
                    &settings,
                    PixelSampling::Independent,
                    spp,
                )
            })
            .map_err(|e| e.to_string())?;
            let seconds = start.elapsed().as_secs_f64();
            save_pfm(&out, &image).map_err(|e| e.to_string())?;
            Ok(format!(
                "{spp} spp in {seconds:.4} s, {} non-finite",
                acc.non_finite()
            ))
        }
    }
}

fn staged(view: &View) -> Result<Staged, String> {
    view.scene
        .build(view.width, view.height)
        .map_err(|e| e.to_string())
}

fn v(x: Vec3) -> String {
    format!("[{:?}, {:?}, {:?}]", x.x, x.y, x.z)
}

/// The scene and camera as JSON, every number as the crate holds it (f32, printed
/// so that it reads back to the same f32).
fn describe(scene: &Scene, camera: &Camera) -> Result<String, String> {
    let pinhole = camera
        .pinhole()
        .ok_or("the scene's camera is not a pinhole")?;
    let frame = pinhole.frame();
    let film = pinhole.film();
    let (x, y) = (film.x_extent(), film.y_extent());
    let basis = frame.basis();
    let mut objects = Vec::new();
    for object in scene.objects() {
        objects.push(object_json(object)?);
    }
    Ok(format!(
        "{{\n\"camera\": {{\"eye\": {}, \"u\": {}, \"v\": {}, \"w\": {}, \
         \"screen_distance\": {:?}, \"x_extent\": [{:?}, {:?}], \"y_extent\": [{:?}, {:?}], \
         \"width\": {}, \"height\": {}}},\n\"background\": {},\n\"objects\": [\n{}\n]\n}}",
        v(frame.position()),
        v(basis.u()),
        v(basis.v()),
        v(basis.w()),
        pinhole.screen_distance(),
        x.0,
        x.1,
        y.0,
        y.1,
        film.width(),
        film.height(),
        v(scene.background()),
        objects.join(",\n")
    ))
}

fn object_json(object: &Object) -> Result<String, String> {
    let shape = match &object.shape {
        Shape::Plane(p) => format!(
            "{{\"type\": \"plane\", \"point\": {}, \"normal\": {}}}",
            v(p.point()),
            v(p.normal())
        ),
        Shape::Sphere(s) => format!(
            "{{\"type\": \"sphere\", \"centre\": {}, \"radius\": {:?}}}",
            v(s.centre()),
            s.radius()
        ),
        Shape::Quad(q) => format!(
            "{{\"type\": \"quad\", \"corner\": {}, \"end_a\": {}, \"end_b\": {}, \"normal\": {}}}",
            v(q.corner()),
            v(q.point(1.0, 0.0)),
            v(q.point(0.0, 1.0)),
            v(q.normal())
        ),
        other => return Err(format!("no Mitsuba counterpart for {other:?}")),
    };
    let material = match object.material {
        Material::Diffuse { albedo } => {
            format!("{{\"type\": \"diffuse\", \"albedo\": {}}}", v(albedo))
        }
        Material::Mirror { reflectance } => format!(
            "{{\"type\": \"mirror\", \"reflectance\": {}}}",
            v(reflectance)
        ),
        Material::Glass { ior } => format!("{{\"type\": \"glass\", \"ior\": {ior:?}}}"),
    };
    Ok(format!(
        "{{\"shape\": {shape}, \"material\": {material}, \"emission\": {}, \"front_only\": {}}}",
        v(object.emission),
        object.front_only
    ))
}
