//! Lesson 08: Appel's ray casting (Lecture 4), then light and shadows.
//!
//! For each pixel, a ray through the pixel centre is tested against every primitive;
//! the closest hit's colour, or the background, is the pixel. The same scene is cast
//! with the orthographic and the pinhole camera. Then one step past the slides:
//! Lambert shading from a point light with a shadow ray, and the self-intersection
//! problem that shadow rays bring (shadow acne), shown and fixed.
//!
//!     cargo run --release --example 08_ray_casting
//!     cargo run --release --example 08_ray_casting -- --width 1920 --height 1080 --threads 1

use render_lessons::ray::Interval;
use std::process::ExitCode;

use clap::Parser;
use glam::Vec3;
use render_lessons::camera::Camera;
use render_lessons::course::lesson::{self, ImageFlags, Output, parse_finite, parse_vec3};
use render_lessons::course::mine;
use render_lessons::course::report::{Table, num, vec3};
use render_lessons::error::non_negative;
use render_lessons::framebuffer::Framebuffer;
use render_lessons::raster::agreement;
use render_lessons::raycast::{lit, shadowless};
use render_lessons::render::render;
use render_lessons::scene::Scene;
use render_lessons::scenes::{LESSON08_OBJECTS, lesson08, lesson08_cameras};
use render_lessons::spawn::Offset;
use render_lessons::{Error, Result};

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 08: ray casting, then Lambert shading and shadow rays")]
#[command(allow_negative_numbers = true)]
struct Args {
    #[command(flatten)]
    image: ImageFlags,
    /// The fixed shadow-ray epsilon whose failure the lesson shows.
    #[arg(long, default_value = "1e-4", value_parser = parse_finite)]
    epsilon: f32,
    /// How far the whole scene (and camera) is moved for the acne comparison, as x,y,z.
    #[arg(long, default_value = "10000,0,0", value_parser = parse_vec3, allow_hyphen_values = true)]
    far: Vec3,
    /// Also draw the shadowless pinhole image with your own `closest` (coding exercise
    /// 8.1) and the Lambert image with your own `lambert` (8.2):
    /// `cargo run --release --features exercises --example 08_ray_casting -- --mine`.
    #[arg(long)]
    mine: bool,
    #[command(flatten)]
    output: Output,
}

/// The lesson's images, in the order [`images`] renders them.
pub const IMAGES: [&str; 5] = [
    "08_shadowless_ortho.png",
    "08_shadowless_pinhole.png",
    "08_lambert.png",
    "08_far_fixed_epsilon.png",
    "08_far_scaled_offset.png",
];

// ANCHOR: images
/// Every image of the lesson, named in [`IMAGES`]: the scene shadowless through both
/// cameras, lit with shadow rays, and lit again moved by `far`, where a fixed
/// shadow-ray `epsilon` fails and the scaled offset does not.
pub fn images(
    (width, height): (u32, u32),
    epsilon: f32,
    far: Vec3,
    threads: Option<usize>,
) -> Result<[Framebuffer; 5]> {
    let near = lesson08(Vec3::ZERO)?;
    let [ortho, pinhole] = lesson08_cameras(width, height, Vec3::ZERO)?;
    let far_scene = lesson08(far)?;
    let [_, far_pinhole] = lesson08_cameras(width, height, far)?;
    let t = threads;
    Ok([
        render(&ortho, t, |r| shadowless(&near, r))?,
        render(&pinhole, t, |r| shadowless(&near, r))?,
        render(&pinhole, t, |r| lit(&near, r, Offset::Scaled))?,
        render(&far_pinhole, t, |r| {
            lit(&far_scene, r, Offset::Fixed(epsilon))
        })?,
        render(&far_pinhole, t, |r| lit(&far_scene, r, Offset::Scaled))?,
    ])
}
// ANCHOR_END: images

/// The shadowless pinhole image drawn with `closest`, the student's own once it
/// passes its check (coding exercise 8.1, `src/course/exercises/ch08.rs`).
pub fn my_shadowless_image(
    closest: mine::Closest,
    (width, height): (u32, u32),
    threads: Option<usize>,
) -> Result<Framebuffer> {
    let scene = lesson08(Vec3::ZERO)?;
    let [_, pinhole] = lesson08_cameras(width, height, Vec3::ZERO)?;
    let shapes: Vec<_> = scene.objects().iter().map(|o| o.shape.clone()).collect();
    render(&pinhole, threads, |r| {
        match closest(r, &shapes, Interval::AHEAD) {
            Some(found) => scene.object(&found).colour(),
            None => scene.background(),
        }
    })
}

/// The Lambert image drawn with `lambert`, the student's own once it passes its
/// check (coding exercise 8.2, `src/course/exercises/ch08.rs`).
pub fn my_lambert_image(
    lambert: mine::Lambert,
    (width, height): (u32, u32),
    threads: Option<usize>,
) -> Result<Framebuffer> {
    let scene = lesson08(Vec3::ZERO)?;
    let [_, pinhole] = lesson08_cameras(width, height, Vec3::ZERO)?;
    render(&pinhole, threads, |r| mine::lit_with(&scene, r, lambert))
}

/// How many pixels show each primitive (in scene order, then the background).
fn coverage(scene: &Scene, camera: &Camera) -> Vec<u32> {
    let (w, h) = (camera.film().width(), camera.film().height());
    let mut counts = vec![0u32; scene.objects().len() + 1];
    for (x, y) in (0..h).flat_map(|y| (0..w).map(move |x| (x, y))) {
        let hit = scene.closest(&camera.ray(x, y), Interval::AHEAD);
        counts[hit.map_or(scene.objects().len(), |found| found.object)] += 1;
    }
    counts
}

/// The lesson's tables: pixels per object for both cameras, the acne count of the
/// far scene, and a few pixels of the Lambert image.
pub fn numbers(
    (width, height): (u32, u32),
    epsilon: f32,
    far: Vec3,
    images: &[Framebuffer; 5],
) -> Result<String> {
    let near = lesson08(Vec3::ZERO)?;
    let [ortho, pinhole] = lesson08_cameras(width, height, Vec3::ZERO)?;
    let mut table = Table::new(
        &format!(
            "Shadowless ray casting, {width} x {height} pixels: pixels showing each primitive"
        ),
        &["primitive", "orthographic", "pinhole"],
    );
    let names = LESSON08_OBJECTS.iter().chain(&["background"]);
    for ((name, o), p) in names
        .zip(coverage(&near, &ortho))
        .zip(coverage(&near, &pinhole))
    {
        table.row(vec![name.to_string(), o.to_string(), p.to_string()]);
    }
    let mut acne = Table::new(
        &format!(
            "Shadow rays, scene moved by {}: pixels differing from the clean image",
            vec3(far, 0)
        ),
        &["shadow-ray start", "pixels", "share"],
    );
    let [_, _, lambert, fixed, scaled] = images;
    let total = f64::from(width * height);
    for (label, img) in [
        (format!("t > {epsilon:e} (fixed)"), fixed),
        ("scaled offset".to_string(), scaled),
    ] {
        let differing = agreement(img, lambert, &[], 2.0 / 255.0).differing;
        let share = format!("{}%", num(100.0 * f64::from(differing) / total, 2));
        acne.row(vec![label, differing.to_string(), share]);
    }
    let mut pixels = Table::new(
        "A few pixels of the Lambert image (linear RGB), at fractions of the width and height",
        &["where", "pixel", "colour"],
    );
    let spots = [
        ("red sphere, lit side", 0.30, 0.40),
        ("floor in the red sphere's shadow", 0.16, 0.60),
        ("floor, lit", 0.85, 0.85),
        ("sky", 0.50, 0.02),
    ];
    for (name, fx, fy) in spots {
        let (x, y) = ((fx * width as f32) as u32, (fy * height as f32) as u32);
        let colour = vec3(lambert.get(x, y).unwrap_or(Vec3::ZERO), 4);
        pixels.row(vec![name.to_string(), format!("({x}, {y})"), colour]);
    }
    Ok(format!("{table}\n{acne}\n{pixels}"))
}

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| {
        let (closest, lambert) = if args.mine {
            let closest = mine::if_passing(mine::my_closest())?;
            (closest, mine::if_passing(mine::my_lambert())?)
        } else {
            (None, None)
        };
        let mine_images = u64::from(closest.is_some()) + u64::from(lambert.is_some());
        let (size, threads) = args.image.check(IMAGES.len() as u64 + mine_images)?;
        non_negative("--epsilon", args.epsilon)?;
        lesson08(args.far).map_err(|_| Error::Invalid {
            param: "--far",
            reason: "moves the scene out of f32's reach (its triangle loses its area)",
        })?;
        let images = images(size, args.epsilon, args.far, threads)?;
        lesson::print(&numbers(size, args.epsilon, args.far, &images)?);
        for (name, image) in IMAGES.iter().zip(&images) {
            args.output.image(name, image)?;
        }
        if let Some(closest) = closest {
            let image = my_shadowless_image(closest, size, threads)?;
            args.output.image("08_shadowless_mine.png", &image)?;
        }
        if let Some(lambert) = lambert {
            let image = my_lambert_image(lambert, size, threads)?;
            args.output.image("08_lambert_mine.png", &image)?;
        }
        Ok(())
    })
}
