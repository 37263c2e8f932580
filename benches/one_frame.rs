//! One or more frames of lesson 08 (1920 x 1080 unless told), on one thread, by one
//! caster, with the buffer made once: what `valgrind --tool=callgrind` counts in
//! `scripts/instructions-per-ray`, which runs it for 1 and 2 frames and divides the
//! difference by the number of rays, so start-up and set-up cancel out.
//!
//!     cargo build --release -p render-benches --bin one-frame
//!     target/release/one-frame CASTER [WIDTH HEIGHT [FRAMES]]
//!
//! CASTER is `c` (the plain C anchor), `plain` (`course::measure::plain`), `robust`
//! (`raycast::shadowless`), `c-camera` or `camera` (camera rays only, C or Rust).
//! `check` instead compares the C anchor with the Rust plain caster, image and camera
//! rays, bit for bit, and fails when a pixel differs (`.ci/run` runs it); without a
//! C compiler it says that the anchor was skipped. `clock` measures the core's clock
//! rate instead ([`clock::cycles_per_second`]).
//!
//! The line it prints ends with the time the frames took, set-up left out, which
//! `scripts/instructions-per-ray --clock` turns into cycles per ray.

use std::process::ExitCode;
use std::time::Instant;

use glam::Vec3;
use render_benches::anchor;
use render_benches::args::{self, number};
use render_benches::clock;
use render_benches::frame::FrameLoop;
use render_lessons::camera::Camera;
use render_lessons::course::measure::plain::PlainScene;
use render_lessons::raycast::shadowless;
use render_lessons::scenes::{still_life, still_life_pinhole};

const CASTERS: [&str; 7] = [
    "c", "plain", "robust", "c-camera", "camera", "check", "clock",
];

fn main() -> ExitCode {
    args::main("one-frame", run)
}

fn run(args: Vec<String>) -> Result<String, String> {
    let caster = args.first().map(String::as_str).unwrap_or_default();
    if !CASTERS.contains(&caster) {
        return Err(format!(
            "CASTER must be one of {}, not '{caster}'",
            CASTERS.join(", ")
        ));
    }
    if args.len() > 4 {
        return Err(
            "usage: one-frame CASTER [WIDTH HEIGHT [FRAMES]], check [WIDTH HEIGHT], or clock"
                .into(),
        );
    }
    if caster == "clock" {
        return clock::cycles_per_second(7)
            .map(|hz| format!("clock: {:.3} GHz", hz / 1e9))
            .ok_or(
                "clock: measured with x86-64 additions; this is another machine".into(),
            );
    }
    let width = number(&args, 1, "WIDTH", 1920)?;
    let height = number(&args, 2, "HEIGHT", 1080)?;
    let frames = number(&args, 3, "FRAMES", 1)?;
    let camera = still_life_pinhole(width, height).map_err(|e| e.to_string())?;
    let scene = still_life(Vec3::ZERO).map_err(|e| e.to_string())?;
    let plain =
        PlainScene::new(&scene).ok_or("lesson 08's scene has a shape plain lacks")?;
    let mut frame = FrameLoop::new(&camera, 1);
    if caster == "check" {
        return check(&camera, &plain, &mut frame);
    }
    let start = Instant::now();
    for _ in 0..frames {
        match caster {
            "c" => anchor::frame(width, height, frame.pixels_mut())
                .ok_or(anchor::MISSING)?,
            "c-camera" => anchor::camera(width, height, frame.pixels_mut())
                .ok_or(anchor::MISSING)?,
            "plain" => frame.run(&camera, |r| plain.shadowless(r)),
            "robust" => frame.run(&camera, |r| shadowless(&scene, r)),
            _ => frame.run(&camera, |r| r.direction()),
        }
        std::hint::black_box(frame.pixels());
    }
    let seconds = start.elapsed().as_secs_f64();
    let sum: f64 = frame
        .pixels()
        .iter()
        .map(|p| f64::from(p.x + p.y + p.z))
        .sum();
    Ok(format!(
        "{caster}: {frames} frame(s) of {width}x{height}, checksum {sum:.6}, in {seconds:.6} s"
    ))
}

/// The C anchor against the Rust plain caster: how many pixels and camera rays
/// differ in any bit; an error when one does.
fn check(
    camera: &Camera,
    plain: &PlainScene,
    frame: &mut FrameLoop,
) -> Result<String, String> {
    let (width, height) = (camera.film().width(), camera.film().height());
    let mut c = vec![Vec3::ZERO; width as usize * height as usize];
    let differ = |a: &[Vec3], b: &[Vec3]| {
        let bits = |v: &Vec3| v.to_array().map(f32::to_bits);
        a.iter().zip(b).filter(|(a, b)| bits(a) != bits(b)).count()
    };
    if anchor::frame(width, height, &mut c).is_none() {
        return Ok(anchor::MISSING.into());
    }
    frame.run(camera, |r| plain.shadowless(r));
    let pixels = differ(&c, frame.pixels());
    anchor::camera(width, height, &mut c).ok_or(anchor::MISSING)?;
    frame.run(camera, |r| r.direction());
    let rays = differ(&c, frame.pixels());
    let line = format!(
        "C anchor against the Rust plain caster, {width}x{height}: {pixels} pixels and {rays} \
         camera rays differ in any bit"
    );
    if pixels + rays == 0 {
        Ok(line)
    } else {
        Err(line)
    }
}
