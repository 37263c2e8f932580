//! Every diagram of the book, drawn at the lessons' defaults through the lessons' own
//! figure functions, is legible: no two labels overlap, no label lies on an axis or a
//! tick mark, and the figure is at most 800 px wide, so the book's content column
//! (about 750 px) shows it at full size, or nearly, and its labels stay readable.

use clap::Parser;
use render_lessons::Result;
use render_lessons::course::diagram::Diagram;
use render_lessons::framebuffer::Framebuffer;

#[path = "../book/figures/src/lesson09.rs"]
#[allow(dead_code)]
mod book09;
#[path = "../book/figures/src/lesson10.rs"]
#[allow(dead_code)]
mod book10;
#[path = "../examples/01_transforms.rs"]
#[allow(dead_code)]
mod l01;
#[path = "../examples/02_ray_model.rs"]
#[allow(dead_code)]
mod l02;
#[path = "../examples/03_ortho_camera.rs"]
#[allow(dead_code)]
mod l03;
#[path = "../examples/04_basis_change.rs"]
#[allow(dead_code)]
mod l04;
#[path = "../examples/05_arbitrary_ortho_camera.rs"]
#[allow(dead_code)]
mod l05;
#[path = "../examples/06_pinhole_camera.rs"]
#[allow(dead_code)]
mod l06;
#[path = "../examples/07_intersections.rs"]
#[allow(dead_code)]
mod l07;

/// The widest figure the book's column shows without shrinking it much.
const MAX_WIDTH: u32 = 800;

/// Every lesson diagram, named as its file, drawn as the example's `main` draws it
/// with no flags.
fn lesson_figures() -> Result<Vec<(String, Diagram)>> {
    let mut all = Vec::new();
    let a = l01::Args::parse_from(["01"]);
    all.push(("01_transform_order.png".into(), l01::order_figure(a.angle)?));
    let a = l02::Args::parse_from(["02"]);
    let ray = render_lessons::ray::Ray::new(a.origin, a.direction)?;
    all.push(("02_ray.png".into(), l02::ray_figure(&ray)?));
    let a = l03::Args::parse_from(["03"]);
    let cam = l03::camera(a.width, a.height, (a.x_min, a.x_max), (a.y_min, a.y_max))?;
    all.push(("03_plane.png".into(), l03::plane_figure(cam.film())?));
    all.push(("03_rays.png".into(), l03::rays_figure(&cam)?));
    let a = l04::Args::parse_from(["04"]);
    all.push(("04_two_bases.png".into(), l04::bases_figure(a.angle, a.b)?));
    let a = l05::Args::parse_from(["05"]);
    let cam = l05::camera(a.width, a.height, a.position, a.direction, a.up)?;
    all.push(("05_camera_from_above.png".into(), l05::top_figure(&cam)?));
    let a = l06::Args::parse_from(["06"]);
    let frame = render_lessons::camera::Frame::look(a.position, a.direction, a.up)?;
    let [at_origin, _] = l06::cameras(a.screen_distance, frame)?;
    all.push(("06_pinhole_rays.png".into(), l06::fan_figure(&at_origin)?));
    for case in &l07::cases()? {
        all.push((format!("07_{}.png", case.name), l07::figure(case)?));
    }
    // Lesson 10's ladder at its default size (160 x 120, up to 64 spp), blank: the
    // layout and captions are what is checked, and they do not depend on the pixels.
    let blank = Framebuffer::from_fn(160, 120, |_, _| glam::Vec3::splat(0.3))?;
    let rungs = render_lessons::pathtrace::convergence::ladder(64)?;
    let ladder: Vec<_> = rungs.into_iter().map(|n| (n, blank.clone())).collect();
    let convergence = render_lessons::course::ladder_figure::ladder_figure(&ladder)?;
    all.push(("10_convergence.png".into(), convergence));
    Ok(all)
}

/// The book's own diagrams (book/figures).
fn book_figures() -> Result<Vec<(String, Diagram)>> {
    // The side-by-side strip with blank renders of the lesson's size: its captions are
    // what is checked, and they do not depend on the pixels.
    let blank = Framebuffer::from_fn(480, 270, |_, _| glam::Vec3::splat(0.3))?;
    Ok(vec![
        ("09_pipeline_stages.png".into(), book09::stages()?),
        (
            "09_side_by_side.png".into(),
            book09::captioned(&[&blank, &blank, &blank], &book09::SIDE_BY_SIDE)?,
        ),
        ("10_hemisphere.png".into(), book10::hemisphere_figure()?),
        ("10_path.png".into(), book10::path_figure()?),
    ])
}

fn check(figures: Vec<(String, Diagram)>, max_width: u32) {
    let mut problems = Vec::new();
    for (name, d) in &figures {
        for c in d.label_collisions() {
            problems.push(format!("{name}: {c}"));
        }
        let (w, _) = d.size();
        if w > max_width {
            problems.push(format!("{name}: {w} px wide, more than {max_width}"));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn lesson_figures_are_legible() {
    check(lesson_figures().unwrap(), MAX_WIDTH);
}

#[test]
fn book_figures_are_legible() {
    let figures = book_figures().unwrap();
    let (strips, diagrams): (Vec<_>, Vec<_>) = figures
        .into_iter()
        .partition(|(name, _)| name == "09_side_by_side.png");
    check(diagrams, MAX_WIDTH);
    // The strip keeps the renders' own pixels (three 480 px panels), so the page
    // shrinks it about twice: its captions are drawn twice the labels' size.
    check(strips, 3 * 480 + 2 * 8);
}

#[test]
fn a_tick_value_under_a_label_is_left_out_and_a_collision_is_reported() {
    use glam::Vec2;
    use render_lessons::course::diagram::{Collision, Place, palette};
    let mut d = Diagram::new(400, 300, (-2.0, 2.0), (-2.0, 2.0)).unwrap();
    d.axes((-2.0, 2.0), (-2.0, 2.0), 1.0, ("x", "y"));
    let ticks = d.labels().len();
    // A label right over the tick value "1" of the x axis: the value gives way.
    d.text(Vec2::new(1.0, -0.15), "here", palette::HIT, Place::Below);
    assert_eq!(d.labels().len(), ticks);
    // Only the y axis's "1" is left.
    assert_eq!(d.labels().iter().filter(|l| l.text == "1").count(), 1);
    // Two labels on one point collide, and a label across the y axis lies on it.
    d.text(Vec2::new(-1.0, 1.0), "one", palette::INK, Place::Centre);
    d.text(Vec2::new(-1.0, 1.0), "two", palette::INK, Place::Centre);
    d.text(Vec2::new(0.0, -1.5), "across", palette::INK, Place::Centre);
    let found = d.label_collisions();
    assert!(found.contains(&Collision::Labels("one".into(), "two".into())));
    assert!(found.contains(&Collision::Axis("across".into())));
    // `text_clear` moves a label off what is drawn.
    d.dot(Vec2::new(-1.0, -1.0), 3.0, palette::HIT);
    let place = d.text_clear(
        Vec2::new(-1.0, -1.0),
        "clear",
        palette::INK,
        &[Place::Centre, Place::Left],
    );
    assert_eq!(place, Place::Left);
}
