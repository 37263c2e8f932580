//! Lesson 09, the Newell teapot (chapter 09_7): its data are Newell's, its patches
//! join without cracks, the committed `teapot.obj` is what `teapot_obj` writes, its
//! load statistics, and the lesson drawing it.

use crate::examples::rasterization as lesson;

use render_lessons::ray::Interval;
use std::collections::HashSet;
use std::fmt::Write;
use std::path::Path;

use glam::Vec3;
use render_lessons::camera::Camera;
use render_lessons::course::report::num;
use render_lessons::mesh::teapot::{TEAPOT_PATCHES, TEAPOT_POINTS};
use render_lessons::mesh::{Mesh, patch_point, teapot_obj};
use render_lessons::scene::BvhScene;
use render_lessons::scene::Intersect;
use render_lessons::scenes::{TEAPOT_OBJ, asset_path, still_life};
use render_lessons::scenes::{Up, floor_and_mesh};
use render_lessons::scenes::{
    mesh_on_the_floor, still_life_pinhole, still_life_shadows,
};

/// The teapot's grid of the committed file.
const GRID: u32 = 8;

#[test]
fn the_committed_teapot_is_what_teapot_obj_writes() {
    let path = asset_path(Path::new(TEAPOT_OBJ));
    let written = teapot_obj(GRID).unwrap();
    if std::env::var_os("UPDATE_ASSETS").is_some() {
        std::fs::write(&path, &written).unwrap();
    }
    let committed = std::fs::read_to_string(&path).unwrap();
    assert!(
        committed == written,
        "{} is not teapot_obj({GRID}); write it again with \
         UPDATE_ASSETS=1 cargo test --test lessons the_committed_teapot",
        path.display()
    );
    // Small enough to keep in the repository.
    assert!(committed.len() < 200_000, "{}", committed.len());
    assert!(teapot_obj(0).is_err() && teapot_obj(1025).is_err());
}

#[test]
fn the_teapot_data_is_newells() {
    // 306 control points, 32 patches of 16; every point is used but the four
    // near the lid's knob (numbers 205, 206, 216, 223), which no patch names.
    let used: HashSet<u16> = TEAPOT_PATCHES.iter().flatten().copied().collect();
    let unused: Vec<u16> = (1..=306).filter(|n| !used.contains(n)).collect();
    assert_eq!(unused, [205, 206, 216, 223]);
    // The teapot is symmetric about its y = 0 plane, and its body, rim, lid and
    // bottom (all but the handle and spout, patches 13 to 20) about x = 0 too: a
    // mistyped coordinate would break a mirror image.
    let key = |p: [f64; 3]| p.map(|c| (c * 1e6).round() as i64);
    let points: HashSet<[i64; 3]> = TEAPOT_POINTS.iter().map(|&p| key(p)).collect();
    for p in TEAPOT_POINTS {
        assert!(points.contains(&key([p[0], -p[1], p[2]])), "{p:?}");
    }
    for (k, patch) in TEAPOT_PATCHES.iter().enumerate() {
        if (12..20).contains(&k) {
            continue;
        }
        for &n in patch {
            let p = TEAPOT_POINTS[usize::from(n) - 1];
            assert!(points.contains(&key([-p[0], p[1], p[2]])), "{p:?}");
        }
    }
    // The surface's bounding box, sampled finely, is the published one: x from -3
    // (the handle) to 3.434 (the spout's lip), y from -2 to 2, z from 0 to 3.15
    // (the knob), with z up.
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for patch in 0..32 {
        for i in 0..=64 {
            for j in 0..=64 {
                let p = patch_point(patch, i, j, 64).to_array();
                for k in 0..3 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
        }
    }
    let round = |x: [f64; 3]| x.map(|c| format!("{c:.3}"));
    assert_eq!(round(lo), ["-3.000", "-2.000", "0.000"]);
    assert_eq!(round(hi), ["3.434", "2.000", "3.150"]);
}

#[test]
fn the_teapot_patches_join_without_cracks() {
    // An edge of a patch is one of its four boundary rows of control points. Where
    // two patches share one (the same four points, either way round), both must
    // give the same tessellation points along it, bit for bit.
    let edges = |patch: usize| -> [[u16; 4]; 4] {
        let c = TEAPOT_PATCHES[patch];
        let at = |r: usize, s: usize| c[4 * r + s];
        [
            [at(0, 0), at(0, 1), at(0, 2), at(0, 3)],
            [at(3, 0), at(3, 1), at(3, 2), at(3, 3)],
            [at(0, 0), at(1, 0), at(2, 0), at(3, 0)],
            [at(0, 3), at(1, 3), at(2, 3), at(3, 3)],
        ]
    };
    // The grid points along edge e (0: i = 0, 1: i = n, 2: j = 0, 3: j = n).
    let along = |patch: usize, e: usize, n: u32| -> Vec<[u64; 3]> {
        (0..=n)
            .map(|k| match e {
                0 => (0, k),
                1 => (n, k),
                2 => (k, 0),
                _ => (k, n),
            })
            .map(|(i, j)| {
                patch_point(patch, i, j, n)
                    .to_array()
                    .map(|c| (c + 0.0).to_bits())
            })
            .collect()
    };
    let mut shared = 0;
    for a in 0..32 {
        for b in a + 1..32 {
            for (ea, edge_a) in edges(a).iter().enumerate() {
                for (eb, edge_b) in edges(b).iter().enumerate() {
                    let mut reversed = *edge_b;
                    reversed.reverse();
                    if edge_a != edge_b && *edge_a != reversed {
                        continue;
                    }
                    shared += 1;
                    let (pa, mut pb) = (along(a, ea, 7), along(b, eb, 7));
                    if *edge_a != *edge_b {
                        pb.reverse();
                    }
                    assert_eq!(pa, pb, "patches {a} and {b}");
                }
            }
        }
    }
    assert!(shared >= 40, "{shared}");
    // Welded, the quads leave open only the teapot's real openings: the rim's inner
    // edge and the lid's outer edge (4 patches each), the handle's and the spout's
    // two ends (2 patches each): 16 x 8 edges at 8 quads a side.
    let mesh = Mesh::from_obj(asset_path(Path::new(TEAPOT_OBJ)))
        .unwrap()
        .mesh;
    let directed: HashSet<(u32, u32)> = mesh
        .triangles
        .iter()
        .flat_map(|&[a, b, c]| [(a, b), (b, c), (c, a)])
        .collect();
    let open = directed
        .iter()
        .filter(|&&(a, b)| !directed.contains(&(b, a)));
    assert_eq!(open.count(), 16 * GRID as usize);
    // No edge is walked twice the same way: the patches all turn the same way.
    assert_eq!(directed.len(), 3 * mesh.triangles.len());
}

#[test]
fn teapot_load_statistics() {
    let loaded = Mesh::from_obj(asset_path(Path::new(TEAPOT_OBJ))).unwrap();
    let mesh = &loaded.mesh;
    let (lo, hi) = mesh
        .positions
        .iter()
        .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &p| {
            (lo.min(p), hi.max(p))
        });
    let corner = |v: Vec3| {
        let c = v.to_array().map(|c| num(f64::from(c), 3));
        format!("({}, {}, {})", c[0], c[1], c[2])
    };
    // Outward: the signed volume sum a . (b x c) / 6 is positive.
    let volume: f64 = mesh
        .triangles
        .iter()
        .map(|t| t.map(|i| mesh.positions[i as usize].as_dvec3()))
        .map(|[a, b, c]| a.dot(b.cross(c)) / 6.0)
        .sum();
    let c = loaded.counts;
    let mut text = String::new();
    let _ = writeln!(text, "teapot.obj, {GRID} x {GRID} quads a patch, y up");
    let _ = writeln!(text, "vertices               {}", mesh.positions.len());
    let _ = writeln!(text, "faces                  {}", c.faces);
    let _ = writeln!(text, "faces triangulated     {}", c.faces_triangulated);
    let _ = writeln!(text, "triangles              {}", mesh.triangles.len());
    let _ = writeln!(text, "skipped (degenerate)   {}", c.skipped_degenerate);
    let _ = writeln!(
        text,
        "bounding box (3 dp)    {} .. {}",
        corner(lo),
        corner(hi)
    );
    let _ = writeln!(text, "signed volume (2 dp)   {}", num(volume, 2));
    insta::assert_snapshot!("teapot_load_statistics", text);
    // Two triangles a quad; one per quad at the knob and at the bottom's middle
    // (4 patches each, GRID quads round each pole) has no area.
    assert_eq!(c.faces, 32 * (GRID * GRID) as usize);
    assert_eq!(c.skipped_degenerate, 8 * GRID as usize);
    assert_eq!(mesh.triangles.len(), 2 * c.faces - c.skipped_degenerate);
}

/// Lesson 09 at a small size with `mesh` (the book's scene, spheres of 16
/// segments, a 256^2 shadow map).
fn small_lesson(mesh: &Path, subdivisions: u32) -> (String, lesson::Lesson) {
    let scene = still_life(Vec3::ZERO).unwrap();
    let camera = still_life_pinhole(160, 90).unwrap();
    let mesh = mesh_on_the_floor(mesh, Up::Y, subdivisions, &camera).unwrap();
    let shadows = still_life_shadows(256, 1.0);
    let lesson = lesson::images(&scene, &camera, 16, shadows, &mesh.model).unwrap();
    let file = "teapot.obj";
    (
        lesson::numbers(&scene, 16, (&mesh, file), &lesson).unwrap(),
        lesson,
    )
}

/// How many pixels of `camera`'s view see a mesh triangle (not the floor, not
/// the sky) in lesson 09's floor-and-mesh scene.
fn mesh_pixels(mesh: &Path, camera: &Camera) -> usize {
    let scene = still_life(Vec3::ZERO).unwrap();
    let model = mesh_on_the_floor(mesh, Up::Y, 0, camera).unwrap().model;
    // Through the tree: it answers as the list does (tests/course/bvh.rs), 4033
    // objects for each of the 14 400 rays made this the slowest part of the test.
    let floor_and_mesh = BvhScene::new(floor_and_mesh(&scene, &model).unwrap());
    let (w, h) = (camera.film().width(), camera.film().height());
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let hit = floor_and_mesh.closest(&camera.ray(x, y), Interval::AHEAD);
            hit.is_some_and(|found| found.object > 0)
        })
        .count()
}

#[test]
fn the_teapot_in_lesson_09() {
    let teapot = asset_path(Path::new(TEAPOT_OBJ));
    let (numbers, lesson) = small_lesson(&teapot, 0);
    let camera = still_life_pinhole(160, 90).unwrap();
    let covered = mesh_pixels(&teapot, &camera);
    let text = format!("{numbers}\nteapot pixels (ray cast, 160 x 90): {covered}\n");
    insta::assert_snapshot!("teapot_in_lesson_09", text);
    // The same triangles both ways: every compared pixel identical.
    let mesh = lesson
        .agreements
        .iter()
        .find(|(l, _, _)| *l == "floor + mesh");
    let agreement = mesh.unwrap().2;
    assert_eq!(agreement.differing, 0, "{agreement:?}");
    // The teapot is in view and far from filling it.
    assert!((500..5000).contains(&covered), "{covered}");
}
