//! Lesson 10: Monte Carlo path tracing, an estimator of Kajiya's rendering equation
//! (Lecture 2).
//!
//! smallpt's Cornell box rendered progressively at 1, 4, 16 and 64 samples per pixel,
//! each image compared with a reference of many more samples: the error (RMSE)
//! falls as 1/sqrt(N). A second table compares the four ways of sampling at the same
//! sample count. The estimator itself is `radiance` in src/pathtrace/estimator.rs.
//!
//!     cargo run --release --example 10_path_tracing
//!     cargo run --release --example 10_path_tracing -- --sampling cosine --spp 256 --jitter
//!     cargo run --release --example 10_path_tracing -- --scene two-lights --aperture 0.2

use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use indicatif::ProgressBar;
use render_lessons::Result;
use render_lessons::camera::Camera;
use render_lessons::course::convergence::{Part, Renders, Study};
use render_lessons::course::failure::LessonResult;
use render_lessons::course::ladder_figure::ladder_figure;
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::path_flags::{LensFlags, PathFlags, StudyFlags};
use render_lessons::course::report::{Table, num};
use render_lessons::framebuffer::pfm::save_pfm;
use render_lessons::pathtrace::PixelSampling;
use render_lessons::pathtrace::progressive::rmse;
use render_lessons::render::with_threads;
use render_lessons::scene::Intersect;
use render_lessons::scene::ListOrTree;
use render_lessons::scenes::path_tracing::{SceneName, Staged};

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| {
        let start = Instant::now();
        // ANCHOR: setup
        // At most 11 rungs, 3 strategies, the reference and two f64 accumulators.
        let threads = lesson::budget(args.width, args.height, args.threads, 20)?;
        let size = (args.width, args.height);
        let lens = (args.lens.aperture, args.lens.focus);
        let Staged { scene, camera } = scene_and_camera(args.scene, size, lens)?;
        let study = args.study.study(args.path.settings())?;
        // Every object on every ray while that stays cheap, else lesson 11's BVH.
        let scene = ListOrTree::new(
            scene,
            study.samples() * u64::from(args.width * args.height),
        );
        // ANCHOR_END: setup
        let renders =
            with_threads(threads, || render(&scene, &camera, &study, &args.output))?;
        let seconds = start.elapsed().as_secs_f64();
        lesson::print(&numbers(args.scene, &study, &renders));
        lesson::print(&format!("rendered in {seconds:.1} s\n"));
        let out = &args.output;
        lesson::wrote(&out.file("10_reference.png"));
        out.diagram("10_convergence.png", &ladder_figure(&renders.ladder)?)?;
        let pfm = out.file("10_reference.pfm");
        save_pfm(&pfm, &renders.reference)?;
        lesson::wrote(&pfm);
        Ok(())
    })
}

// ANCHOR: render
/// The lesson's loop: the `study` rendered pass by pass, each pass adding to every
/// pixel more samples of the estimator, `radiance` along a ray through the pixel
/// (`Accumulator::render_pass`). Each image is written to `out` the moment it is
/// finished (Ctrl-C keeps them), the reference after every pass: watch it sharpen.
pub fn render(
    scene: &impl Intersect,
    camera: &Camera,
    study: &Study,
    out: &Output,
) -> LessonResult<Renders> {
    let bar = ProgressBar::new(study.samples());
    let top = study.ladder.last().copied().unwrap_or(0);
    let sampling = study.settings.sampling.flag();
    let mut reference_spp = 0;
    lesson::stop_on_ctrl_c();
    let renders = study.render(scene, camera, |part, pass| {
        bar.inc(u64::from(pass.added));
        let (image, spp) = (&pass.image, pass.samples);
        match part {
            Part::Ladder if spp == top => {
                out.image(&format!("10_{spp}spp.png"), image)?;
                out.image(&format!("10_{sampling}.png"), image)?
            }
            Part::Ladder => out.image(&format!("10_{spp}spp.png"), image)?,
            Part::Strategy(s) => out.image(&format!("10_{}.png", s.flag()), image)?,
            Part::Reference => {
                image.save_png(out.file("10_reference.png"))?;
                reference_spp = spp;
            }
        }
        lesson::check_interrupt()
    });
    bar.finish_and_clear();
    renders.inspect_err(|_| {
        if reference_spp > 0 && reference_spp < study.reference_spp {
            eprintln!("10_reference.png is partial: {reference_spp} samples per pixel");
        }
    })
}
// ANCHOR_END: render

/// The scene `name` at `width` x `height` pixels, and its camera: a thin lens of
/// radius `aperture` focused at distance `focus`, or the pinhole if `aperture` is 0.
pub fn scene_and_camera(
    name: SceneName,
    (width, height): (u32, u32),
    (aperture, focus): (f32, f32),
) -> Result<Staged> {
    let Staged { scene, camera } = name.build(width, height)?;
    let camera = match aperture {
        0.0 => camera,
        aperture => camera.with_lens(aperture, focus)?,
    };
    Ok(Staged { scene, camera })
}

// ANCHOR: numbers
/// The lesson's tables for the `scene`: error against the reference as samples grow,
/// and the four strategies side by side. Independent of timing and thread count.
pub fn numbers(scene: SceneName, study: &Study, renders: &Renders) -> String {
    let r = &renders.reference;
    let jitter = study.passes.pixels == PixelSampling::Jittered;
    let mut ladder = Table::new(
        &format!(
            "{scene:?} scene, {} x {}, {} sampling{}: RMSE against a {}-sample MIS reference",
            r.width(),
            r.height(),
            study.settings.sampling.name(),
            if jitter { ", jittered" } else { "" },
            study.reference_spp
        ),
        &["spp", "RMSE", "RMSE x sqrt(spp)", "mean"],
    );
    for (spp, image) in &renders.ladder {
        let e = rmse(image, r);
        let scaled = e * f64::from(*spp).sqrt();
        let mean = num(image.mean(), 5);
        ladder.row(vec![spp.to_string(), num(e, 5), num(scaled, 4), mean]);
    }
    let top = study.ladder.last().copied().unwrap_or(0);
    let title = format!("The four strategies at {top} spp");
    let mut strategies = Table::new(&title, &["sampling", "RMSE", "mean"]);
    for (s, image) in &renders.strategies {
        let e = rmse(image, r);
        strategies.row(vec![s.name().to_string(), num(e, 5), num(image.mean(), 5)]);
    }
    format!(
        "{ladder}\n{strategies}\nreference mean {}; samples dropped as NaN or infinite: {}\n",
        num(r.mean(), 5),
        renders.non_finite
    )
}
// ANCHOR_END: numbers

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 10: Monte Carlo path tracing, four sampling strategies")]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// The scene.
    #[arg(long, value_enum, default_value_t = SceneName::Cornell)]
    pub scene: SceneName,
    /// Image width in pixels.
    #[arg(long, default_value_t = 160)]
    pub width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 120)]
    pub height: u32,
    /// Worker threads (default: every core).
    #[arg(long)]
    pub threads: Option<usize>,
    #[command(flatten)]
    pub path: PathFlags,
    #[command(flatten)]
    pub study: StudyFlags,
    #[command(flatten)]
    pub lens: LensFlags,
    #[command(flatten)]
    pub output: Output,
}
