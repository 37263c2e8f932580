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
use render_lessons::Result;
use render_lessons::camera::{Camera, Film, Frame, OrthoCamera, PinholeCamera};
use render_lessons::course::lesson::{self, Output, parse_finite, parse_vec3};
use render_lessons::course::report::{Table, num, vec3};
use render_lessons::framebuffer::Framebuffer;
use render_lessons::offset::Offset;
use render_lessons::raycast::{lit, shadowless};
use render_lessons::render::render;
use render_lessons::scene::{Object, PointLight, Scene};
use render_lessons::shapes::{Aabb, Plane, Shape, Sphere, Triangle};

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 08: ray casting, then Lambert shading and shadow rays")]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Image width in pixels.
    #[arg(long, default_value_t = 480)]
    pub width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 270)]
    pub height: u32,
    /// Worker threads (default: every core). The image does not depend on it.
    #[arg(long)]
    pub threads: Option<usize>,
    /// The fixed shadow-ray epsilon whose failure the lesson shows.
    #[arg(long, default_value = "1e-4", value_parser = parse_finite)]
    pub epsilon: f32,
    /// How far the whole scene (and camera) is moved for the acne comparison, as x,y,z.
    #[arg(long, default_value = "10000,0,0", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub far: Vec3,
    #[command(flatten)]
    pub output: Output,
}

// ANCHOR: scene
/// The lesson's scene, moved by `shift`: a floor, three spheres, a box and a
/// triangle, in a plain list, lit by one point light.
pub fn scene(shift: Vec3) -> Result<Scene> {
    let object = |shape, (r, g, b)| Object::diffuse(shape, Vec3::new(r, g, b));
    let sphere = |c: Vec3, r| Sphere::new(c + shift, r).map(Shape::Sphere);
    let objects = vec![
        object(Shape::Plane(Plane::new(shift, Vec3::Y)?), (0.75, 0.75, 0.7)),
        object(sphere(Vec3::new(-1.6, 1.0, 0.0), 1.0)?, (0.85, 0.2, 0.15)),
        object(sphere(Vec3::new(1.3, 0.7, 1.2), 0.7)?, (0.2, 0.35, 0.85)),
        object(sphere(Vec3::new(0.2, 0.4, 2.4), 0.4)?, (0.2, 0.7, 0.3)),
        object(
            Shape::Aabb(Aabb::new(
                Vec3::new(-0.3, 0.0, -2.0) + shift,
                Vec3::new(0.9, 1.6, -0.8) + shift,
            )?),
            (0.9, 0.75, 0.2),
        ),
        object(
            Shape::Triangle(Triangle::new(
                Vec3::new(2.0, 0.0, -2.0) + shift,
                Vec3::new(3.4, 0.0, -1.2) + shift,
                Vec3::new(2.7, 2.2, -1.6) + shift,
            )?),
            (0.6, 0.3, 0.75),
        ),
    ];
    let light = PointLight {
        position: Vec3::new(3.0, 6.0, 4.0) + shift,
        intensity: Vec3::splat(60.0),
    };
    Scene::new(objects, Vec3::new(0.6, 0.75, 0.95)).and_then(|s| s.with_light(light))
}
// ANCHOR_END: scene

// ANCHOR: cameras
/// Both cameras at the same place, looking at the same point. The pinhole's screen
/// sits at the distance of that point, so both frame the same rectangle there.
pub fn cameras(args: &Args, shift: Vec3) -> Result<[Camera; 2]> {
    let eye = Vec3::new(0.0, 3.0, 9.0) + shift;
    let target = Vec3::new(0.0, 0.8, 0.0) + shift;
    let frame = Frame::look(eye, target - eye, Vec3::Y)?;
    let half_height = 2.6;
    let half_width = half_height * args.width as f32 / args.height as f32;
    let film = Film::new(
        args.width,
        args.height,
        (-half_width, half_width),
        (-half_height, half_height),
    )?;
    Ok([
        OrthoCamera::new(film, frame).into(),
        PinholeCamera::new(film, (target - eye).length(), frame)?.into(),
    ])
}
// ANCHOR_END: cameras

/// Every image of the lesson, by file name.
pub fn images(args: &Args) -> Result<Vec<(&'static str, Framebuffer)>> {
    let near = scene(Vec3::ZERO)?;
    let [ortho, pinhole] = cameras(args, Vec3::ZERO)?;
    let far = scene(args.far)?;
    let [_, far_pinhole] = cameras(args, args.far)?;
    let fixed = Offset::Fixed(args.epsilon);
    Ok(vec![
        (
            "08_shadowless_ortho.png",
            render(&ortho, args.threads, |r| shadowless(&near, r))?,
        ),
        (
            "08_shadowless_pinhole.png",
            render(&pinhole, args.threads, |r| shadowless(&near, r))?,
        ),
        (
            "08_lambert.png",
            render(&pinhole, args.threads, |r| {
                lit(&near, r, Offset::Scaled)
            })?,
        ),
        (
            "08_far_fixed_epsilon.png",
            render(&far_pinhole, args.threads, |r| lit(&far, r, fixed))?,
        ),
        (
            "08_far_scaled_offset.png",
            render(&far_pinhole, args.threads, |r| {
                lit(&far, r, Offset::Scaled)
            })?,
        ),
    ])
}

/// How many pixels show each primitive (in scene order, then the background).
fn coverage(scene: &Scene, camera: &Camera) -> Vec<u32> {
    let (w, h) = (camera.film().width(), camera.film().height());
    let mut counts = vec![0u32; scene.objects().len() + 1];
    for (x, y) in (0..h).flat_map(|y| (0..w).map(move |x| (x, y))) {
        let index = match scene.closest_hit(&camera.ray(x, y), 0.0, f32::INFINITY) {
            Some((_, object)) => scene.objects().iter().position(|o| std::ptr::eq(o, object)),
            None => None,
        };
        counts[index.unwrap_or(scene.objects().len())] += 1;
    }
    counts
}

/// The lesson's tables: pixels per object for both cameras, and the acne count.
pub fn numbers(args: &Args, images: &[(&str, Framebuffer)]) -> Result<String> {
    let near = scene(Vec3::ZERO)?;
    let [ortho, pinhole] = cameras(args, Vec3::ZERO)?;
    let names = [
        "floor",
        "red sphere",
        "blue sphere",
        "green sphere",
        "box",
        "triangle",
        "background",
    ];
    let mut table = Table::new(
        &format!(
            "Shadowless ray casting, {} x {} pixels: pixels showing each primitive",
            args.width, args.height
        ),
        &["primitive", "orthographic", "pinhole"],
    );
    for ((name, o), p) in names
        .iter()
        .zip(coverage(&near, &ortho))
        .zip(coverage(&near, &pinhole))
    {
        table.row(vec![name.to_string(), o.to_string(), p.to_string()]);
    }
    let image = |name: &str| images.iter().find(|(n, _)| *n == name).map(|(_, fb)| fb);
    let mut acne = Table::new(
        &format!(
            "Lambert + shadow ray, the scene moved by {}: pixels that differ from the clean image",
            vec3(args.far, 0)
        ),
        &["shadow-ray start", "pixels", "share"],
    );
    if let (Some(fixed), Some(scaled), Some(near_img)) = (
        image("08_far_fixed_epsilon.png"),
        image("08_far_scaled_offset.png"),
        image("08_lambert.png"),
    ) {
        let total = (args.width * args.height) as f64;
        for (label, img) in [
            (format!("t > {:e} (fixed)", args.epsilon), fixed),
            ("scaled offset".to_string(), scaled),
        ] {
            let differing = differing_pixels(img, near_img, 2.0 / 255.0);
            acne.row(vec![
                label,
                differing.to_string(),
                format!("{}%", num(100.0 * differing as f64 / total, 2)),
            ]);
        }
    }
    let mut pixels = Table::new(
        "A few pixels of the Lambert image (linear RGB), at fractions of the width and height",
        &["where", "pixel", "colour"],
    );
    if let Some(lit) = image("08_lambert.png") {
        let spots = [
            ("red sphere, lit side", 0.30, 0.40),
            ("floor in the red sphere's shadow", 0.16, 0.60),
            ("floor, lit", 0.85, 0.85),
            ("sky", 0.50, 0.02),
        ];
        for (name, fx, fy) in spots {
            let (x, y) = (
                (fx * args.width as f32) as u32,
                (fy * args.height as f32) as u32,
            );
            let colour = lit.get(x, y).unwrap_or(Vec3::ZERO);
            pixels.row(vec![
                name.to_string(),
                format!("({x}, {y})"),
                vec3(colour, 4),
            ]);
        }
    }
    Ok(format!("{table}\n{acne}\n{pixels}"))
}

/// How many pixels differ between two images of the same size by more than `tolerance`
/// in some channel.
pub fn differing_pixels(a: &Framebuffer, b: &Framebuffer, tolerance: f32) -> u32 {
    let mut count = 0;
    for y in 0..a.height() {
        for x in 0..a.width() {
            let (pa, pb) = (a.get(x, y), b.get(x, y));
            if pa
                .zip(pb)
                .is_none_or(|(pa, pb)| (pa - pb).abs().max_element() > tolerance)
            {
                count += 1;
            }
        }
    }
    count
}

fn main() -> ExitCode {
    let args = Args::parse();
    lesson::run(|| {
        let images = images(&args)?;
        lesson::print(&numbers(&args, &images)?);
        for (name, image) in &images {
            args.output.image(name, image)?;
        }
        Ok(())
    })
}
