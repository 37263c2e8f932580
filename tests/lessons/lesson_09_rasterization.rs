//! Lesson 09: the rasterization pipeline of Lecture 2. The lecture's tables, the
//! projection against the cameras, the tessellated shapes closed and facing out, the
//! lesson's numbers (its snapshots), the numbers the pages work out, and the fixtures
//! of the lesson's other modules: `lesson_09_coverage` (clipping, coverage, the
//! z-buffer), `lesson_09_shading` (shading, the shadow map, against ray casting) and
//! `lesson_09_meshes` (OBJ files, the teapot).

use crate::examples::rasterization as lesson;
use render_lessons::course::report::num;

use std::collections::HashMap;
use std::fmt::Write;
use std::path::Path;

use glam::Vec3;
use render_lessons::camera::{Camera, Film, Frame, OrthoCamera, PinholeCamera};
use render_lessons::course::compare::{TOLERANCE, agreement, reference};
use render_lessons::error::{Error, Problem, Shortfall};
use render_lessons::mesh::{LECTURE_TRIANGLES, LECTURE_VERTICES, Mesh, Model};
use render_lessons::raster::{
    CameraTransforms, Cull, DepthRange, RasterSettings, Shading, rasterize,
};
use render_lessons::render::with_threads;
use render_lessons::scene::{PointLight, Scene};
use render_lessons::scenes::{
    PlacedMesh, TORUS_OBJ, Up, mesh_on_the_floor, still_life, still_life_pinhole,
    still_life_shadows,
};
use render_lessons::transform::Transform;

pub(crate) fn film() -> Film {
    Film::new(16, 9, (-1.6, 1.6), (-0.9, 0.9)).unwrap()
}

/// Both cameras' place: at (1, 2, 6), looking along (-0.2, -0.3, -1), Y up.
fn frame() -> Frame {
    Frame::look(
        Vec3::new(1.0, 2.0, 6.0),
        Vec3::new(-0.2, -0.3, -1.0),
        Vec3::Y,
    )
    .unwrap()
}

pub(crate) fn pinhole() -> PinholeCamera {
    PinholeCamera::new(film(), 1.5, frame()).unwrap()
}

fn ortho() -> OrthoCamera {
    OrthoCamera::new(film(), frame())
}

pub(crate) const DEPTH: DepthRange = DepthRange {
    near: 0.5,
    far: 50.0,
};

pub(crate) const LIGHT: PointLight = PointLight {
    position: Vec3::new(4.0, 6.0, 4.0),
    intensity: Vec3::splat(40.0),
};

#[test]
fn lecture_tables() {
    let mut out = String::from("vertex list (slide numbering)\n");
    for (i, v) in LECTURE_VERTICES.iter().enumerate() {
        writeln!(out, "{}\t{}\t{}\t{}", i + 1, v[0], v[1], v[2]).unwrap();
    }
    out.push_str("triangle list (slide numbering)\n");
    for (i, t) in LECTURE_TRIANGLES.iter().enumerate() {
        writeln!(out, "{}\t{}\t{}\t{}", i + 1, t[0], t[1], t[2]).unwrap();
    }
    insta::assert_snapshot!("lecture_tables", out);

    // The full triangle list needs vertices the slide does not show.
    let positions: Vec<Vec3> =
        LECTURE_VERTICES.iter().map(|&p| Vec3::from(p)).collect();
    let triangles: Vec<[u32; 3]> =
        LECTURE_TRIANGLES.iter().map(|t| t.map(|i| i - 1)).collect();
    let err = Mesh::new(positions.clone(), triangles).unwrap_err();
    assert_eq!(
        err,
        Error::Value {
            param: "triangle",
            problem: Problem::VertexIndex {
                triangle: 0,
                index: 4,
                vertices: 4
            }
        }
    );
    assert!(err.to_string().contains("triangle 0 refers to vertex 4"));

    // The fixture: the four vertices, slide triangles 3 and 4: the square y = 5, facing
    // +Y.
    let mesh = Mesh::lecture_fixture();
    assert_eq!(mesh.positions, positions);
    assert_eq!(mesh.triangles, vec![[1, 0, 3], [2, 1, 3]]);
    for n in &mesh.normals {
        assert!((*n - Vec3::Y).length() < 1e-6);
    }
}

fn projection_table(camera: &Camera, points: &[Vec3]) -> String {
    let pipeline = CameraTransforms::new(camera, DEPTH).unwrap();
    let mut out = String::new();
    for &p in points {
        let clip = pipeline.to_clip(&Transform::IDENTITY, p);
        let screen = pipeline.to_screen(clip).unwrap();
        let expected = camera.project(p).unwrap();
        assert!(
            (screen.truncate() - expected).length() < 1e-4,
            "{p}: {screen} vs {expected}"
        );
        assert!((0.0..=1.0).contains(&screen.z));
        writeln!(
            out,
            "({}, {}, {}) -> clip ({}, {}, {}, {})\n    -> pixel ({}, {}) depth {}",
            num(f64::from(p.x), 4),
            num(f64::from(p.y), 4),
            num(f64::from(p.z), 4),
            num(f64::from(clip.x), 4),
            num(f64::from(clip.y), 4),
            num(f64::from(clip.z), 4),
            num(f64::from(clip.w), 4),
            num(f64::from(screen.x), 4),
            num(f64::from(screen.y), 4),
            num(f64::from(screen.z), 4)
        )
        .unwrap();
    }
    out
}

#[test]
fn projection_matches_the_cameras() {
    let points: Vec<Vec3> = LECTURE_VERTICES
        .iter()
        .map(|&p| Vec3::from(p) * 0.5 - Vec3::new(2.0, 2.0, 3.0))
        .chain([Vec3::ZERO, Vec3::new(-1.0, 0.5, -2.0)])
        .collect();
    let mut out = String::from("pinhole\n");
    out += &projection_table(&pinhole().into(), &points);
    out += "orthographic\n";
    out += &projection_table(&ortho().into(), &points);
    insta::assert_snapshot!("projection", out);

    // Many more points, both cameras, at the origin and placed.
    for camera in [
        Camera::from(pinhole()),
        Camera::from(ortho()),
        PinholeCamera::at_origin(film(), 1.0).unwrap().into(),
        OrthoCamera::at_origin(film()).into(),
    ] {
        let pipeline = CameraTransforms::new(&camera, DEPTH).unwrap();
        for i in 0..200 {
            let f = i as f32;
            let p = Vec3::new(
                (f * 0.37).sin() * 3.0,
                (f * 0.71).cos() * 2.0,
                -(f * 0.13).sin().abs() * 8.0 - 1.0,
            );
            let Some(expected) = camera.project(p) else {
                continue;
            };
            let camera_z = camera.frame().point_to_camera(p).z;
            if -camera_z < DEPTH.near && matches!(camera, Camera::Pinhole(_)) {
                continue;
            }
            let screen = pipeline
                .to_screen(pipeline.to_clip(&Transform::IDENTITY, p))
                .unwrap();
            assert!(
                (screen.truncate() - expected).length()
                    < 1e-4 * expected.length().max(1.0)
            );
        }
    }
}

fn quad(z: f32, half: f32) -> Mesh {
    Mesh::new(
        vec![
            Vec3::new(-half, -half, z),
            Vec3::new(half, -half, z),
            Vec3::new(half, half, z),
            Vec3::new(-half, half, z),
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    )
    .unwrap()
}

#[test]
fn uv_sphere_is_closed_and_faces_out() {
    let centre = Vec3::new(1.0, -2.0, 0.5);
    let mesh = Mesh::uv_sphere(centre, 2.0, 12, 7).unwrap();
    assert_eq!(mesh.positions.len(), 2 + 12 * 6);
    assert_eq!(mesh.triangles.len(), 2 * 12 * 6);
    let mut edges = HashMap::new();
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        let n = (b - a).cross(c - a);
        assert!(
            n.dot((a + b + c) / 3.0 - centre) > 0.0,
            "inward triangle {t:?}"
        );
        for k in 0..3 {
            *edges.entry((t[k], t[(k + 1) % 3])).or_insert(0) += 1;
        }
    }
    // Closed and consistently wound: every directed edge once, and its reverse once.
    for (&(a, b), &count) in &edges {
        assert_eq!(count, 1);
        assert_eq!(edges.get(&(b, a)), Some(&1));
    }
    for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
        assert!(((*p - centre).length() - 2.0).abs() < 1e-5);
        assert!((*n - (*p - centre) / 2.0).length() < 1e-5);
    }
    assert!(matches!(
        Mesh::uv_sphere(centre, 1.0, 2, 5),
        Err(Error::Value {
            param: "segments",
            problem: Problem::TooFew { .. }
        })
    ));
    assert!(matches!(
        Mesh::uv_sphere(centre, 1.0, 5, 1),
        Err(Error::Value {
            param: "rings",
            problem: Problem::TooFew { .. }
        })
    ));
    assert!(matches!(
        Mesh::uv_sphere(centre, 0.0, 5, 5),
        Err(Error::Value {
            param: "radius",
            problem: Problem::NotPositive { .. }
        })
    ));
}

#[test]
fn segments_are_checked_before_tessellating() {
    let scene = render_lessons::scenes::still_life(Vec3::ZERO).unwrap();
    assert!(render_lessons::mesh::check_segments(&scene, 4).is_ok());
    let too_few = render_lessons::mesh::check_segments(&scene, 3).unwrap_err();
    assert_eq!(too_few.param(), "segments");
    // 65536 segments: three spheres of 2^32 triangles, far more than any machine has.
    let too_many = render_lessons::mesh::check_segments(&scene, 65536).unwrap_err();
    assert!(
        matches!(
            too_many,
            Error::Machine {
                param: "segments",
                shortfall: Shortfall::TooMuch { .. }
            }
        ),
        "{too_many:?}"
    );
    assert!(render_lessons::mesh::tessellate(&scene, u32::MAX).is_err());
}

#[test]
fn same_image_for_any_thread_count() {
    let instances = vec![
        Model::new(
            Mesh::uv_sphere(Vec3::new(0.0, 0.0, -4.0), 1.0, 24, 12).unwrap(),
            Vec3::new(0.9, 0.3, 0.2),
        ),
        Model::new(
            Mesh::uv_sphere(Vec3::new(1.5, 0.5, -6.0), 1.2, 24, 12).unwrap(),
            Vec3::new(0.2, 0.8, 0.3),
        ),
        Model::new(quad(-7.0, 4.0), Vec3::splat(0.7)),
    ];
    let camera: Camera = pinhole().into();
    let film = Film::new(96, 54, (-1.6, 1.6), (-0.9, 0.9)).unwrap();
    let camera2: Camera = PinholeCamera::at_origin(film, 1.0).unwrap().into();
    for camera in [camera, camera2, ortho().into()] {
        for shading in [Shading::PerVertex, Shading::PerPixel] {
            let settings = RasterSettings {
                shading,
                cull: Cull::Back,
                ..RasterSettings::default()
            };
            let on = |threads| {
                with_threads(threads, || {
                    rasterize(&instances, &camera, &LIGHT, &settings)
                })
                .unwrap()
            };
            let one = on(Some(1));
            for threads in [Some(2), Some(5), None] {
                assert_eq!(one, on(threads));
            }
            one.to_srgb8().unwrap();
        }
    }
}

/// The lesson at its defaults, as `main` runs it: the scene, the tessellation of 64
/// segments, the 1024^2 shadow map with a bias of 1, and the torus.
fn book_lesson() -> (Scene, PlacedMesh, lesson::Lesson) {
    let scene = still_life(Vec3::ZERO).unwrap();
    let camera = still_life_pinhole(480, 270).unwrap();
    let mesh = mesh_on_the_floor(Path::new(TORUS_OBJ), Up::Y, 0, &camera).unwrap();
    let shadows = still_life_shadows(1024, 1.0);
    let lesson = lesson::images(&scene, &camera, 64, shadows, &mesh.model).unwrap();
    (scene, mesh, lesson)
}

#[test]
fn numbers() {
    let (scene, mesh, lesson) = book_lesson();
    insta::assert_snapshot!(
        "numbers",
        lesson::numbers(&scene, 64, (&mesh, "torus.obj"), &lesson).unwrap()
    );

    let by_label = |label: &str| {
        let found = lesson.agreements.iter().find(|(l, _, _)| *l == label);
        found.map(|&(_, _, a)| a).unwrap()
    };
    // The target: the rasterized image and the ray-cast one agree on at least
    // 99% of the pixels away from silhouettes, for the tessellated scene and the mesh.
    let per_pixel = by_label("per-pixel shading");
    assert!(per_pixel.percent_agreeing() >= 99.0, "{per_pixel:?}");
    let mesh = by_label("floor + mesh");
    assert!(mesh.percent_agreeing() >= 99.0, "{mesh:?}");
    // The table compares what the lesson writes: recomputed from the files' images.
    let recomputed = agreement(
        &lesson.images.per_pixel,
        &lesson.images.ray_cast,
        &reference(&scene, &still_life_pinhole(480, 270).unwrap())
            .unwrap()
            .silhouettes,
        TOLERANCE,
    );
    assert_eq!(recomputed, per_pixel);
    // Silhouettes are a thin minority of the image.
    assert!(per_pixel.silhouette * 20 < per_pixel.compared);
    // Gouraud shading of a floor made of two huge triangles is far off.
    let gouraud = by_label("per-vertex (Gouraud)");
    assert!(
        gouraud.differing > 100 * per_pixel.differing.max(1),
        "{gouraud:?}"
    );
    // Too small a bias gives acne, too large detaches shadows: both worse than 1 texel.
    let good = by_label("shadow map").differing;
    assert!(by_label("shadow map, bias 0").differing > 10 * good);
    assert!(by_label("shadow map, bias x 50").differing > 5 * good);
}

#[test]
fn cuboid_and_floor_face_outwards() {
    let cuboid =
        Mesh::cuboid(Vec3::new(-1.0, 0.0, 2.0), Vec3::new(0.5, 3.0, 2.5)).unwrap();
    assert_eq!((cuboid.positions.len(), cuboid.triangles.len()), (24, 12));
    let centre = Vec3::new(-0.25, 1.5, 2.25);
    let floor = Mesh::floor(Vec3::new(1.0, -2.0, 3.0), 4.0).unwrap();
    for mesh in [&cuboid, &floor] {
        for t in &mesh.triangles {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            let geometric = (b - a).cross(c - a).normalize();
            for &i in t {
                assert!((mesh.normals[i as usize] - geometric).length() < 1e-6);
            }
            if std::ptr::eq(mesh, &cuboid) {
                // Outward: away from the box's centre.
                assert!(geometric.dot(a - centre) > 0.0);
            }
        }
    }
    assert!(floor.normals.iter().all(|&n| n == Vec3::Y));
    let flat = Mesh::uv_sphere(Vec3::ZERO, 1.0, 8, 4)
        .unwrap()
        .flat_shaded()
        .unwrap();
    assert_eq!(flat.positions.len(), 3 * flat.triangles.len());
}

/// The numbers lesson 09's pages work out by hand: depth with n = 0.5 and f = 50
/// (`09_1`), the guard band (`09_2`), a perspective-correct weight (`09_3`) and a
/// light 100 above a 4 x 4 square (`09_4`).
#[test]
fn lesson_09_worked_numbers() {
    let (n, f) = (0.5f64, 50.0f64);
    let (a, b) = ((f + n) / (f - n), 2.0 * f * n / (f - n));
    assert_eq!(format!("{a:.4} {b:.4}"), "1.0202 1.0101");
    let z = |d: f64| a - b / d;
    let depth = |d: f64| (z(d) + 1.0) / 2.0;
    assert_eq!(format!("{:.4}", z(6.6321)), "0.8679");
    assert_eq!(format!("{:.4} {:.3}", z(1.0), depth(1.0)), "0.0101 0.505");
    assert_eq!(format!("{:.4} {:.3}", z(5.0), depth(5.0)), "0.8182 0.909");
    assert_eq!(format!("{:.0}", 100.0 * depth(5.0)), "91");
    assert!(depth(0.5).abs() < 1e-12 && (depth(50.0) - 1.0).abs() < 1e-12);
    // Exercise 9.7: film [-1.6, 1.6] x [-0.9, 0.9] at s = 1.5, 16 x 9 pixels, the
    // point (0.8, 0.45, -3).
    let s = 1.5;
    let (xs, ys) = (s * 0.8 / 3.0, s * 0.45 / 3.0);
    assert_eq!(format!("{xs:.1} {ys:.3}"), "0.4 0.225");
    assert_eq!(
        (16.0 * (xs + 1.6) / 3.2, 9.0 * (0.9 - ys) / 1.8),
        (10.0, 3.375)
    );
    assert_eq!(
        format!("{:.4} {:.4}", 2.0 * s / 3.2, 2.0 * s / 1.8),
        "0.9375 1.6667"
    );
    assert_eq!((8.0 * (0.25 + 1.0), 4.5 * (1.0 - 0.25)), (10.0, 3.375));
    // 09_2: |x| <= 64 w in NDC, 2 units per image width.
    assert_eq!((64.0 - 1.0) / 2.0, 31.5);
    // 09_3: the far vertex's weight at the screen midpoint.
    let (near, far) = (0.5 * 1.0, 0.5 * 0.25);
    assert_eq!((far, near + far, far / (near + far)), (0.125, 0.625, 0.2));
    // 09_4: a light 100 above the centre of a 4 x 4 square.
    let d2 = 2.0f64 * 2.0 + 100.0 * 100.0 + 2.0 * 2.0;
    assert_eq!(d2, 10_008.0);
    let cos = 100.0 / d2.sqrt();
    assert_eq!(format!("{cos:.4} {:.4e}", cos / d2), "0.9996 9.9880e-5");
    assert_eq!(format!("{:.2}", 100.0 * (1.0 - cos / d2 / 1e-4)), "0.12");
}
