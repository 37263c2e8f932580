//! Lesson 09, real models as a user brings them (chapter 09_7): files that are not
//! quite UTF-8, models far from their file's origin or far larger than the scene,
//! faces of two corners and non-convex faces. Each file is a small equivalent of a
//! real one, written here.

use std::path::PathBuf;

use glam::{DVec3, Vec3};
use render_lessons::error::Error;
use render_lessons::mesh::{LoadedMesh, Mesh};
use render_lessons::scenes::{TEAPOT_OBJ, TORUS_OBJ, asset_path};

/// A scratch folder, and a function that writes `bytes` to a file of it.
fn scratch() -> (tempfile::TempDir, impl Fn(&str, &[u8]) -> PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path().to_path_buf();
    (dir, move |name: &str, bytes: &[u8]| {
        let path = root.join(name);
        std::fs::write(&path, bytes).unwrap();
        path
    })
}

/// The unit cube scaled by `scale` and moved by `offset`, as 8 vertices and 6 quads
/// turning counter-clockwise seen from outside.
fn cube(scale: f64, offset: f64) -> String {
    let mut text = String::new();
    for k in 0..8 {
        let corner = [k & 1, (k >> 1) & 1, (k >> 2) & 1]
            .map(|bit| format!("{}", offset + scale * f64::from(bit)));
        text += &format!("v {}\n", corner.join(" "));
    }
    // Vertex k + 1 has x = bit 0 of k, y = bit 1, z = bit 2.
    for face in [
        "1 3 4 2", "5 6 8 7", "1 2 6 5", "3 7 8 4", "1 5 7 3", "2 4 8 6",
    ] {
        text += &format!("f {face}\n");
    }
    text
}

/// The signed volume enclosed by a closed mesh (divergence theorem: a sixth of the
/// sum of a . (b x c) over its triangles), in f64.
fn volume(mesh: &Mesh) -> f64 {
    let p = |i: u32| mesh.positions[i as usize].as_dvec3();
    let sum: f64 = mesh
        .triangles
        .iter()
        .map(|&[a, b, c]| p(a).dot(p(b).cross(p(c))))
        .sum();
    sum / 6.0
}

fn load(path: &PathBuf) -> LoadedMesh {
    Mesh::from_obj(path).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_latin_1_byte_or_a_byte_order_mark_does_not_refuse_the_file() {
    let (_dir, write) = scratch();
    let triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    // "modèle" and "café" in Latin-1: bytes that are not UTF-8.
    let latin1 = [
        b"# mod\xe8le\nusemtl caf\xe9\n".as_slice(),
        triangle.as_bytes(),
    ];
    let loaded = load(&write("latin1.obj", &latin1.concat()));
    assert_eq!(loaded.mesh.triangles.len(), 1);
    // A byte-order mark before the first vertex: the vertex is still read, so the
    // face names the three vertices it means.
    let bom = ["\u{feff}", triangle].concat();
    let loaded = load(&write("bom.obj", bom.as_bytes()));
    assert_eq!(loaded.mesh.positions, [Vec3::ZERO, Vec3::X, Vec3::Y]);
    // A byte that is not UTF-8 inside a number is refused, at its line.
    let bad = write("number.obj", b"v 0 0 0\nv 1 0 \xe9\n");
    let err = Mesh::from_obj(&bad).unwrap_err();
    assert!(matches!(err, Error::File { line: Some(2), .. }), "{err}");
}

#[test]
fn a_bare_usemtl_or_a_missing_mtl_file_loads() {
    let (_dir, write) = scratch();
    let text = "mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl\nf 1 2 3\n";
    let loaded = load(&write("materials.obj", text.as_bytes()));
    assert_eq!(loaded.mesh.triangles.len(), 1);
}

#[test]
fn a_model_far_from_its_files_origin_keeps_every_triangle() {
    let (_dir, write) = scratch();
    // A cube of side 0.01 at a million: in f32 its corners a million away from the
    // origin are 0.0625 apart, and every triangle would lose its area.
    let far = load(&write("far.obj", cube(0.01, 1e6).as_bytes()));
    assert_eq!(far.mesh.triangles.len(), 12);
    assert_eq!(far.counts.skipped_degenerate, 0);
    assert_eq!(far.origin, DVec3::splat(1e6));
    let side = far
        .mesh
        .positions
        .iter()
        .map(|p| p.max_element())
        .fold(0.0, f32::max);
    assert!((side - 0.01).abs() < 1e-8, "{side}");
    assert!((volume(&far.mesh) - 1e-6).abs() < 1e-12);
    // The book's models lie round their origin and keep their coordinates.
    for path in [TORUS_OBJ, TEAPOT_OBJ] {
        assert_eq!(load(&asset_path(path)).origin, DVec3::ZERO, "{path}");
    }
}

#[test]
fn a_model_too_big_for_f32_arithmetic_loads_and_one_too_big_for_f32_is_refused() {
    let (_dir, write) = scratch();
    // Side 1e11: the cross products of its edges, 1e22, square to 1e44, beyond f32.
    let big = load(&write("big.obj", cube(1e11, 0.0).as_bytes()));
    assert_eq!(big.mesh.triangles.len(), 12);
    assert_eq!(big.counts.skipped_degenerate, 0);
    assert!((volume(&big.mesh) / 1e33 - 1.0).abs() < 1e-6);
    // Side 1e39: no f32 holds the coordinates, even round the model's centre. The
    // first face names vertex 1, (0, 0, 0), then vertex 3, (0, 1e39, 0), on line 3.
    let path = write("huge.obj", cube(1e39, 0.0).as_bytes());
    let err = Mesh::from_obj(&path).unwrap_err();
    let message = err.to_string();
    assert!(message.contains("huge.obj, line 3: "), "{message}");
    assert!(message.contains("too large for f32"), "{message}");
}

#[test]
fn faces_of_two_corners_are_counted() {
    let (_dir, write) = scratch();
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\nf 2 3\nf 1 2 3\nl 1 3\n";
    let loaded = load(&write("edges.obj", text.as_bytes()));
    assert_eq!((loaded.counts.faces, loaded.counts.skipped_edges), (1, 2));
    assert_eq!(
        loaded.counts.to_string(),
        "2 faces of fewer than 3 corners skipped"
    );
}

/// Twice the area of the triangles of `mesh`, each seen along +Z: the sum, and the
/// sum of their absolute values.
fn areas_along_z(mesh: &Mesh) -> (f32, f32) {
    mesh.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            (b - a).cross(c - a).z
        })
        .fold((0.0, 0.0), |(sum, abs), a| (sum + a, abs + a.abs()))
}

/// An OBJ file of one face, the polygon of `corners` in the plane z = 0.
fn polygon(corners: &[(f64, f64)]) -> String {
    let vertices: String = corners
        .iter()
        .map(|(x, y)| format!("v {x} {y} 0\n"))
        .collect();
    let numbers: Vec<String> = (1..=corners.len()).map(|k| k.to_string()).collect();
    format!("{vertices}f {}\n", numbers.join(" "))
}

/// A comb of `teeth` teeth of side 1 on a bar 1 high, counter-clockwise from its
/// bottom left corner: 4 x `teeth` corners, area 3 x `teeth` - 1.
fn comb(teeth: u32) -> Vec<(f64, f64)> {
    let right = f64::from(2 * teeth - 1);
    let mut corners = vec![(0.0, -1.0), (right, -1.0)];
    for j in (0..teeth).rev() {
        let x = f64::from(2 * j);
        corners.extend([(x + 1.0, 1.0), (x, 1.0)]);
        if j > 0 {
            corners.extend([(x, 0.0), (x - 1.0, 0.0)]);
        }
    }
    corners
}

#[test]
fn a_non_convex_face_is_cut_into_triangles_that_cover_it_exactly() {
    let (_dir, write) = scratch();
    // An L of area 3 whose first corner is the inner one, and a comb of 16 teeth
    // (64 corners, area 47): fans round their first corners would stick out.
    let l = [
        (1.0, 1.0),
        (0.0, 1.0),
        (0.0, 0.0),
        (2.0, 0.0),
        (2.0, 2.0),
        (1.0, 2.0),
    ];
    for (corners, area) in [(l.to_vec(), 3.0), (comb(16), 47.0)] {
        let n = corners.len();
        let loaded = load(&write("face.obj", polygon(&corners).as_bytes()));
        // n - 2 triangles, less those cut off with no area where corners that are
        // left come to lie on a line (the feet of the comb's teeth).
        let triangles = loaded.mesh.triangles.len();
        assert_eq!(triangles + loaded.counts.skipped_degenerate, n - 2);
        let (sum, abs) = areas_along_z(&loaded.mesh);
        assert_eq!(sum, abs, "{n} corners: every triangle turns the face's way");
        assert_eq!(sum / 2.0, area, "{n} corners");
    }
    // A bow tie, whose edges cross, is refused at its line.
    let bow_tie = polygon(&[(0.0, 0.0), (2.0, 2.0), (2.0, 0.0), (0.0, 2.0)]);
    let err = Mesh::from_obj(write("bow-tie.obj", bow_tie.as_bytes())).unwrap_err();
    assert!(matches!(err, Error::File { line: Some(5), .. }), "{err}");
    assert!(err.to_string().contains("edges cross"), "{err}");
}
