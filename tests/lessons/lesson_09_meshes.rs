//! Lesson 09, real meshes: OBJ faces of any size split into triangles, degenerate
//! triangles skipped and counted, errors that name the file; the Newell teapot
//! (its data, its tessellation, the committed file, the lesson drawing it); a
//! million triangles.

use crate::examples::rasterization as lesson;

use crate::examples::speed_vs_accuracy as lesson11;

use render_lessons::ray::Interval;
use std::collections::{HashMap, HashSet};
use std::fmt::Write;
use std::path::{Path, PathBuf};

use glam::Vec3;
use render_lessons::bvh::ListOrTree;
use render_lessons::camera::Camera;
use render_lessons::course::compare::reference;
use render_lessons::course::report::num;
use render_lessons::error::{Error, Shortfall};
use render_lessons::mesh::teapot::{TEAPOT_PATCHES, TEAPOT_POINTS};
use render_lessons::mesh::{FaceCounts, Mesh, fan, patch_point, teapot_obj};
use render_lessons::scenes::floor_and_mesh;
use render_lessons::scenes::{TEAPOT_OBJ, TORUS_OBJ, asset_path, still_life};
use render_lessons::scenes::{mesh_on_the_floor, still_life_pinhole, still_life_shadows};

/// A scratch folder, and a function that writes `text` to a file of it.
fn scratch() -> (tempfile::TempDir, impl Fn(&str, &str) -> PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path().to_path_buf();
    (dir, move |name: &str, text: &str| {
        let path = root.join(name);
        std::fs::write(&path, text).unwrap();
        path
    })
}

const SQUARE_AND_PENTAGON: &str = "\
# a unit square (a quad) and a regular-ish convex pentagon beside it
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 3 0 0
v 4 0 0
v 4.3 1 0
v 3.5 1.6 0
v 2.7 1 0
f 1 2 3 4
f 5 6 7 8 9
";

#[test]
fn a_quad_becomes_two_triangles_and_a_pentagon_three() {
    assert_eq!(
        fan(&[0, 1, 2, 3]).collect::<Vec<_>>(),
        [[0, 1, 2], [0, 2, 3]]
    );
    let pentagon: Vec<_> = fan(&[4, 5, 6, 7, 8]).collect();
    assert_eq!(pentagon, [[4, 5, 6], [4, 6, 7], [4, 7, 8]]);
    assert_eq!(fan(&[7, 8, 9]).collect::<Vec<_>>(), [[7, 8, 9]]);
    assert_eq!(fan(&[7, 8]).count(), 0);

    let (_dir, write) = scratch();
    let loaded = Mesh::from_obj(&write("faces.obj", SQUARE_AND_PENTAGON)).unwrap();
    let counts = FaceCounts {
        faces: 2,
        faces_triangulated: 2,
        skipped_degenerate: 0,
    };
    assert_eq!(loaded.counts, counts);
    assert_eq!(loaded.counts.to_string(), "2 faces triangulated");
    let mesh = &loaded.mesh;
    assert_eq!(mesh.triangles.len(), 2 + 3);
    // The fans cover the faces exactly: areas 1 and the pentagon's (shoelace formula).
    let area = |t: &[u32; 3]| {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        (b - a).cross(c - a).z / 2.0
    };
    let square: f32 = mesh.triangles[..2].iter().map(area).sum();
    let five: f32 = mesh.triangles[2..].iter().map(area).sum();
    assert!((square - 1.0).abs() < 1e-6, "{square}");
    let corners = [(3.0, 0.0), (4.0, 0.0), (4.3, 1.0), (3.5, 1.6), (2.7, 1.0)];
    let shoelace: f32 = (0..5)
        .map(|k| {
            let ((x0, y0), (x1, y1)) = (corners[k], corners[(k + 1) % 5]);
            x0 * y1 - x1 * y0
        })
        .sum::<f32>()
        / 2.0;
    assert!((five - shoelace).abs() < 1e-5, "{five} {shoelace}");
    // Every triangle turns as its face does (counter-clockwise seen from +Z).
    assert!(mesh.triangles.iter().all(|t| area(t) > 0.0));
}

#[test]
fn a_face_with_a_repeated_vertex_is_skipped_and_counted() {
    let (_dir, write) = scratch();
    // A quad with a repeated corner (a pole), a triangle with one, and a good one.
    let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 1 2 3\nf 2 2 3\nf 1 2 4\n";
    let loaded = Mesh::from_obj(&write("poles.obj", text)).unwrap();
    let counts = FaceCounts {
        faces: 3,
        faces_triangulated: 1,
        skipped_degenerate: 2,
    };
    assert_eq!(loaded.counts, counts);
    assert_eq!(
        loaded.counts.to_string(),
        "1 faces triangulated, 2 degenerate triangles skipped"
    );
    // The quad's second triangle (1, 2, 3) and the last face are kept.
    assert_eq!(loaded.mesh.triangles.len(), 2);
    assert_eq!(loaded.mesh.degenerate(), 0);
}

#[test]
fn a_bad_file_gives_an_error_naming_the_path() {
    let (dir, write) = scratch();
    let cases: Vec<(PathBuf, Option<usize>, &str)> = vec![
        (dir.path().join("missing.obj"), None, "No such file"),
        (dir.path().to_path_buf(), None, "is a folder"),
        (
            write("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 4\n"),
            Some(4),
            "",
        ),
        (
            write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 0 1 2\n"),
            Some(5),
            "",
        ),
        (
            write("nan.obj", "v 0 0 0\nv 1 0 0\n# bad:\nv nan 1 0\nf 1 2 3\n"),
            Some(4),
            "NaN or infinite",
        ),
        (
            write("inf.obj", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n"),
            Some(2),
            "NaN or infinite",
        ),
        (
            write("words.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n"),
            Some(2),
            "",
        ),
        (write("empty.obj", ""), None, "no vertices"),
        (
            write("no-faces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"),
            None,
            "no faces",
        ),
        (
            write("edges.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\nl 1 3\n"),
            None,
            "no faces",
        ),
        (
            write(
                "line.obj",
                "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3 4\n",
            ),
            None,
            "all 2 are degenerate",
        ),
        (
            write("binary.obj", "v 0 0 0\n\u{0}\u{1}\n"),
            None,
            "no faces",
        ),
    ];
    let invalid = dir.path().join("invalid-utf8.obj");
    std::fs::write(&invalid, b"v 0 0 0\n\xff\xfe\n").unwrap();
    for (path, line, says) in cases
        .into_iter()
        .chain([(invalid, None, "cannot be read as text")])
    {
        let err = Mesh::from_obj(&path).unwrap_err();
        let Error::File { line: got, .. } = &err else {
            panic!("{err:?}")
        };
        let message = err.to_string();
        assert!(
            message.starts_with(&path.display().to_string()),
            "{message}"
        );
        assert_eq!(*got, line, "{message}");
        if let Some(line) = line {
            assert!(message.contains(&format!("line {line}:")), "{message}");
        }
        assert!(message.contains(says), "{message}");
    }
}

#[test]
fn obj_files() {
    let (dir, write) = scratch();
    let good = write(
        "good.obj",
        "# a triangle\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    );
    let loaded = Mesh::from_obj(&good).unwrap();
    assert_eq!(loaded.mesh.triangles, vec![[0, 1, 2]]);
    assert!((loaded.mesh.normals[0] - Vec3::Z).length() < 1e-6);
    assert_eq!(loaded.counts.to_string(), "");
    // Normals from the file, one per vertex, are kept (normalised).
    let with_normals = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nf 1//1 2//1 3//1\n";
    let mesh = Mesh::from_obj(&write("normals.obj", with_normals))
        .unwrap()
        .mesh;
    assert_eq!(mesh.normals, vec![Vec3::Z; 3]);
    // Two groups are merged into one mesh, the second's indices shifted.
    let groups = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\ng a\nf 1 2 3\ng b\nf 2 4 3\n";
    let mesh = Mesh::from_obj(&write("groups.obj", groups)).unwrap().mesh;
    assert_eq!(mesh.triangles.len(), 2);
    let missing = Mesh::from_obj(&dir.path().join("missing.obj")).unwrap_err();
    assert!(matches!(missing, Error::File { line: None, .. }));
    assert!(missing.to_string().contains("missing.obj"), "{missing}");
}

#[test]
fn obj_files_with_nothing_to_draw_are_refused_and_degenerate_triangles_counted() {
    let (_dir, write) = scratch();
    // One triangle with area, one whose corners lie on a line: the mesh keeps the
    // first only, and the count says so.
    let text = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n";
    let loaded = Mesh::from_obj(&write("flat.obj", text)).unwrap();
    assert_eq!(loaded.counts.skipped_degenerate, 1);
    assert_eq!(loaded.mesh.triangles.len(), 1);
    assert_eq!(loaded.mesh.objects(Vec3::ONE).unwrap().len(), 1);
    // Every triangle degenerate (1e38 corners: the area overflows): nothing to show.
    let huge = write("huge.obj", "v 0 0 0\nv 1e38 0 0\nv 0 1e38 0\nf 1 2 3\n");
    let err = Mesh::from_obj(&huge).unwrap_err();
    assert!(err.to_string().contains("all 1 are degenerate"), "{err}");
    let err = mesh_on_the_floor(&huge, 0).unwrap_err();
    assert!(err.to_string().contains("huge.obj"), "{err}");
}

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
    let mesh = Mesh::from_obj(&asset_path(Path::new(TEAPOT_OBJ)))
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
    let loaded = Mesh::from_obj(&asset_path(Path::new(TEAPOT_OBJ))).unwrap();
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
    let mesh = mesh_on_the_floor(mesh, subdivisions).unwrap();
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
    let model = mesh_on_the_floor(mesh, 0).unwrap().model;
    let floor_and_mesh = floor_and_mesh(&scene, &model).unwrap();
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

#[test]
fn mesh_on_the_floor_leaves_the_torus_where_it_was_and_fits_the_teapot_to_it() {
    use render_lessons::transform::Transform;
    let torus = mesh_on_the_floor(Path::new(TORUS_OBJ), 0).unwrap().model;
    let placed = Transform::rotation_x(-0.5).then(Transform::translation(2.2, 0.75, 1.6));
    assert_eq!(torus.model, placed);
    // The teapot, centred and scaled: its box's longest half side is the torus's 1.4.
    let teapot = mesh_on_the_floor(Path::new(TEAPOT_OBJ), 0).unwrap().model;
    let back = placed.inverse().unwrap();
    let in_box: Vec<Vec3> = teapot
        .mesh
        .positions
        .iter()
        .map(|&p| back.point(teapot.model.point(p)))
        .collect();
    let (lo, hi) = in_box
        .iter()
        .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &p| {
            (lo.min(p), hi.max(p))
        });
    assert!(((lo + hi) / 2.0).length() < 1e-5, "{lo} {hi}");
    assert!(
        (((hi - lo) / 2.0).max_element() - 1.4).abs() < 1e-5,
        "{lo} {hi}"
    );
}

#[test]
fn the_ray_caster_goes_through_a_bvh_when_the_list_would_be_too_slow_with_the_same_image() {
    let scene = still_life(Vec3::ZERO).unwrap();
    let camera = still_life_pinhole(96, 54).unwrap();
    let model = mesh_on_the_floor(Path::new(TORUS_OBJ), 0).unwrap().model;
    let floor_and_torus = floor_and_mesh(&scene, &model).unwrap();
    // The book's render, 480 x 270 x 1025 primitives: the list.
    let list = ListOrTree::new(floor_and_torus.clone(), 480 * 270);
    assert!(matches!(list, ListOrTree::List(_)));
    // At 1920 x 1080 the list would make 2 x 10^9 tests: the tree.
    let tree = ListOrTree::new(floor_and_torus, 1920 * 1080);
    assert!(matches!(tree, ListOrTree::Tree(_)));
    let (a, b) = (reference(&list, &camera), reference(&tree, &camera));
    assert_eq!(a.unwrap(), b.unwrap());
}

#[test]
fn too_much_subdivision_is_refused_before_any_work() {
    let torus = Path::new(TORUS_OBJ);
    // 11 levels: more than the 10 allowed.
    let err = mesh_on_the_floor(torus, 11).unwrap_err();
    assert_eq!(err.param(), "subdivide");
    // 10 levels of the torus: 1024 x 4^10 triangles, a terabyte.
    let err = mesh_on_the_floor(torus, 10).unwrap_err();
    assert!(
        matches!(
            err,
            Error::Machine {
                param: "subdivide",
                shortfall: Shortfall::TooMuch { unit: "bytes", .. }
            }
        ),
        "{err:?}"
    );
}

/// The teapot at 128 x 128 quads a patch: 32 x 128^2 = 524 288 quads, a million
/// triangles, written to a scratch file and read back.
#[test]
fn a_million_triangle_obj_loads() {
    let (_dir, write) = scratch();
    let obj = teapot_obj(128).unwrap();
    let path = write("teapot-128.obj", &obj);
    drop(obj);
    let loaded = Mesh::from_obj(&path).unwrap();
    assert_eq!(loaded.counts.faces, 524_288);
    assert_eq!(loaded.counts.skipped_degenerate, 8 * 128);
    assert_eq!(loaded.mesh.triangles.len(), 1_048_576 - 1024);
}

/// `--subdivide 4` on the teapot, as lessons 09 and 11 run it: 4032 x 4^4 triangles
/// through the BVH, the same image as the teapot unsplit (the flat faces do not
/// move) but for pixels where a split edge now lies exactly on a pixel centre.
#[test]
fn the_subdivided_teapot_renders_through_the_tree() {
    let teapot = asset_path(Path::new(TEAPOT_OBJ));
    let mesh = mesh_on_the_floor(&teapot, 4).unwrap();
    assert_eq!(mesh.model.mesh.triangles.len(), 4032 * 256);
    assert_eq!(mesh.subdivisions, 4);
    let (text, image) = lesson11::big_mesh(&teapot, 4).unwrap();
    assert!(text.contains("1032192"), "{text}");
    let (_, unsplit) = lesson11::big_mesh(&teapot, 0).unwrap();
    let differing = (0..270)
        .flat_map(|y| (0..480).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let (a, b) = (image.get(x, y).unwrap(), unsplit.get(x, y).unwrap());
            (a - b).abs().max_element() > 1.0 / 255.0
        })
        .count();
    assert!(differing * 1000 < 480 * 270, "{differing}");
}

/// Counts used in the chapter: faces per patch side, vertex numbers.
#[test]
fn lesson_09_mesh_worked_numbers() {
    let mut hist: HashMap<usize, usize> = HashMap::new();
    for patch in TEAPOT_PATCHES {
        *hist.entry(patch.len()).or_default() += 1;
    }
    assert_eq!(hist[&16], 32);
    assert_eq!(TEAPOT_POINTS.len(), 306);
    // 4032 triangles split four times.
    assert_eq!(4032 * 4usize.pow(4), 1_032_192);
}
