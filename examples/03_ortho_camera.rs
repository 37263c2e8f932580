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
use render_lessons::course::diagram::{Diagram, Place, palette};
use render_lessons::course::lesson::{self, Output, parse_finite};
use render_lessons::course::report::{Table, num, vec3};
use render_lessons::framebuffer::Framebuffer;

/// The lesson's parameters; the defaults reproduce the slide's pixel (0,0) -> (-6, 4, 0).
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
    #[arg(long, default_value = "-8", value_parser = parse_finite)]
    pub x_min: f32,
    /// Right edge of the projection plane.
    #[arg(long, default_value = "8", value_parser = parse_finite)]
    pub x_max: f32,
    /// Bottom edge of the projection plane.
    #[arg(long, default_value = "-6", value_parser = parse_finite)]
    pub y_min: f32,
    /// Top edge of the projection plane.
    #[arg(long, default_value = "6", value_parser = parse_finite)]
    pub y_max: f32,
    /// Also draw the origin image with your own `pixel_to_plane` (coding exercise 3.1):
    /// `cargo run --features exercises --example 03_ortho_camera -- --mine`.
    #[arg(long)]
    pub mine: bool,
    #[command(flatten)]
    pub output: Output,
}

/// The plane of the flags, cut into `width` x `height` pixels.
pub fn film(args: &Args, width: u32, height: u32) -> Result<Film> {
    Film::new(
        width,
        height,
        (args.x_min, args.x_max),
        (args.y_min, args.y_max),
    )
}

// ANCHOR: camera
/// The lesson's camera: at the origin, looking down -Z, over the given plane.
pub fn camera(args: &Args) -> Result<OrthoCamera> {
    let film = Film::new(
        args.width,
        args.height,
        (args.x_min, args.x_max),
        (args.y_min, args.y_max),
    )?;
    Ok(OrthoCamera::at_origin(film))
}
// ANCHOR_END: camera

/// Most rows the table prints before it stops listing pixels.
pub const MAX_ROWS: u32 = 24;

/// The lesson's table: each pixel's ray.
pub fn numbers(args: &Args) -> Result<String> {
    let cam = camera(args)?;
    let film = cam.film();
    let mut table = Table::new(
        &format!(
            "Orthographic camera: plane [{}, {}] x [{}, {}], {} x {} pixels, row 0 at the top",
            num(film.x_extent().0 as f64, 2),
            num(film.x_extent().1 as f64, 2),
            num(film.y_extent().0 as f64, 2),
            num(film.y_extent().1 as f64, 2),
            film.width(),
            film.height()
        ),
        &["pixel", "ray origin", "ray direction"],
    );
    // ANCHOR: table
    let pixels = (0..film.height()).flat_map(|y| (0..film.width()).map(move |x| (x, y)));
    for (x, y) in pixels.take(MAX_ROWS as usize) {
        let ray = cam.ray(x, y);
        table.row(vec![
            format!("({x}, {y})"),
            vec3(ray.origin(), 3),
            vec3(ray.direction(), 3),
        ]);
    }
    // ANCHOR_END: table
    let shown = (film.width() * film.height()).min(MAX_ROWS);
    let mut text = table.to_string();
    if shown < film.width() * film.height() {
        text.push_str(&format!(
            "... ({} more pixels)\n",
            film.width() * film.height() - shown
        ));
    }
    Ok(text)
}

/// The front view: the projection plane, its pixel grid and every pixel centre.
pub fn plane_figure(args: &Args) -> Result<Diagram> {
    let cam = camera(args)?;
    let film = cam.film();
    let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
    let pad = 0.15 * (x1 - x0).max(y1 - y0);
    let mut d = Diagram::new(800, 620, (x0 - pad, x1 + pad), (y0 - pad, y1 + pad))?;
    d.title("The projection plane seen from the camera: pixel centres are the ray origins");
    d.axes(
        (x0 - pad, x1 + pad),
        (y0 - pad, y1 + pad),
        (x1 - x0) / 4.0,
        ("x", "y"),
    );
    let corners = [
        Vec2::new(x0, y0),
        Vec2::new(x1, y0),
        Vec2::new(x1, y1),
        Vec2::new(x0, y1),
    ];
    d.fill(&corners, palette::PLANE, 40);
    d.outline(&corners, palette::PLANE, 2.0);
    let (cw, ch) = (
        (x1 - x0) / film.width() as f32,
        (y1 - y0) / film.height() as f32,
    );
    for i in 1..film.width() {
        let x = x0 + i as f32 * cw;
        d.line(Vec2::new(x, y0), Vec2::new(x, y1), palette::PLANE, 1.0);
    }
    for j in 1..film.height() {
        let y = y0 + j as f32 * ch;
        d.line(Vec2::new(x0, y), Vec2::new(x1, y), palette::PLANE, 1.0);
    }
    let labelled = film.width() * film.height() <= 48;
    for y in 0..film.height() {
        for x in 0..film.width() {
            let o = cam.ray(x, y).origin();
            d.dot(o.truncate(), 4.0, palette::HIT);
            if labelled {
                let at = format!("({}, {})", num(o.x as f64, 1), num(o.y as f64, 1));
                d.text(
                    o.truncate(),
                    &format!("pixel ({x},{y})"),
                    palette::INK,
                    Place::Above,
                );
                d.text(o.truncate(), &at, palette::HIT, Place::Below);
            }
        }
    }
    Ok(d)
}

/// The side view (z to the right, y up): parallel rays leave the plane along -Z.
pub fn rays_figure(args: &Args) -> Result<Diagram> {
    let cam = camera(args)?;
    let film = cam.film();
    let (y0, y1) = film.y_extent();
    let length = 1.2 * (y1 - y0);
    let zy = |p: Vec3| Vec2::new(p.z, p.y);
    let pad = 0.15 * (y1 - y0);
    let mut d = Diagram::new(800, 620, (-length - pad, 2.0 * pad), (y0 - pad, y1 + pad))?;
    d.title("Seen from the side: every ray starts on z = 0 and travels along (0, 0, -1)");
    d.axes(
        (-length - pad, 2.0 * pad),
        (y0 - pad, y1 + pad),
        ((y1 - y0) / 6.0).max(0.5).round(),
        ("z", "y"),
    );
    d.line(Vec2::new(0.0, y0), Vec2::new(0.0, y1), palette::PLANE, 4.0);
    d.text(
        Vec2::new(0.0, y0),
        "projection plane z = 0",
        palette::PLANE,
        Place::Below,
    );
    let column = 0;
    for y in 0..film.height() {
        let ray = cam.ray(column, y);
        d.arrow(zy(ray.origin()), zy(ray.at(length)), palette::RAY, 2.0);
        d.dot(zy(ray.origin()), 4.0, palette::HIT);
        d.text(
            zy(ray.origin()),
            &format!("row {y}"),
            palette::INK,
            Place::Right,
        );
    }
    Ok(d)
}

// ANCHOR: origin_image
/// An image whose colour encodes each pixel's ray origin: red grows with x, green
/// with y, across the plane. Row 0, at the top of the file, is the top of the plane.
pub fn origin_image(args: &Args, width: u32, height: u32) -> Result<Framebuffer> {
    let film = film(args, width, height)?;
    let cam = OrthoCamera::at_origin(film);
    colour_by_origin(&film, |x, y| cam.ray(x, y).origin().truncate())
}

/// Colours each pixel by where `origin(x, y)` lies on the film's plane.
pub fn colour_by_origin(film: &Film, origin: impl Fn(u32, u32) -> Vec2) -> Result<Framebuffer> {
    let ((x0, x1), (y0, y1)) = (film.x_extent(), film.y_extent());
    Framebuffer::from_fn(film.width(), film.height(), |x, y| {
        let o = origin(x, y);
        Vec3::new((o.x - x0) / (x1 - x0), (o.y - y0) / (y1 - y0), 0.25)
    })
}
// ANCHOR_END: origin_image

/// The origin image drawn with the student's own `pixel_to_plane`, once it passes its
/// check (coding exercise 3.1, `src/course/exercises/ch03.rs`).
pub fn my_origin_image(args: &Args, width: u32, height: u32) -> Result<Framebuffer> {
    let film = film(args, width, height)?;
    #[cfg(feature = "exercises")]
    {
        use render_lessons::course::exercises::{ch03, check};
        let outcome = check::check_pixel_to_plane(ch03::pixel_to_plane);
        if !matches!(outcome, check::Outcome::Pass) {
            let report = check::PIXEL_TO_PLANE.report(&outcome);
            return Err(render_lessons::Error::Exercise { report });
        }
        let (x, y) = (film.x_extent(), film.y_extent());
        colour_by_origin(&film, |px, py| {
            ch03::pixel_to_plane(x, y, width, height, px, py)
        })
    }
    #[cfg(not(feature = "exercises"))]
    {
        let _ = film;
        Err(render_lessons::Error::Exercise {
            report: "--mine runs your code for coding exercise 3.1; turn the exercises on: \
                     cargo run --features exercises --example 03_ortho_camera -- --mine"
                .into(),
        })
    }
}

fn main() -> ExitCode {
    let args = Args::parse();
    lesson::run(|| {
        lesson::print(&numbers(&args)?);
        args.output.diagram("03_plane.png", &plane_figure(&args)?)?;
        args.output.diagram("03_rays.png", &rays_figure(&args)?)?;
        args.output
            .image("03_origins.png", &origin_image(&args, 320, 240)?)?;
        if args.mine {
            args.output
                .image("03_origins_mine.png", &my_origin_image(&args, 320, 240)?)?;
        }
        Ok(())
    })
}
