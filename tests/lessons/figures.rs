//! Every diagram of the book, drawn at the lessons' defaults through the lessons' own
//! figure functions, is legible: no two labels overlap, no label lies on an axis or a
//! tick mark, and the figure is at most 800 px wide, so the book's content column
//! (about 750 px) shows it at full size, or nearly, and its labels stay readable.

use clap::Parser;
use render_lessons::Result;
use render_lessons::course::diagram::{Diagram, cross_section};
use render_lessons::framebuffer::Framebuffer;

use crate::examples::arbitrary_ortho_camera as l05;
use crate::examples::basis_change as l04;
use crate::examples::book_figures_09 as book09;
use crate::examples::book_figures_10 as book10;
use crate::examples::intersections as l07;
use crate::examples::ortho_camera as l03;
use crate::examples::pinhole_camera as l06;
use crate::examples::ray_model as l02;
use crate::examples::transforms as l01;

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
        let figure = cross_section(case.name, &case.shape, &case.ray)?;
        all.push((format!("07_{}.png", case.name), figure));
    }
    // Lesson 10's ladder at its default size (160 x 120, up to 64 spp), blank: the
    // layout and captions are what is checked, and they do not depend on the pixels.
    let blank = Framebuffer::from_fn(160, 120, |_, _| glam::Vec3::splat(0.3))?;
    let rungs = render_lessons::course::convergence::ladder(64)?;
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

/// Figures wider than [`MAX_WIDTH`], with the width they may have and why: strips of
/// renders side by side at the lessons' own 480 px per panel, which the page shows
/// scaled down. Renders carry no text; a strip's captions are drawn large enough for
/// the scale (the browser test, tests/browser/check.mjs, checks every figure's
/// smallest text as the page shows it).
const STRIPS: [(&str, u32, &str); 6] = [
    (
        "09_side_by_side.png",
        3 * 480 + 2 * 8,
        "three renders, captions at twice the labels' size",
    ),
    ("09_shadows.png", 2 * 480 + 8, "two renders, no text"),
    ("09_shadow_bias.png", 2 * 480 + 8, "two renders, no text"),
    ("09_mesh.png", 2 * 480 + 8, "two renders, no text"),
    ("09_teapot.png", 2 * 480 + 8, "two renders, no text"),
    ("09_texture.png", 2 * 480 + 8, "two renders, no text"),
];

/// The width of a PNG (from its IHDR chunk) or an SVG (its root element's `width`),
/// in pixels.
fn image_width(path: &std::path::Path) -> Option<u32> {
    let bytes = std::fs::read(path).ok()?;
    match path.extension()?.to_str()? {
        "png" => {
            let ihdr = bytes.get(12..24)?;
            (&ihdr[..4] == b"IHDR")
                .then(|| u32::from_be_bytes([ihdr[4], ihdr[5], ihdr[6], ihdr[7]]))
        }
        "svg" => {
            let text = String::from_utf8(bytes).ok()?;
            let root = &text[text.find("<svg")?..];
            let root = &root[..root.find('>')?];
            let width = root.split_once(" width=\"")?.1;
            width[..width.find('"')?]
                .trim_end_matches("px")
                .parse::<f64>()
                .ok()
                .map(|w| w.ceil() as u32)
        }
        _ => None,
    }
}

#[test]
fn every_png_and_svg_of_the_book_fits_the_page() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("chapters/figures");
    let mut problems = Vec::new();
    let mut checked = 0;
    let mut entries: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let image = path.extension().is_some_and(|e| e == "png" || e == "svg");
        if !image {
            continue;
        }
        let Some(width) = image_width(&path) else {
            problems.push(format!("{name}: cannot read its width"));
            continue;
        };
        checked += 1;
        let allowed = STRIPS
            .iter()
            .find(|s| s.0 == name)
            .map_or(MAX_WIDTH, |s| s.1);
        if width > allowed {
            problems.push(format!("{name}: {width} px wide, more than {allowed}"));
        }
    }
    assert!(
        checked > 40,
        "only {checked} figures found in {}",
        dir.display()
    );
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_width_check_reads_png_and_svg() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("a.png");
    Framebuffer::from_fn(801, 3, |_, _| glam::Vec3::ZERO)
        .unwrap()
        .save_png(&png)
        .unwrap();
    assert_eq!(image_width(&png), Some(801));
    let svg = dir.path().join("b.svg");
    std::fs::write(&svg, "<?xml version=\"1.0\"?>\n<svg width=\"800\" height=\"500\" viewBox=\"0 0 800 500\">\n<rect width=\"10\"/></svg>").unwrap();
    assert_eq!(image_width(&svg), Some(800));
    let chart = render_lessons::course::chart::Chart::new(
        "t",
        ("x (1)", render_lessons::course::chart::Scale::Linear),
        ("y (1)", render_lessons::course::chart::Scale::Linear),
    )
    .with("s", vec![(0.0, 0.0), (1.0, 1.0)]);
    std::fs::write(&svg, chart.svg().unwrap()).unwrap();
    assert_eq!(
        image_width(&svg),
        Some(render_lessons::course::chart::WIDTH)
    );
}

/// The browser test needs the size of each figure's smallest text; it keeps them as
/// constants, which must match the code that draws the figures.
#[test]
fn the_browser_test_knows_the_figures_text_sizes() {
    let check = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/browser/check.mjs"),
    )
    .unwrap();
    let constant = |name: &str| -> f64 {
        let line = check
            .lines()
            .find(|l| l.starts_with(&format!("const {name} = ")))
            .unwrap_or_else(|| panic!("check.mjs has no `const {name} = `"));
        line.split('=')
            .nth(1)
            .unwrap()
            .trim()
            .trim_end_matches(';')
            .parse()
            .unwrap()
    };
    // Tick values are the smallest text of a diagram: 0.8 of a label.
    let tick = f64::from(render_lessons::course::diagram::LABEL_SIZE) * 0.8;
    assert_eq!(constant("DIAGRAM_TEXT_PX"), tick);
    assert_eq!(constant("MIN_TEXT_PX"), 9.0);
}
