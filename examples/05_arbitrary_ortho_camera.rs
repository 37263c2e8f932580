//! Lesson 05: an orthographic camera anywhere (Lecture 4, "Arbitrary Orthographic
//! Camera").
//!
//! From the camera position p, view direction d and up vector k we build the
//! camera basis w, u, v; each ray is made in camera space as in lesson 03 and then
//! carried to the world: origin B o + p, direction B d.
//!
//!     cargo run --example 05_arbitrary_ortho_camera
//!     cargo run --example 05_arbitrary_ortho_camera -- --position 0,5,0 --direction 0,-1,0 --up 0,0,-1

use std::process::ExitCode;

use clap::Parser;
use glam::{Vec2, Vec3};
use render_lessons::Result;
use render_lessons::camera::{Film, Frame, OrthoCamera};
use render_lessons::course::diagram::{CameraRays, Diagram, Place, View, extent};
use render_lessons::course::lesson::{self, Output};
use render_lessons::course::parsers;
use render_lessons::course::report::{Table, vec3};

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    lesson::run(|| {
        let (p, d, k) = (args.position, args.direction, args.up);
        let cam = camera(args.width, args.height, p, d, k)?;
        lesson::print(&numbers(&cam, d, k));
        let figure = top_figure(&cam)?;
        args.output.diagram("05_camera_from_above.png", &figure)?;
        Ok(())
    })
}

// ANCHOR: camera
/// The lesson's camera: lesson 03's plane [-8, 8] x [-6, 6], placed by p, d and k.
pub fn camera(
    width: u32,
    height: u32,
    p: Vec3,
    d: Vec3,
    k: Vec3,
) -> Result<OrthoCamera> {
    let film = Film::new(width, height, (-8.0, 8.0), (-6.0, 6.0))?;
    let frame = Frame::look(p, d, k)?;
    Ok(OrthoCamera::new(film, frame))
}
// ANCHOR_END: camera

/// The lesson's tables: the basis built from d and k, then every pixel's ray (at most
/// 6 x 6) in camera space and in the world.
pub fn numbers(cam: &OrthoCamera, d: Vec3, k: Vec3) -> String {
    let b = cam.frame().basis();
    let p = cam.frame().position();
    let (p, d, k) = (vec3(p, 3), vec3(d, 3), vec3(k, 3));
    let mut basis = Table::new(
        &format!("Camera basis from p = {p},\nd = {d}, k = {k}"),
        &["vector", "formula", "world coordinates"],
    );
    basis.row(vec!["w".into(), "-d/|d|".into(), vec3(b.w(), 4)]);
    basis.row(vec!["u".into(), "(k x w)/|k x w|".into(), vec3(b.u(), 4)]);
    basis.row(vec!["v".into(), "w x u".into(), vec3(b.v(), 4)]);
    let mut rays = Table::new(
        "Rays: made in camera space, then origin B o + p and direction B d",
        &["pixel", "camera origin", "world origin", "world direction"],
    );
    for y in 0..cam.film().height().min(6) {
        for x in 0..cam.film().width().min(6) {
            let local = cam.local_ray(Film::pixel_centre(x, y)).origin();
            let ray = cam.ray(x, y);
            rays.row(vec![
                format!("({x}, {y})"),
                vec3(local, 3),
                vec3(ray.origin(), 3),
                vec3(ray.direction(), 3),
            ]);
        }
    }
    format!("{basis}\n{rays}")
}

/// The figure, seen from above (x to the right, -z up the page): the world axes, the
/// camera with its u and w, the plane edge-on, and the parallel rays of one image row.
pub fn top_figure(cam: &OrthoCamera) -> Result<Diagram> {
    let sketch = CameraRays::top(*cam, 14.0)
        .basis(3.0)
        .eye("p", Place::Below)
        .sizes(1.5, 3.5);
    let mut points = vec![Vec2::ZERO];
    points.extend(sketch.points());
    let (x, y) = extent(&points, 2.0);
    let mut d = Diagram::new(800, 700, x, y)?;
    d.title("Seen from above: the camera basis and the rays of one image row, in world space");
    d.axes(x, y, 2.0, View::Top.axis_names());
    sketch.draw(&mut d);
    Ok(d)
}

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 05: an arbitrary orthographic camera")]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Camera position p, as x,y,z.
    #[arg(long, default_value = "6,0,6", value_parser = parsers::vec3, allow_hyphen_values = true)]
    pub position: Vec3,
    /// View direction d, as x,y,z.
    #[arg(long, default_value = "-1,0,-1", value_parser = parsers::vec3, allow_hyphen_values = true)]
    pub direction: Vec3,
    /// Up vector k, as x,y,z.
    #[arg(long, default_value = "0,1,0", value_parser = parsers::vec3, allow_hyphen_values = true)]
    pub up: Vec3,
    /// Image width in pixels.
    #[arg(long, default_value_t = 4)]
    pub width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 3)]
    pub height: u32,
    #[command(flatten)]
    pub output: Output,
}
