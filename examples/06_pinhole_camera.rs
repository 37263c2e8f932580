//! Lesson 06: the perspective (pinhole) camera (Lecture 4, "Pinhole Camera Setup").
//!
//! Every ray starts at the eye e and goes through the pixel's point s on a screen at
//! distance s in front of the eye: direction (s - e)/|s - e|. Rays fan out, so far
//! things look small: perspective distortion, which the orthographic camera lacks.
//!
//!     cargo run --example 06_pinhole_camera
//!     cargo run --example 06_pinhole_camera -- --screen-distance 4

use std::process::ExitCode;

use clap::Parser;
use glam::{Vec2, Vec3};
use render_lessons::Result;
use render_lessons::camera::{Camera, Film, Frame, OrthoCamera, PinholeCamera};
use render_lessons::course::diagram::{Diagram, Place, palette};
use render_lessons::course::lesson::{self, Output, parse_finite, parse_vec3};
use render_lessons::course::report::{Table, num, vec3};
use render_lessons::framebuffer::Framebuffer;
use render_lessons::ray::Ray;

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 06: the pinhole camera")]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Distance s from the eye to the screen (the screen is lesson 03's [-8, 8] x [-6, 6]).
    #[arg(long, default_value = "8", value_parser = parse_finite)]
    pub screen_distance: f32,
    /// Position p of the arbitrary camera, as x,y,z.
    #[arg(long, default_value = "0,3,6", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub position: Vec3,
    /// View direction d of the arbitrary camera, as x,y,z.
    #[arg(long, default_value = "0,-1,-2", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub direction: Vec3,
    /// Up vector k of the arbitrary camera, as x,y,z.
    #[arg(long, default_value = "0,1,0", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub up: Vec3,
    /// Width in pixels of each of the two views of the floor grid.
    #[arg(long, default_value_t = 320)]
    pub view_width: u32,
    #[command(flatten)]
    pub output: Output,
}

// ANCHOR: camera
/// The pinhole camera at the origin: lesson 03's 4 x 3 film as a screen at z = -s.
pub fn camera_at_origin(args: &Args) -> Result<PinholeCamera> {
    let film = Film::new(4, 3, (-8.0, 8.0), (-6.0, 6.0))?;
    PinholeCamera::at_origin(film, args.screen_distance)
}
// ANCHOR_END: camera

/// The arbitrary pinhole camera: the same film, placed by p, d and k.
pub fn camera_placed(args: &Args) -> Result<PinholeCamera> {
    let film = Film::new(4, 3, (-8.0, 8.0), (-6.0, 6.0))?;
    let frame = Frame::look(args.position, args.direction, args.up)?;
    PinholeCamera::new(film, args.screen_distance, frame)
}

/// The lesson's tables.
pub fn numbers(args: &Args) -> Result<String> {
    let cam = camera_at_origin(args)?;
    let mut at_origin = Table::new(
        &format!(
            "Pinhole camera at the origin: eye e = (0, 0, 0), screen at z = -{}",
            num(args.screen_distance as f64, 2)
        ),
        &["pixel", "screen point s", "ray direction (s - e)/|s - e|"],
    );
    for (x, y) in [(0, 0), (1, 0), (2, 1), (3, 2)] {
        at_origin.row(vec![
            format!("({x}, {y})"),
            vec3(cam.screen_point(x, y), 3),
            vec3(cam.ray(x, y).direction(), 4),
        ]);
    }
    let placed = camera_placed(args)?;
    let mut arbitrary = Table::new(
        &format!(
            "Placed: p = {}, d = {}, k = {}",
            vec3(args.position, 3),
            vec3(args.direction, 3),
            vec3(args.up, 3)
        ),
        &["pixel", "world origin", "world direction"],
    );
    for (x, y) in [(0, 0), (1, 0), (2, 1), (3, 2)] {
        let ray = placed.ray(x, y);
        arbitrary.row(vec![
            format!("({x}, {y})"),
            vec3(ray.origin(), 3),
            vec3(ray.direction(), 4),
        ]);
    }
    Ok(format!("{at_origin}\n{arbitrary}"))
}

/// The figure, seen from the side (z to the right, y up): rays of one image column
/// fan out from the eye through their screen points.
pub fn fan_figure(args: &Args) -> Result<Diagram> {
    let cam = camera_at_origin(args)?;
    let s = cam.screen_distance();
    let (y0, y1) = cam.film().y_extent();
    let reach = 2.0 * s;
    let zy = |p: Vec3| Vec2::new(p.z, p.y);
    let spread = (y1 - y0) / s * reach * 0.5 + 1.0;
    let mut d = Diagram::new(800, 620, (-reach - 1.0, 2.0), (-spread, spread))?;
    d.title("Seen from the side: rays leave the eye e and pass through the screen points s");
    d.axes((-reach - 1.0, 2.0), (-spread, spread), 2.0, ("z", "y"));
    d.line(Vec2::new(-s, y0), Vec2::new(-s, y1), palette::PLANE, 4.0);
    d.text(
        Vec2::new(-s, y0),
        &format!("screen z = -{}", num(s as f64, 1)),
        palette::PLANE,
        Place::Below,
    );
    for y in 0..cam.film().height() {
        let ray = cam.ray(1, y);
        let through = cam.screen_point(1, y);
        let t_end = reach / -ray.direction().z;
        d.arrow(zy(ray.origin()), zy(ray.at(t_end)), palette::RAY, 2.0);
        d.dot(zy(through), 4.5, palette::HIT);
        d.text(
            zy(through),
            &format!("s, row {y}"),
            palette::INK,
            Place::Right,
        );
    }
    d.dot(Vec2::ZERO, 6.0, palette::CAMERA);
    d.text(Vec2::ZERO, "e", palette::CAMERA, Place::Right);
    Ok(d)
}

// ANCHOR: floor
/// The colour seen along a ray: a checkerboard on the floor y = 0 (squares of side 1),
/// found by solving o_y + t d_y = 0 for t; the sky where the ray never reaches it.
pub fn floor_colour(ray: &Ray) -> Vec3 {
    let (o, d) = (ray.origin(), ray.direction());
    let t = -o.y / d.y;
    if !(t > 0.0 && t.is_finite()) {
        return Vec3::new(0.6, 0.75, 0.95);
    }
    let p = ray.at(t);
    let dark = (p.x.floor() + p.z.floor()) as i64 % 2 == 0;
    if dark {
        Vec3::splat(0.1)
    } else {
        Vec3::splat(0.8)
    }
}
// ANCHOR_END: floor

// ANCHOR: side_by_side
/// The same floor through both cameras, from the same place: orthographic on the
/// left, pinhole on the right. The orthographic view keeps every square the same
/// size; the pinhole view shrinks squares with distance and makes parallel lines meet.
pub fn side_by_side(args: &Args) -> Result<Framebuffer> {
    let (w, h) = (args.view_width, args.view_width * 3 / 4);
    let film = Film::new(w, h, (-4.0, 4.0), (-3.0, 3.0))?;
    let frame = Frame::look(args.position, args.direction, args.up)?;
    let cameras: [Camera; 2] = [
        OrthoCamera::new(film, frame).into(),
        PinholeCamera::new(film, args.screen_distance * 0.5, frame)?.into(),
    ];
    Framebuffer::from_fn(2 * w, h, |x, y| {
        let camera = &cameras[(x / w) as usize];
        floor_colour(&camera.ray(x % w, y))
    })
}
// ANCHOR_END: side_by_side

fn main() -> ExitCode {
    let args = Args::parse();
    lesson::run(|| {
        lesson::print(&numbers(&args)?);
        args.output
            .diagram("06_pinhole_rays.png", &fan_figure(&args)?)?;
        args.output
            .image("06_ortho_vs_pinhole.png", &side_by_side(&args)?)
    })
}
