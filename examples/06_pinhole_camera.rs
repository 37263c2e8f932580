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
use glam::Vec3;
use render_lessons::Result;
use render_lessons::camera::{Camera, Film, Frame, OrthoCamera, PinholeCamera};
use render_lessons::course::diagram::{CameraRays, Diagram, Place, View};
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::report::{Table, num, vec3};
use render_lessons::course::{mine, parsers};
use render_lessons::framebuffer::Framebuffer;
use render_lessons::limits::MAX_RESOLUTION;
use render_lessons::ray::Ray;

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| {
        let (s, d, k) = (args.screen_distance, args.direction, args.up);
        let frame = Frame::look(args.position, d, k)?;
        let [at_origin, placed] = cameras(s, frame)?;
        let view_width = args.view_width;
        let views = views(frame, view_width, s * 0.5)?;
        let pinhole_ray = args.mine.then(mine::my_pinhole_ray).transpose()?;
        lesson::print(&numbers(&at_origin, &placed, d, k));
        let out = &args.output;
        out.diagram("06_pinhole_rays.png", &fan_figure(&at_origin)?)?;
        out.image("06_ortho_vs_pinhole.png", &side_by_side(&views)?)?;
        if let Some(pinhole_ray) = pinhole_ray {
            let image = my_pinhole_view(frame, view_width, s * 0.5, pinhole_ray)?;
            out.image("06_pinhole_mine.png", &image)?;
        }
        Ok(())
    })
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

// ANCHOR: camera
/// The lesson's two pinhole cameras, with lesson 03's 4 x 3 film [-8, 8] x [-6, 6] as
/// their screen at distance `s` from the eye: one at the origin, one placed by `frame`.
pub fn cameras(s: f32, frame: Frame) -> Result<[PinholeCamera; 2]> {
    let film = Film::new(4, 3, (-8.0, 8.0), (-6.0, 6.0))?;
    Ok([
        PinholeCamera::at_origin(film, s)?,
        PinholeCamera::new(film, s, frame)?,
    ])
}
// ANCHOR_END: camera

/// The lesson's tables: the pinhole at the origin (screen points and directions), then
/// the placed camera's world rays; `d` and `k` are the placed camera's flags.
pub fn numbers(
    at_origin: &PinholeCamera,
    placed: &PinholeCamera,
    d: Vec3,
    k: Vec3,
) -> String {
    let s = num(at_origin.screen_distance() as f64, 2);
    let mut origin_table = Table::new(
        &format!("Pinhole camera at the origin: eye e = (0, 0, 0), screen at z = -{s}"),
        &["pixel", "screen point s", "ray direction (s - e)/|s - e|"],
    );
    let p = placed.frame().position();
    let (p, d, k) = (vec3(p, 3), vec3(d, 3), vec3(k, 3));
    let mut placed_table = Table::new(
        &format!("Placed: p={p}, d={d}, k={k}"),
        &["pixel", "world origin", "world direction"],
    );
    for (x, y) in [(0, 0), (1, 0), (2, 1), (3, 2)] {
        origin_table.row(vec![
            format!("({x}, {y})"),
            vec3(at_origin.screen_point(Film::pixel_centre(x, y)), 3),
            vec3(at_origin.ray(x, y).direction(), 4),
        ]);
        let ray = placed.ray(x, y);
        placed_table.row(vec![
            format!("({x}, {y})"),
            vec3(ray.origin(), 3),
            vec3(ray.direction(), 4),
        ]);
    }
    format!("{origin_table}\n{placed_table}")
}

/// The figure, seen from the side (z to the right, y up): rays of one image column
/// fan out from the eye through their screen points.
pub fn fan_figure(cam: &PinholeCamera) -> Result<Diagram> {
    let s = cam.screen_distance();
    let (y0, y1) = cam.film().y_extent();
    let reach = 2.0 * s;
    let spread = (y1 - y0) / s * reach * 0.5 + 1.0;
    let (z, y) = ((-reach - 1.0, 2.0), (-spread, spread));
    let mut d = Diagram::new(800, 620, z, y)?;
    d.title(
        "Seen from the side: rays leave the eye e and pass through the screen points s",
    );
    d.axes(z, y, 2.0, View::Side.axis_names());
    CameraRays::side(*cam, reach)
        .column(1)
        .plane(format!("screen z = -{}", num(s as f64, 1)))
        .labels(|_, y| format!("s, row {y}"))
        .eye("e", Place::Right)
        .sizes(2.0, 4.5)
        .draw(&mut d);
    Ok(d)
}

// ANCHOR: side_by_side
/// The two cameras of the comparison, placed by the same frame: orthographic and
/// pinhole (screen distance `s`), each with `width` x 3/4 `width` pixels over the
/// film [-4, 4] x [-3, 3].
pub fn views(frame: Frame, width: u32, s: f32) -> Result<[Camera; 2]> {
    let film = Film::new(width, width * 3 / 4, (-4.0, 4.0), (-3.0, 3.0))?;
    Ok([
        OrthoCamera::new(film, frame).into(),
        PinholeCamera::new(film, s, frame)?.into(),
    ])
}

/// The same floor through both cameras, side by side: orthographic on the left,
/// pinhole on the right. The orthographic view keeps every square the same size; the
/// pinhole view shrinks squares with distance and makes parallel lines meet.
pub fn side_by_side(cameras: &[Camera; 2]) -> Result<Framebuffer> {
    let (w, h) = (cameras[0].film().width(), cameras[0].film().height());
    Framebuffer::from_fn(2 * w, h, |x, y| {
        let camera = &cameras[(x / w) as usize];
        floor_colour(&camera.ray(x % w, y))
    })
}
// ANCHOR_END: side_by_side

/// The pinhole half of the comparison drawn with `pinhole_ray`, the student's own
/// once it passes its check (coding exercise 6.3, `src/course/exercises/ch06.rs`).
pub fn my_pinhole_view(
    frame: Frame,
    width: u32,
    s: f32,
    pinhole_ray: mine::PinholeRay,
) -> Result<Framebuffer> {
    let film = Film::new(width, width * 3 / 4, (-4.0, 4.0), (-3.0, 3.0))?;
    Framebuffer::from_fn(film.width(), film.height(), |x, y| {
        let (origin, direction) = pinhole_ray(&film, s, &frame, x, y);
        Ray::new(origin, direction)
            .map_or(Vec3::new(1.0, 0.0, 1.0), |r| floor_colour(&r))
    })
}

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 06: the pinhole camera")]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Distance s from the eye to the screen (lesson 03's [-8, 8] x [-6, 6]).
    #[arg(long, default_value = "8", value_parser = parsers::finite)]
    pub screen_distance: f32,
    /// Position p of the arbitrary camera, as x,y,z.
    #[arg(long, default_value = "0,3,6", value_parser = parsers::vec3, allow_hyphen_values = true)]
    pub position: Vec3,
    /// View direction d of the arbitrary camera, as x,y,z.
    #[arg(long, default_value = "0,-1,-2", value_parser = parsers::vec3, allow_hyphen_values = true)]
    pub direction: Vec3,
    /// Up vector k of the arbitrary camera, as x,y,z.
    #[arg(long, default_value = "0,1,0", value_parser = parsers::vec3, allow_hyphen_values = true)]
    pub up: Vec3,
    /// Width in pixels of each of the two views of the floor grid.
    #[arg(long, default_value_t = 320, value_parser = parsers::pixels(MAX_RESOLUTION / 2))]
    pub view_width: u32,
    /// Also draw the pinhole view with your own `pinhole_ray` (coding exercise 6.3):
    /// `cargo run --example 06_pinhole_camera -- --mine`.
    #[arg(long)]
    pub mine: bool,
    #[command(flatten)]
    pub output: Output,
}
