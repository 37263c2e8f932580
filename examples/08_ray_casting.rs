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

use std::process::ExitCode;

use clap::Parser;
use glam::Vec3;
use render_lessons::course::failure::LessonResult;
use render_lessons::course::image_tables::{
    coverage_table, differing_table, spots_table,
};
use render_lessons::course::lesson::{self, ImageFlags, Output};
use render_lessons::course::mine::{self, Picture};
use render_lessons::course::parsers;
use render_lessons::course::report::vec3;
use render_lessons::error::Problem;
use render_lessons::framebuffer::Framebuffer;
use render_lessons::lesson_images;
use render_lessons::ray::Interval;
use render_lessons::raycast::{lit, shadowless};
use render_lessons::render::render;
use render_lessons::scenes::{STILL_LIFE_OBJECTS, still_life, still_life_cameras};
use render_lessons::spawn::Offset;
use render_lessons::{Error, Result};

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    let mine = || my_pictures(args.mine);
    args.image
        .run_with_mine(Images::COUNT, &args.output, mine, |size| {
            let images = images(size, args.epsilon, args.far)?;
            lesson::print(&numbers(size, args.epsilon, args.far, &images)?);
            Ok(args.output.images(images.named())?)
        })
}

// ANCHOR: images
/// Every image of the lesson: the scene shadowless through both cameras, lit with
/// shadow rays, and lit again moved by `far`, where a fixed shadow-ray `epsilon`
/// fails and the scaled offset does not.
pub fn images((width, height): (u32, u32), epsilon: f32, far: Vec3) -> Result<Images> {
    let near = still_life(Vec3::ZERO)?;
    let [ortho, pinhole] = still_life_cameras(width, height, Vec3::ZERO)?;
    let far_scene = still_life(far).map_err(|_| Error::Value {
        param: "far",
        problem: Problem::Invalid {
            reason: "moves the scene out of f32's reach (its triangle loses its area)",
        },
    })?;
    let [_, far_pinhole] = still_life_cameras(width, height, far)?;
    Ok(Images {
        shadowless_ortho: render(&ortho, |r| shadowless(&near, r))?,
        shadowless_pinhole: render(&pinhole, |r| shadowless(&near, r))?,
        lambert: render(&pinhole, |r| lit(&near, r, Offset::Scaled))?,
        far_fixed_epsilon: render(&far_pinhole, |r| {
            lit(&far_scene, r, Offset::Fixed(epsilon))
        })?,
        far_scaled_offset: render(&far_pinhole, |r| {
            lit(&far_scene, r, Offset::Scaled)
        })?,
    })
}
// ANCHOR_END: images

lesson_images! {
    /// The lesson's images, each beside the file it is saved as.
    Images {
        shadowless_ortho: "08_shadowless_ortho.png",
        shadowless_pinhole: "08_shadowless_pinhole.png",
        lambert: "08_lambert.png",
        far_fixed_epsilon: "08_far_fixed_epsilon.png",
        far_scaled_offset: "08_far_scaled_offset.png",
    }
}

/// The lesson's tables: pixels per object for both cameras, the acne count of the
/// far scene, and a few pixels of the Lambert image.
pub fn numbers(
    (width, height): (u32, u32),
    epsilon: f32,
    far: Vec3,
    images: &Images,
) -> Result<String> {
    let near = still_life(Vec3::ZERO)?;
    let [ortho, pinhole] = still_life_cameras(width, height, Vec3::ZERO)?;
    let title = format!(
        "Shadowless ray casting, {width} x {height} pixels: pixels showing each primitive"
    );
    let cameras = [("orthographic", &ortho), ("pinhole", &pinhole)];
    let coverage = coverage_table(&title, &near, &STILL_LIFE_OBJECTS, &cameras);
    let (lambert, fixed, scaled) = (
        &images.lambert,
        &images.far_fixed_epsilon,
        &images.far_scaled_offset,
    );
    let title = format!(
        "Shadow rays, scene moved by {}: pixels differing from the clean image",
        vec3(far, 0)
    );
    let starts = [
        (format!("t > {epsilon:e} (fixed)"), fixed),
        ("scaled offset".to_string(), scaled),
    ];
    let acne = differing_table(&title, "shadow-ray start", lambert, &starts);
    let title = "A few pixels of the Lambert image (linear RGB), at fractions of the width and height";
    let spots = [
        ("red sphere, lit side", 0.30, 0.40),
        ("floor in the red sphere's shadow", 0.16, 0.60),
        ("floor, lit", 0.85, 0.85),
        ("sky", 0.50, 0.02),
    ];
    let pixels = spots_table(title, lambert, &spots);
    Ok(format!("{coverage}\n{acne}\n{pixels}"))
}

/// With `--mine`, the pictures drawn with the student's functions that pass their
/// checks ([`mine::if_passing`]): the shadowless pinhole image with `closest`, as
/// `08_shadowless_mine.png`, and the Lambert image with `lambert`, as
/// `08_lambert_mine.png`.
fn my_pictures(mine: bool) -> LessonResult<Vec<Picture>> {
    let mut pictures = Vec::new();
    if !mine {
        return Ok(pictures);
    }
    if let Some(closest) = mine::if_passing(mine::my_closest())? {
        let draw = move |size| my_shadowless_image(closest, size);
        pictures.push(Picture::new(
            "08_shadowless_mine.png",
            "08_shadowless_pinhole.png",
            draw,
        ));
    }
    if let Some(lambert) = mine::if_passing(mine::my_lambert())? {
        let draw = move |size| my_lambert_image(lambert, size);
        pictures.push(Picture::new("08_lambert_mine.png", "08_lambert.png", draw));
    }
    Ok(pictures)
}

/// The shadowless pinhole image drawn with `closest`, the student's own once it
/// passes its check (coding exercise 8.3, `src/course/exercises/ch08.rs`).
pub fn my_shadowless_image(
    closest: mine::Closest,
    (width, height): (u32, u32),
) -> Result<Framebuffer> {
    let scene = still_life(Vec3::ZERO)?;
    let [_, pinhole] = still_life_cameras(width, height, Vec3::ZERO)?;
    let shapes: Vec<_> = scene.objects().iter().map(|o| o.shape.clone()).collect();
    render(&pinhole, |r| match closest(r, &shapes, Interval::AHEAD) {
        Some(found) => scene.object(&found).colour(),
        None => scene.background(),
    })
}

/// The Lambert image drawn with `lambert`, the student's own once it passes its
/// check (coding exercise 8.7, `src/course/exercises/ch08.rs`).
pub fn my_lambert_image(
    lambert: mine::Lambert,
    (width, height): (u32, u32),
) -> Result<Framebuffer> {
    let scene = still_life(Vec3::ZERO)?;
    let [_, pinhole] = still_life_cameras(width, height, Vec3::ZERO)?;
    render(&pinhole, |r| mine::lit_with(&scene, r, lambert))
}

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 08: ray casting, then Lambert shading and shadow rays")]
#[command(allow_negative_numbers = true)]
struct Args {
    #[command(flatten)]
    image: ImageFlags,
    /// The fixed shadow-ray epsilon whose failure the lesson shows (0 or more).
    #[arg(long, default_value = "1e-4", value_parser = parsers::non_negative)]
    epsilon: f32,
    /// How far the whole scene (and camera) is moved for the acne comparison, as x,y,z.
    #[arg(long, default_value = "10000,0,0", value_parser = parsers::vec3, allow_hyphen_values = true)]
    far: Vec3,
    /// Also draw the shadowless pinhole image with your own `closest` (coding exercise
    /// 8.3) and the Lambert image with your own `lambert` (8.7):
    /// `cargo run --release --example 08_ray_casting -- --mine`.
    #[arg(long)]
    mine: bool,
    #[command(flatten)]
    output: Output,
}
