//! Lesson 09, a model from a file placed in the still life (chapter 09_7): on the
//! floor, inside the frame, whatever its size, its place in its file, the axis it
//! has up, or a stray triangle far from the rest.

use std::path::{Path, PathBuf};

use clap::Parser;
use glam::{DVec3, Vec3, Vec3Swizzles};
use render_lessons::camera::Camera;
use render_lessons::mesh::Mesh;
use render_lessons::scenes::placement::{STAND, frame_scale};
use render_lessons::scenes::{
    PlacedMesh, TEAPOT_OBJ, TORUS_OBJ, Up, asset_path, mesh_on_the_floor,
    still_life_pinhole,
};
use render_lessons::transform::Transform;

use crate::examples::rasterization as lesson;

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

/// The box from `offset` to `offset + size` as 8 vertices and 6 quads turning
/// counter-clockwise seen from outside (vertex k + 1 has x = bit 0 of k, y = bit
/// 1, z = bit 2), the vertices numbered from `first`.
fn block(offset: DVec3, size: DVec3, first: u32) -> String {
    let mut text = String::new();
    for k in 0..8u32 {
        let bits =
            DVec3::new(f64::from(k & 1), f64::from((k >> 1) & 1), f64::from(k >> 2));
        let p = offset + size * bits;
        text += &format!("v {} {} {}\n", p.x, p.y, p.z);
    }
    for face in [
        [1, 3, 4, 2],
        [5, 6, 8, 7],
        [1, 2, 6, 5],
        [3, 7, 8, 4],
        [1, 5, 7, 3],
        [2, 4, 8, 6],
    ] {
        let corners = face.map(|k| (k + first).to_string());
        text += &format!("f {}\n", corners.join(" "));
    }
    text
}

/// The world positions of a placed mesh.
fn world(mesh: &PlacedMesh) -> Vec<Vec3> {
    let model = &mesh.model;
    model
        .mesh
        .positions
        .iter()
        .map(|&p| model.model.point(p))
        .collect()
}

/// Checks that `mesh` stands on the floor (its lowest point at y = 0) and that
/// `camera` sees every point of it, at least 1 % of the frame inside its edges.
fn stands_in_the_frame(mesh: &PlacedMesh, camera: &Camera, name: &str) {
    let points = world(mesh);
    let lowest = points.iter().map(|p| p.y).fold(f32::INFINITY, f32::min);
    assert!(lowest.abs() < 1e-5, "{name}: lowest point at y = {lowest}");
    let (w, h) = (camera.film().width() as f32, camera.film().height() as f32);
    for p in points {
        let pixel = camera.project(p).unwrap();
        let inside = pixel.cmpge((0.0099 * w, 0.0099 * h).into()).all()
            && pixel.cmple((0.9901 * w, 0.9901 * h).into()).all();
        assert!(inside, "{name}: {p} lands at {pixel}");
    }
}

#[test]
fn the_torus_and_the_teapot_stand_where_they_stood_raised_onto_the_floor() {
    let camera = still_life_pinhole(480, 270).unwrap();
    let torus = mesh_on_the_floor(Path::new(TORUS_OBJ), Up::Y, 0, &camera).unwrap();
    // As read: not moved, not scaled (its box: half side 1.4).
    let read = Mesh::from_obj(asset_path(TORUS_OBJ)).unwrap().mesh;
    assert_eq!(torus.model.mesh, read);
    // Tilted by 0.5 about x, the torus (radii 1 and 0.4) reaches sin 0.5 + 0.4 =
    // 0.879 below its centre, which stood at 0.75 (0.13 under the floor); its
    // vertices lie on that surface, so the lowest reaches a little less far.
    let lift = torus.model.model.point(Vec3::ZERO).y;
    assert!((0.86..=0.5f32.sin() + 0.4).contains(&lift), "{lift}");
    let placed =
        Transform::rotation_x(-0.5).then(Transform::translation(2.2, lift, 1.6));
    assert_eq!(torus.model.model, placed);
    stands_in_the_frame(&torus, &camera, "torus");
    // The teapot: centred, its box's longest half side the torus's 1.4.
    let teapot = mesh_on_the_floor(Path::new(TEAPOT_OBJ), Up::Y, 0, &camera).unwrap();
    let (lo, hi) = (teapot.model.mesh.positions.iter())
        .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &p| {
            (lo.min(p), hi.max(p))
        });
    assert!(((lo + hi) / 2.0).length() < 1e-5, "{lo} {hi}");
    assert!(
        (((hi - lo) / 2.0).max_element() - 1.4).abs() < 1e-5,
        "{lo} {hi}"
    );
    stands_in_the_frame(&teapot, &camera, "teapot");
    for fitted in [&torus, &teapot] {
        assert_eq!((fitted.fit.left_out, fitted.fit.frame_scale), (0, 1.0));
    }
}

#[test]
fn models_of_any_shape_size_and_place_stand_on_the_floor_inside_the_frame() {
    let (_dir, write) = scratch();
    let cases = [
        ("cube", DVec3::ZERO, DVec3::ONE),
        ("tower", DVec3::ZERO, DVec3::new(1.0, 10.0, 1.0)),
        ("wall", DVec3::ZERO, DVec3::new(10.0, 1.0, 0.5)),
        ("far", DVec3::splat(1e6), DVec3::splat(0.01)),
        ("huge", DVec3::splat(-5e10), DVec3::splat(1e11)),
        ("grain", DVec3::ZERO, DVec3::splat(1e-6)),
    ];
    // The book's frame, a square one and a wide one: the fit is the frame's.
    for (width, height) in [(480, 270), (200, 200), (800, 200)] {
        let camera = still_life_pinhole(width, height).unwrap();
        for (name, offset, size) in cases {
            let path = write("block.obj", &block(offset, size, 0));
            let mesh = mesh_on_the_floor(&path, Up::Y, 0, &camera).unwrap();
            assert_eq!(mesh.model.mesh.triangles.len(), 12, "{name}");
            stands_in_the_frame(&mesh, &camera, name);
            // In the book's frame, a cube at the torus's size fits as it is, and a
            // wall of its width, reaching further than the torus, shrinks.
            // In the book's frame a tower and a wall as large as the torus fit; a
            // cube that large reaches nearer the camera than the torus and
            // shrinks, wherever its file put it.
            if width == 480 {
                let shrunk = mesh.fit.frame_scale < 1.0;
                assert_eq!(shrunk, !["tower", "wall"].contains(&name), "{name}");
            }
        }
    }
}

#[test]
fn a_stray_triangle_far_away_is_left_out_of_the_fit_and_said() {
    let (_dir, write) = scratch();
    let camera = still_life_pinhole(480, 270).unwrap();
    let cube = block(DVec3::ZERO, DVec3::ONE, 0);
    let alone =
        mesh_on_the_floor(&write("cube.obj", &cube), Up::Y, 0, &camera).unwrap();
    // The same cube with a speck 1000 sides away: placed as if the speck were not
    // there, and the speck counted.
    let speck =
        "v 1000 1000 1000\nv 1000.001 1000 1000\nv 1000 1000.001 1000\nf 9 10 11\n";
    let path = write("speck.obj", &(cube + speck));
    let with = mesh_on_the_floor(&path, Up::Y, 0, &camera).unwrap();
    assert_eq!(with.fit.left_out, 1);
    assert!(with.fit.left_out_area < 1e-6, "{}", with.fit.left_out_area);
    assert_eq!(with.model.model, alone.model.model);
    assert_eq!(world(&with)[..8], world(&alone)[..]);
    let numbers = lesson_numbers(&with);
    let said =
        "fitted without 1 triangles far from the rest (under 0.01 % of the area)";
    assert!(numbers.contains(said), "{numbers}");
    // Two cubes apart, each with half the area: both are the model.
    let pair =
        block(DVec3::ZERO, DVec3::ONE, 0) + &block(DVec3::splat(5.0), DVec3::ONE, 8);
    let pair = mesh_on_the_floor(&write("pair.obj", &pair), Up::Y, 0, &camera).unwrap();
    assert_eq!(pair.fit.left_out, 0);
    stands_in_the_frame(&pair, &camera, "pair");
}

/// Lesson 09's tables with `mesh`, at 96 x 54 pixels.
fn lesson_numbers(mesh: &PlacedMesh) -> String {
    use render_lessons::scenes::{still_life, still_life_shadows};
    let scene = still_life(Vec3::ZERO).unwrap();
    let camera = still_life_pinhole(96, 54).unwrap();
    let shadows = still_life_shadows(64, 1.0);
    let images = lesson::images(&scene, &camera, 8, shadows, &mesh.model);
    lesson::numbers(&scene, 8, (mesh, "speck.obj"), &images.unwrap()).unwrap()
}

#[test]
fn up_z_stands_a_z_up_model_up() {
    let (_dir, write) = scratch();
    let camera = still_life_pinhole(480, 270).unwrap();
    // A post 10 high along z, as a scan or a 3D-printing file would have it.
    let path = write(
        "post.obj",
        &block(DVec3::ZERO, DVec3::new(1.0, 1.0, 10.0), 0),
    );
    let height = |up| {
        let mesh = mesh_on_the_floor(&path, up, 0, &camera).unwrap();
        stands_in_the_frame(&mesh, &camera, "post");
        let points = world(&mesh);
        let top = points.iter().map(|p| p.y).fold(0.0, f32::max);
        let across = points.iter().map(|p| (p.xz() - STAND.xz()).length());
        (top, across.fold(0.0, f32::max))
    };
    let (lying, standing) = (height(Up::Y), height(Up::Z));
    assert!(standing.0 > 1.5 * lying.0, "{lying:?} {standing:?}");
    assert!(standing.0 > 3.0 * standing.1, "{standing:?}");
    // The flag: y or z, and nothing else, named in the error.
    let parse = |up: &str| lesson::Args::try_parse_from(["09", "--up", up]);
    assert_eq!(parse("z").unwrap().up, Up::Z);
    let err = parse("x").unwrap_err().to_string();
    assert!(err.contains("'--up <UP>'") && err.contains("y, z"), "{err}");
    // The frame's fit alone: a point at the stand itself needs no shrinking.
    assert_eq!(frame_scale(&camera, STAND, 0.01, [STAND].into_iter()), 1.0);
}
