//! Lesson 03: the orthographic camera at the origin, looking down -Z (Lecture 4).
//!
//! Each pixel's ray starts at the pixel's centre on the projection plane z = 0 and
//! travels along (0, 0, -1). With the plane [-8, 8] x [-6, 6] cut into 4 x 3 pixels,
//! pixel (0, 0) (top left) gets the ray origin (-6, 4, 0), as on the slide.
//!
//!     cargo run --example 03_ortho_camera
//!     cargo run --example 03_ortho_camera -- --width 8 --height 6

use std::process::ExitCode;

use clap::Parser;
use glam::{Vec2, Vec3};
use render_lessons::Result;
use render_lessons::camera::{Film, OrthoCamera};
use render_lessons::course::diagram::{CameraRays, Diagram, View};
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::mine;
use render_lessons::course::parsers;
use render_lessons::course::report::{Table, num, vec3};
use render_lessons::framebuffer::Framebuffer;

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| {
        let x = lesson::extent("--x-min/--x-max", args.x_min, args.x_max)?;
        let y = lesson::extent("--y-min/--y-max", args.y_min, args.y_max)?;
        let cam = camera(args.width, args.height, x, y)?;
        let pixel_to_plane = args.mine.then(mine::my_pixel_to_plane).transpose()?;
        lesson::print(&numbers(&cam));
        let out = &args.output;
        out.diagram("03_plane.png", &plane_figure(cam.film())?)?;
        out.diagram("03_rays.png", &rays_figure(&cam)?)?;
        let picture = Film::new(320, 240, x, y)?;
        out.image("03_origins.png", &origin_image(&picture)?)?;
        if let Some(pixel_to_plane) = pixel_to_plane {
            let image = my_origin_image(&picture, pixel_to_plane)?;
            out.image("03_origins_mine.png", &image)?;
        }
        Ok(())
    })
}

// ANCHOR: camera
/// The lesson's camera: at the origin, looking down -Z, over the plane `x` by `y`
/// (x_min, x_max and y_min, y_max) cut into `width` x `height` pixels.
pub fn camera(
    width: u32,
    height: u32,
    x: (f32, f32),
    y: (f32, f32),
) -> Result<OrthoCamera> {
    Ok(OrthoCamera::at_origin(Film::new(width, height, x, y)?))
}
// ANCHOR_END: camera

/// Most rows the table prints before it stops listing pixels.
pub const MAX_ROWS: u32 = 24;

/// The lesson's table: each pixel's ray, row by row from the top.
pub fn numbers(cam: &OrthoCamera) -> String {
    let film = cam.film();
    let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
    let (w, h) = (film.width(), film.height());
    let [x0, x1, y0, y1] = [x0, x1, y0, y1].map(|e| num(e as f64, 2));
    let title = format!(
        "Orthographic camera: plane [{x0}, {x1}] x [{y0}, {y1}], {w} x {h} pixels, row 0 on top"
    );
    let mut table = Table::new(&title, &["pixel", "ray origin", "ray direction"]);
    // ANCHOR: table
    let pixels =
        (0..film.height()).flat_map(|y| (0..film.width()).map(move |x| (x, y)));
    for (x, y) in pixels.take(MAX_ROWS as usize) {
        let ray = cam.ray(x, y);
        table.row(vec![
            format!("({x}, {y})"),
            vec3(ray.origin(), 3),
            vec3(ray.direction(), 3),
        ]);
    }
    // ANCHOR_END: table
    match (w * h).saturating_sub(MAX_ROWS) {
        0 => table.to_string(),
        more => format!("{table}... ({more} more pixels)\n"),
    }
}

/// The front view: the projection plane, its pixel grid and every pixel centre.
pub fn plane_figure(film: &Film) -> Result<Diagram> {
    let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
    let pad = 0.15 * (x1 - x0).max(y1 - y0);
    let (x, y) = ((x0 - pad, x1 + pad), (y0 - pad, y1 + pad));
    let mut d = Diagram::new(800, 620, x, y)?;
    d.title(
        "The projection plane seen from the camera: pixel centres are the ray origins",
    );
    d.axes(x, y, (x1 - x0) / 4.0, ("x", "y"));
    d.film(film);
    Ok(d)
}

// ANCHOR: rays_figure
/// The side view (z to the right, y up): parallel rays leave the plane along -Z.
pub fn rays_figure(cam: &OrthoCamera) -> Result<Diagram> {
    let (y0, y1) = cam.film().y_extent();
    let (length, pad) = (1.2 * (y1 - y0), 0.15 * (y1 - y0));
    let (z, y) = ((-length - pad, 2.0 * pad), (y0 - pad, y1 + pad));
    let mut d = Diagram::new(800, 620, z, y)?;
    d.title(
        "Seen from the side: every ray starts on z = 0 and travels along (0, 0, -1)",
    );
    let step = ((y1 - y0) / 6.0).max(0.5).round();
    d.axes(z, y, step, View::Side.axis_names());
    CameraRays::side(*cam, length)
        .column(0)
        .plane("projection plane z = 0")
        .labels(|_, y| format!("row {y}"))
        .draw(&mut d);
    Ok(d)
}
// ANCHOR_END: rays_figure

// ANCHOR: origin_image
/// An image whose colour encodes each pixel's ray origin: red grows with x, green
/// with y, across the plane. Row 0, at the top of the file, is the top of the plane.
pub fn origin_image(film: &Film) -> Result<Framebuffer> {
    let cam = OrthoCamera::at_origin(*film);
    colour_by_origin(film, |x, y| cam.ray(x, y).origin().truncate())
}

/// Colours each pixel by where `origin(x, y)` lies on the film's plane.
pub fn colour_by_origin(
    film: &Film,
    origin: impl Fn(u32, u32) -> Vec2,
) -> Result<Framebuffer> {
    let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
    Framebuffer::from_fn(film.width(), film.height(), |x, y| {
        let o = origin(x, y);
        Vec3::new((o.x - x0) / (x1 - x0), (o.y - y0) / (y1 - y0), 0.25)
    })
}
// ANCHOR_END: origin_image

/// The origin image drawn with `pixel_to_plane`, the student's own once it passes
/// its check (coding exercise 3.5, `src/course/exercises/ch03.rs`).
pub fn my_origin_image(
    film: &Film,
    pixel_to_plane: mine::PixelToPlane,
) -> Result<Framebuffer> {
    colour_by_origin(film, |x, y| pixel_to_plane(film, x, y))
}

/// The lesson's parameters; the defaults reproduce the slide's pixel (0,0) -> (-6, 4,
/// 0).
#[derive(Parser, Debug)]
#[command(about = "Lesson 03: the orthographic camera at the origin")]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Image width in pixels (resolution_x).
    #[arg(long, default_value_t = 4)]
    pub width: u32,
    /// Image height in pixels (resolution_y).
    #[arg(long, default_value_t = 3)]
    pub height: u32,
    /// Left edge of the projection plane.
    #[arg(long, default_value = "-8", value_parser = parsers::finite)]
    pub x_min: f32,
    /// Right edge of the projection plane.
    #[arg(long, default_value = "8", value_parser = parsers::finite)]
    pub x_max: f32,
    /// Bottom edge of the projection plane.
    #[arg(long, default_value = "-6", value_parser = parsers::finite)]
    pub y_min: f32,
    /// Top edge of the projection plane.
    #[arg(long, default_value = "6", value_parser = parsers::finite)]
    pub y_max: f32,
    /// Also draw the origin image with your own `pixel_to_plane` (coding exercise 3.5):
    /// `cargo run --example 03_ortho_camera -- --mine`.
    #[arg(long)]
    pub mine: bool,
    #[command(flatten)]
    pub output: Output,
}
