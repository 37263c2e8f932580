//! The numbers chapters 01 to 09 quote, checked against the snapshots that hold them
//! (issue 15), the early chapters' snapshot tables narrow enough for the page, and two
//! constants the book states (f32's unit roundoff, sRGB's gamma).
//!
//! Standard library, glam and the crate only; the chapters are read as text.

use crate::common::pages::{page as chapter, read, snapshot_body};
use crate::notation::{assert_says, cell, columns, flat, line_starting, summary_pages};

use glam::{Vec3, Vec4};
use render_lessons::mesh::tessellate::{FLOOR_SIZE, tessellate};
use render_lessons::scenes::{STILL_LIFE_OBJECTS, still_life};

// ---- numbers quoted from snapshots -------------------------------------------

#[test]
fn chapter_01_the_sum_of_two_points_divides_to_their_midpoint() {
    let (p, q) = (Vec4::new(1.0, 2.0, 3.0, 1.0), Vec4::new(3.0, 4.0, 5.0, 1.0));
    let sum = p + q;
    assert_eq!(sum, Vec4::new(4.0, 6.0, 8.0, 2.0));
    assert_eq!(sum.truncate() / sum.w, Vec3::new(2.0, 3.0, 4.0));
    assert_eq!(sum.truncate() / sum.w, (p.truncate() + q.truncate()) / 2.0);
    // (2, 4, 6, 2) and (1, 2, 3, 1) are one point.
    let twice = Vec4::new(2.0, 4.0, 6.0, 2.0);
    assert_eq!(twice.truncate() / twice.w, Vec3::new(1.0, 2.0, 3.0));
    assert_says(
        "01_transforms.md",
        "$(1, 2, 3, 1) + (3, 4, 5, 1) = (4, 6, 8, 2)$, and dividing by $w = 2$ gives $(2, 3, 4)$, \
         the *midpoint* of the two",
    );
}

#[test]
fn chapter_01_says_what_its_table_header_said() {
    let table = snapshot_body("lessons::lesson_01_transforms", "numbers");
    assert!(table.starts_with(
        "The slides' matrices, angle 30 degrees, applied to\nthe point (1.000, 2.000, 3.000) \
         (w = 1) and the vector (1.000, 2.000, 3.000) (w = 0)\n"
    ));
    assert_says(
        "01_transforms.md",
        "The example applies the slides' matrices, at the angle $30°$, to the point $(1, 2, 3)$ \
         ($w = 1$) and to the vector $(1, 2, 3)$ ($w = 0$)",
    );
    // The worked numbers of steps 3 and 5.
    assert_eq!(
        cell(&table, "rotation_z(angle)", 1),
        "(-0.134, 2.232, 3.000)"
    );
    assert_eq!(
        cell(&table, "rotate, then translate", 1),
        "(2.866, 2.232, 3.000)"
    );
    assert_eq!(
        cell(&table, "translate, then rotate", 1),
        "(2.464, 3.732, 3.000)"
    );
    assert_says("01_transforms.md", "= (-0.134, 2.232, 3)$");
    assert_says("01_transforms.md", "$(2.866, 2.232, 3)$");
    assert_says("01_transforms.md", "= (2.464, 3.732, 3)$");
}

#[test]
fn chapters_03_to_06_say_what_their_table_headers_said() {
    let ortho = snapshot_body("lessons::lesson_03_ortho_camera", "numbers");
    assert!(ortho.starts_with(
        "Orthographic camera: plane [-8.00, 8.00] x [-6.00, 6.00], 4 x 3 pixels, row 0 on top\n"
    ));
    assert_says(
        "03_ortho_camera.md",
        "For the plane $[-8, 8]\\times[-6, 6]$ cut into $4\\times 3$ pixels, row 0 at the top",
    );

    let placed = snapshot_body("lessons::lesson_05_arbitrary_ortho_camera", "numbers");
    assert!(placed.starts_with(
        "Camera basis from p = (6.000, 0.000, 6.000),\nd = (-1.000, 0.000, -1.000), \
         k = (0.000, 1.000, 0.000)\n"
    ));
    assert_says(
        "05_arbitrary_ortho_camera.md",
        "The example's camera stands at $\\mathbf{p} = (6, 0, 6)$ and looks along \
         $\\mathbf{d} = (-1, 0, -1)$, towards the origin, with $\\mathbf{k} = (0, 1, 0)$",
    );
    // The top view's caption: the vertical axis is -z, so p (z = +6) sits at tick -6.
    assert_says(
        "05_arbitrary_ortho_camera.md",
        "its vertical axis is $-z$ (up the page is the way lesson 03's camera looks), so a tick \
         marked $-6$ means $z = +6$: the camera position $\\mathbf{p} = (6, 0, 6)$ sits at $x = 6$, \
         tick $-6$",
    );
    assert_eq!(cell(&placed, "(0, 0)", 2), "(1.757, 4.000, 10.243)");
    assert_says("05_arbitrary_ortho_camera.md", "= (1.757, 4, 10.243)");

    let pinhole = snapshot_body("lessons::lesson_06_pinhole_camera", "numbers");
    assert_eq!(
        line_starting(&pinhole, "Placed:"),
        "Placed: p=(0.000, 3.000, 6.000), d=(0.000, -1.000, -2.000), k=(0.000, 1.000, 0.000)"
    );
    assert_says(
        "06_1_placed_pinhole.md",
        "The placed camera stands at $\\mathbf{p} = (0, 3, 6)$ and looks along \
         $\\mathbf{d} = (0, -1, -2)$ with $\\mathbf{k} = (0, 1, 0)$",
    );
    let placed_rows = pinhole.split("Placed:").nth(1).unwrap();
    assert_eq!(cell(placed_rows, "(2, 1)", 2), "(0.2425, -0.4339, -0.8677)");
    assert_says(
        "06_1_placed_pinhole.md",
        "\\approx (0.2425, -0.4339, -0.8677)$",
    );
}

#[test]
fn chapter_08_quotes_its_coverage_table() {
    let table = snapshot_body("lessons::lesson_08_ray_casting", "numbers");
    assert!(table.starts_with("Shadowless ray casting, 480 x 270 pixels"));
    let count =
        |name: &str, column: usize| cell(&table, name, column).parse::<u32>().unwrap();
    for column in [1, 2] {
        let rows = STILL_LIFE_OBJECTS.iter().chain(&["background"]);
        let total: u32 = rows.map(|n| count(n, column)).sum();
        assert_eq!(total, 480 * 270, "each column adds up to the image");
    }
    assert_says("08_ray_casting.md", "$480\\times 270 = 129\\,600$ pixels");
    let quoted = format!(
        "grows from {} pixels in the orthographic image to {} with the pinhole; the box and the \
         triangle, behind the target, shrink from {} to {} and from {} to {}",
        count("green sphere", 1),
        count("green sphere", 2),
        count("box", 1),
        count("box", 2),
        count("triangle", 1),
        count("triangle", 2),
    );
    assert_says("08_ray_casting.md", &quoted);
    assert_eq!(count("background", 1), 0);
    assert_says(
        "08_ray_casting.md",
        &format!("{} pixels show the sky", count("background", 2)),
    );
}

#[test]
fn chapter_08_quotes_its_pixel_and_acne_tables() {
    let pixels = snapshot_body("lessons::lesson_08_ray_casting", "lambert_pixels");
    let colour = |name: &str| -> Vec3 {
        let c = cell(&pixels, name, 2);
        let v: Vec<f32> = c
            .trim_matches(['(', ')'])
            .split(", ")
            .map(|x| x.parse().unwrap())
            .collect();
        Vec3::new(v[0], v[1], v[2])
    };
    // The red sphere: its albedo (0.85, 0.2, 0.15) times one factor, 0.8645.
    let factor = colour("red sphere, lit side") / Vec3::new(0.85, 0.2, 0.15);
    assert!(
        (factor - Vec3::splat(0.8645)).abs().max_element() < 2e-3,
        "{factor}"
    );
    assert_says("08_1_light_and_shadows.md", "the same factor $0.8645$");
    assert_says("08_1_light_and_shadows.md", "$I\\cos\\theta/d^2 = 0.7645$");
    // The shadow: exactly k_a times the floor's albedo.
    assert_eq!(
        colour("floor in the red sphere's shadow"),
        0.1 * Vec3::new(0.75, 0.75, 0.7)
    );
    // The lit floor: above 1, as the page says, and the value it quotes.
    let lit = colour("floor, lit");
    assert!(lit.x > 1.0);
    assert_eq!(format!("{:.3}", lit.x), "1.206");
    assert_says("08_1_light_and_shadows.md", "reaches $1.206$, more than 1");

    let acne = snapshot_body("lessons::lesson_08_ray_casting", "acne");
    let fixed = columns(line_starting(&acne, "t > 1e-4 (fixed)"));
    let scaled = columns(line_starting(&acne, "scaled offset"));
    assert_eq!(&fixed[1..], ["2797", "2.16%"]);
    assert_eq!(&scaled[1..], ["8", "0.01%"]);
    assert!(acne.starts_with("Shadow rays, scene moved by (10000, 0, 0)"));
    assert_says(
        "08_1_light_and_shadows.md",
        "The fixed epsilon changes **2797** of the 129 600 pixels (2.16 %), the scaled offset **8** \
         (0.01 %)",
    );
    assert_says(
        "08_1_light_and_shadows.md",
        "with the whole scene, light and camera moved by $(10\\,000, 0, 0)$",
    );
}

#[test]
fn chapter_09_quotes_its_comparison_table() {
    let table = snapshot_body("lessons::lesson_09_rasterization", "numbers");
    let number =
        |name: &str, column: usize| cell(&table, name, column).parse::<u32>().unwrap();
    // The counts of step "the numbers" and of the speed paragraph.
    assert_eq!(
        (number("red sphere", 1), number("red sphere", 2)),
        (1986, 3968)
    );
    assert_eq!(2 + 31 * 64, 1986);
    assert_eq!(2 * 64 + 2 * 30 * 64, 3968);
    assert_says(
        "09_6_against_ray_casting.md",
        "$2 + 31\\cdot 64 = 1986$ vertices",
    );
    let all = cell(&table, "all", 1).parse::<u32>().unwrap();
    assert_says(
        "09_6_against_ray_casting.md",
        &format!("the {} {} triangles", all / 1000, all % 1000),
    );
    let (floor_v, floor_t) = (number("floor", 1), number("floor", 2));
    let (mesh_v, mesh_t) = (
        number("mesh (torus.obj, smooth)", 1),
        number("mesh (torus.obj, smooth)", 2),
    );
    assert_says(
        "09_6_against_ray_casting.md",
        &format!(
            "the torus scene's {} primitives would cost $129\\,600$ rays times {}",
            mesh_t + 1,
            mesh_t + 1
        ),
    );
    assert_says(
        "09_6_against_ray_casting.md",
        &format!(
            "the rasterizer transforms {} vertices once and fills the pixels that {} triangles cover",
            floor_v + mesh_v,
            floor_t + mesh_t
        ),
    );
    assert!((129_600.0 * (mesh_t + 1) as f64 / 1.3e8 - 1.0).abs() < 0.05);
    assert_eq!(
        (mesh_t + 1, floor_v + mesh_v, floor_t + mesh_t),
        (1025, 516, 1026)
    );

    // The agreements quoted in the text and the README.
    let agree = |name: &str| cell(&table, name, 4).to_string();
    assert_eq!(agree("per-pixel shading"), "99.89%");
    assert_eq!(cell(&table, "per-pixel shading", 5), "0.009");
    assert_says(
        "09_6_against_ray_casting.md",
        "99.89 % of the pixels agree to within $1/255$, and the largest difference is $0.009$",
    );
    // The mesh shaded smooth by both renderers.
    assert_eq!(cell(&table, "floor + mesh", 3), "1");
    assert_eq!(cell(&table, "floor + mesh", 5), "0.302");
    assert_says(
        "09_6_against_ray_casting.md",
        "One compared pixel differs, by $0.302$",
    );
    assert_eq!(agree("per-vertex (Gouraud)"), "31.63%");
    assert_says(
        "09_6_against_ray_casting.md",
        "only 31.63 % of the pixels agree",
    );
    assert_eq!(agree("shadow map"), "99.83%");
    assert_says(
        "09_5_shadow_map.md",
        "With the bias of one texel footprint, 99.83 % of the compared pixels agree",
    );
    assert!(
        flat(&read("README.md"))
            .contains("(99.9 % of pixels agree away from silhouettes)")
    );
    assert!(line_starting(&table, "Against the ray caster").starts_with(
        "Against the ray caster, 480 x 270 pixels, away from silhouettes"
    ));
    assert_says(
        "09_6_against_ray_casting.md",
        "at $480\\times 270$ pixels, away from silhouettes; a pixel counts as different when one \
         of its channels is more than $1/255$ apart.",
    );
}

#[test]
fn chapter_09_sagitta_of_the_tessellated_sphere() {
    let sagitta = |segments: f64| 1.0 - (std::f64::consts::PI / segments).cos();
    assert_eq!(format!("{:.4}", sagitta(24.0)), "0.0086");
    assert_eq!(format!("{:.4}", sagitta(64.0)), "0.0012");
    assert_says(
        "09_6_against_ray_casting.md",
        "$0.0086\\,r$ with 24 segments, $0.0012\\,r$ with the lesson's 64",
    );
}

#[test]
fn chapter_09_gouraud_floor_corners_are_about_7070_from_the_light() {
    let scene = still_life(Vec3::ZERO).unwrap();
    let light = scene.point_light().unwrap().position;
    let floor = &tessellate(&scene, 64).unwrap()[0];
    assert_eq!(floor.mesh.positions.len(), 4);
    for corner in &floor.mesh.positions {
        let world = floor.model.point(*corner);
        let d = world.distance(light);
        assert!(
            (7060.0..7080.0).contains(&d),
            "corner {world} is {d} from the light"
        );
    }
    let half_diagonal = FLOOR_SIZE / 2.0 * 2f32.sqrt();
    assert_eq!(half_diagonal.round(), 7071.0);
    assert_says(
        "09_6_against_ray_casting.md",
        "about $7070$ units away from the light (the corners of a square of side $10^4$ lie \
         $5000\\sqrt{2} \\approx 7071$ from its centre)",
    );
    assert_eq!(FLOOR_SIZE, 1e4);
}

// ---- tables that fit the page --------------------------------------------------

/// The widest line a code block shows without a scroll bar in the book's 750 px
/// content column (about 8.6 px per character of the code font).
const PAGE_CHARS: usize = 86;

/// Lines still too wide, and why they stay (none now: the examples print their long
/// titles on two lines). The list must stay empty or shrink: an entry that is no
/// longer too wide fails the test.
const TOO_WIDE_TITLES: [(&str, usize); 0] = [];

/// Snapshots whose rows are all too wide: none now (lesson 09's projection table
/// prints each point on two lines).
const TOO_WIDE_ROWS: [&str; 0] = [];

#[test]
fn snapshot_tables_in_the_early_chapters_fit_the_page() {
    let mut wide = Vec::new();
    for page in summary_pages() {
        let early = page == "intro.md"
            || page == "glossary.md"
            || ["01", "02", "03", "04", "05", "06", "08", "09"]
                .iter()
                .any(|n| page.starts_with(n));
        if !early {
            continue;
        }
        for line in chapter(&page).lines() {
            let Some(spec) = line
                .trim()
                .strip_prefix("{{#include ../")
                .and_then(|s| s.strip_suffix("}}"))
                .filter(|s| s.starts_with("tests/") && s.contains(".snap"))
            else {
                continue;
            };
            let mut parts = spec.split(':');
            let file = parts.next().unwrap();
            if TOO_WIDE_ROWS.contains(&file) {
                continue;
            }
            let text = read(file);
            let lines: Vec<&str> = text.lines().collect();
            let start = parts.next().map_or(1, |s| s.parse::<usize>().unwrap());
            let end = parts
                .next()
                .filter(|s| !s.is_empty())
                .map_or(lines.len(), |s| s.parse::<usize>().unwrap());
            for (i, l) in lines[start - 1..end].iter().enumerate() {
                if l.chars().count() > PAGE_CHARS {
                    wide.push((
                        page.clone(),
                        file.to_string(),
                        start + i,
                        l.chars().count(),
                    ));
                }
            }
        }
    }
    let unexpected: Vec<String> = wide
        .iter()
        .filter(|(_, file, line, _)| !TOO_WIDE_TITLES.contains(&(file.as_str(), *line)))
        .map(|(page, file, line, n)| {
            format!("{page}: {file} line {line} has {n} characters")
        })
        .collect();
    assert!(
        unexpected.is_empty(),
        "too wide for the page:\n{}",
        unexpected.join("\n")
    );
    for (file, line) in TOO_WIDE_TITLES {
        assert!(
            wide.iter().any(|(_, f, l, _)| f == file && *l == line),
            "{file} line {line} fits the page now (or is no longer included): take it off \
             TOO_WIDE_TITLES"
        );
    }
}

/// The unit roundoff of `f32` as the notation table, the glossary and "Where methods
/// fail" state it: epsilon = 2^-24, about 6e-8, the largest relative error of one
/// correctly rounded operation. 1 + epsilon is a tie and rounds to 1 (to even);
/// anything above it rounds up to 1 + 2 epsilon, the next float.
#[test]
fn the_unit_roundoff_of_f32_is_2_to_the_minus_24() {
    let epsilon = f32::EPSILON / 2.0;
    assert_eq!(epsilon, 2f32.powi(-24));
    assert_eq!(format!("{epsilon:.0e}"), "6e-8");
    let one = std::hint::black_box(1.0f32);
    assert_eq!(one + epsilon, 1.0);
    assert_eq!(one + epsilon * 1.5, 1.0 + 2.0 * epsilon);
}

/// The glossary's sRGB: "a curve close to the power 1/2.2" that "spends more of the
/// 256 codes on dark values". The crate's exact curve (`to_srgb8`) is within 8 codes
/// of the plain power 1/2.2 everywhere, and gives the darker half of the linear
/// range, [0, 0.5], far more than half the codes.
#[test]
fn srgb_is_close_to_the_power_one_over_2_2() {
    use render_lessons::framebuffer::to_srgb8;
    let mut worst = 0i32;
    for i in 0..=1000 {
        let linear = i as f32 / 1000.0;
        let power = (linear.powf(1.0 / 2.2) * 255.0).round() as i32;
        worst = worst.max((i32::from(to_srgb8(linear)) - power).abs());
    }
    assert!(worst <= 8, "{worst} codes apart");
    assert!(
        to_srgb8(0.5) > 180,
        "{} of 256 codes below half",
        to_srgb8(0.5)
    );
}
