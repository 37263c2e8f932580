//! Lesson 09: the rasterization pipeline of Lecture 2; the lesson's comparison with
//! ray casting; the shadow map.

use crate::examples::rasterization as lesson;

use render_lessons::ray::Interval;
use std::collections::HashMap;
use std::fmt::Write;
use std::path::Path;

use glam::{Vec2, Vec3};
use render_lessons::camera::{Camera, Film, Frame, OrthoCamera, PinholeCamera};
use render_lessons::course::compare::{TOLERANCE, agreement, reference};
use render_lessons::error::{Error, Problem, Shortfall};
use render_lessons::mesh::{LECTURE_TRIANGLES, LECTURE_VERTICES, Mesh, Model};
use render_lessons::raster::{
    CameraTransforms, ClipVertex, Cull, DepthRange, RasterSettings, ScreenVertex, Shading,
    ShadowMap, Shadows, Varyings, clip_triangle, rasterize, rasterize_triangle,
};
use render_lessons::render::with_threads;
use render_lessons::scene::{PointLight, Scene};
use render_lessons::scenes::squares::{Squares, squares};
use render_lessons::scenes::{
    PlacedMesh, TORUS_OBJ, mesh_on_the_floor, still_life, still_life_pinhole, still_life_shadows,
};
use render_lessons::transform::Transform;

/// Fixed precision, -0 written as 0.
fn num(x: f32) -> String {
    let s = format!("{x:.4}");
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

fn film() -> Film {
    Film::new(16, 9, (-1.6, 1.6), (-0.9, 0.9)).unwrap()
}

fn pinhole() -> PinholeCamera {
    let frame = Frame::look(
        Vec3::new(1.0, 2.0, 6.0),
        Vec3::new(-0.2, -0.3, -1.0),
        Vec3::Y,
    )
    .unwrap();
    PinholeCamera::new(film(), 1.5, frame).unwrap()
}

fn ortho() -> OrthoCamera {
    let frame = Frame::look(
        Vec3::new(1.0, 2.0, 6.0),
        Vec3::new(-0.2, -0.3, -1.0),
        Vec3::Y,
    )
    .unwrap();
    OrthoCamera::new(film(), frame)
}

const DEPTH: DepthRange = DepthRange {
    near: 0.5,
    far: 50.0,
};

const LIGHT: PointLight = PointLight {
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
    let positions: Vec<Vec3> = LECTURE_VERTICES.iter().map(|&p| Vec3::from(p)).collect();
    let triangles: Vec<[u32; 3]> = LECTURE_TRIANGLES.iter().map(|t| t.map(|i| i - 1)).collect();
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

    // The fixture: the four vertices, slide triangles 3 and 4: the square y = 5, facing +Y.
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
            num(p.x),
            num(p.y),
            num(p.z),
            num(clip.x),
            num(clip.y),
            num(clip.z),
            num(clip.w),
            num(screen.x),
            num(screen.y),
            num(screen.z)
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
            assert!((screen.truncate() - expected).length() < 1e-4 * expected.length().max(1.0));
        }
    }
}

fn screen_vertex(p: Vec2) -> ScreenVertex {
    ScreenVertex {
        pixel: p,
        depth: 0.5,
        inv_w: 1.0,
        varyings: Varyings::default(),
    }
}

/// Coverage counts of a closed fan of `n` triangles around `centre`.
fn fan_coverage(centre: Vec2, corners: &[Vec2], size: u32) -> HashMap<(u32, u32), u32> {
    let mut counts = HashMap::new();
    for i in 0..corners.len() {
        let t = [centre, corners[i], corners[(i + 1) % corners.len()]].map(screen_vertex);
        rasterize_triangle(&t, Cull::None, size, 0..size, |f| {
            *counts.entry((f.x, f.y)).or_insert(0) += 1;
        });
    }
    counts
}

/// True if `p` is inside the convex polygon `corners` by at least `margin` pixels.
fn inside_convex(p: Vec2, corners: &[Vec2], margin: f32) -> Option<bool> {
    let mut min = f32::INFINITY;
    let mut max = f32::NEG_INFINITY;
    for i in 0..corners.len() {
        let (a, b) = (corners[i], corners[(i + 1) % corners.len()]);
        let d = (b - a).perp_dot(p - a) / (b - a).length();
        min = min.min(d);
        max = max.max(d);
    }
    // Corners wind one way: all signed distances share a sign inside.
    let (lo, hi) = if max <= 0.0 || min >= 0.0 {
        (min.abs().min(max.abs()), true)
    } else {
        (0.0, false)
    };
    if hi && lo > margin {
        Some(true)
    } else if !hi && (min < -margin && max > margin) {
        Some(false)
    } else {
        None
    }
}

#[test]
fn shared_edges_are_covered_exactly_once() {
    let size = 40;
    let cases: Vec<(Vec2, Vec<Vec2>)> = vec![
        // Pixel-aligned: every vertex on a pixel centre, spokes through pixel centres.
        (
            Vec2::new(20.5, 20.5),
            [
                (10, 10),
                (20, 6),
                (30, 10),
                (34, 20),
                (30, 30),
                (20, 34),
                (10, 30),
                (6, 20),
            ]
            .iter()
            .map(|&(x, y)| Vec2::new(x as f32 + 0.5, y as f32 + 0.5))
            .collect(),
        ),
        // Not aligned: a centre and corners off the grid, on a circle.
        (
            Vec2::new(19.3, 20.7),
            (0..13)
                .map(|i| {
                    let a = i as f32 / 13.0 * std::f32::consts::TAU;
                    Vec2::new(19.3 + 15.1 * a.cos(), 20.7 + 14.3 * a.sin())
                })
                .collect(),
        ),
        // Vertices on integer corners (pixel edges), axis-aligned spokes.
        (
            Vec2::new(20.0, 20.0),
            [
                (8, 8),
                (20, 8),
                (32, 8),
                (32, 20),
                (32, 32),
                (20, 32),
                (8, 32),
                (8, 20),
            ]
            .iter()
            .map(|&(x, y)| Vec2::new(x as f32, y as f32))
            .collect(),
        ),
    ];
    for (centre, corners) in cases {
        let counts = fan_coverage(centre, &corners, size);
        assert!(counts.values().all(|&c| c == 1), "a pixel drawn twice");
        for y in 0..size {
            for x in 0..size {
                let p = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
                let covered = counts.get(&(x, y)).copied().unwrap_or(0);
                match inside_convex(p, &corners, 1e-3) {
                    Some(true) => assert_eq!(covered, 1, "crack at ({x}, {y})"),
                    Some(false) => assert_eq!(covered, 0, "outside drawn at ({x}, {y})"),
                    None => {}
                }
            }
        }
    }
    // A square split along its diagonal through pixel centres: area exactly once.
    let [a, b, c, d] =
        [(2.5, 2.5), (12.5, 2.5), (12.5, 12.5), (2.5, 12.5)].map(|(x, y)| Vec2::new(x, y));
    let mut counts = HashMap::new();
    for t in [[a, b, c], [a, c, d]] {
        rasterize_triangle(&t.map(screen_vertex), Cull::None, 16, 0..16, |f| {
            *counts.entry((f.x, f.y)).or_insert(0) += 1;
        });
    }
    assert!(counts.values().all(|&c| c == 1));
    // Top-left rule: of the border pixel centres, the top row and left column belong.
    assert_eq!(counts.len(), 100);
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
fn z_buffer_order_does_not_matter() {
    let Squares {
        near,
        far,
        camera,
        light,
    } = squares().unwrap();
    for shading in [Shading::PerVertex, Shading::PerPixel] {
        let settings = RasterSettings {
            shading,
            ..RasterSettings::default()
        };
        let a = rasterize(&[near.clone(), far.clone()], &camera, &light, &settings).unwrap();
        let b = rasterize(&[far.clone(), near.clone()], &camera, &light, &settings).unwrap();
        assert_eq!(a, b);
        let centre = a.get(8, 4).unwrap();
        assert!(
            centre.x > centre.z,
            "the near (red) quad is in front: {centre}"
        );
        let edge = a.get(12, 4).unwrap();
        assert!(
            edge.z > edge.x,
            "the far (blue) quad shows around it: {edge}"
        );
    }
}

#[test]
fn interpolation_is_perspective_correct() {
    // A quad receding in depth; its texture coordinates (u, v) are interpolated.
    let camera: Camera =
        PinholeCamera::at_origin(Film::new(64, 64, (-1.0, 1.0), (-1.0, 1.0)).unwrap(), 1.0)
            .unwrap()
            .into();
    let pipeline = CameraTransforms::new(&camera, DEPTH).unwrap();
    let corners = [
        Vec3::new(-1.0, -1.0, -1.5),
        Vec3::new(1.0, -1.0, -1.5),
        Vec3::new(1.0, 1.0, -8.0),
        Vec3::new(-1.0, 1.0, -8.0),
    ];
    let uv = [
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::X,
        Vec3::new(1.0, 1.0, 0.0),
        Vec3::Y,
    ];
    let vertex = |i: usize| ClipVertex {
        clip: pipeline.to_clip(&Transform::IDENTITY, corners[i]),
        varyings: Varyings {
            world: corners[i],
            normal: Vec3::Z,
            colour: uv[i],
        },
    };
    let mut checked = 0;
    let mut worst_affine = 0.0f32;
    for t in [[0, 1, 2], [0, 2, 3]] {
        let clip = [vertex(t[0]), vertex(t[1]), vertex(t[2])];
        let screen = clip.map(|v| ScreenVertex::from_clip(&pipeline, &v).unwrap());
        rasterize_triangle(&screen, Cull::None, 64, 0..64, |f| {
            // The analytic value: this pixel's ray meets the quad's plane at p.
            let ray = camera.ray(f.x, f.y);
            let (a, e1, e2) = (corners[0], corners[1] - corners[0], corners[3] - corners[0]);
            let n = e1.cross(e2);
            let s = (a - ray.origin()).dot(n) / ray.direction().dot(n);
            let p = ray.origin() + s * ray.direction();
            let (u, v) = (
                (p - a).dot(e1) / e1.length_squared(),
                (p - a).dot(e2) / e2.length_squared(),
            );
            assert!(
                (f.varyings.colour.x - u).abs() < 2e-3,
                "u at ({}, {}): {} vs {u}",
                f.x,
                f.y,
                f.varyings.colour.x
            );
            assert!(
                (f.varyings.colour.y - v).abs() < 2e-3,
                "v at ({}, {}): {} vs {v}",
                f.x,
                f.y,
                f.varyings.colour.y
            );
            assert!((f.varyings.world - p).length() < 1e-2);
            // Screen-space (affine) interpolation would be far off.
            let screen_v =
                (f.y as f32 + 0.5 - screen[0].pixel.y) / (screen[2].pixel.y - screen[0].pixel.y);
            worst_affine = worst_affine.max((screen_v.clamp(0.0, 1.0) - v).abs());
            checked += 1;
        });
    }
    assert!(checked > 500, "{checked} fragments");
    assert!(worst_affine > 0.1, "the test distinguishes: {worst_affine}");
}

#[test]
fn near_plane_clipping() {
    let camera: Camera = PinholeCamera::at_origin(film(), 1.0).unwrap().into();
    let pipeline = CameraTransforms::new(&camera, DEPTH).unwrap();
    let v = |p: Vec3| ClipVertex {
        clip: pipeline.to_clip(&Transform::IDENTITY, p),
        varyings: Varyings {
            world: p,
            ..Default::default()
        },
    };
    let in_front = [Vec3::new(-1.0, -1.0, -3.0), Vec3::new(1.0, -1.0, -3.0)];
    // One vertex behind the eye: a quadrilateral remains, two triangles.
    let one_behind = clip_triangle(&[v(in_front[0]), v(in_front[1]), v(Vec3::new(0.0, 1.0, 2.0))]);
    assert_eq!(one_behind.len(), 2);
    // Two behind: one triangle.
    let two_behind = clip_triangle(&[
        v(in_front[0]),
        v(Vec3::new(1.0, -1.0, 1.0)),
        v(Vec3::new(0.0, 1.0, 2.0)),
    ]);
    assert_eq!(two_behind.len(), 1);
    // All behind: nothing.
    assert!(
        clip_triangle(&[
            v(Vec3::Z),
            v(Vec3::new(1.0, 0.0, 1.0)),
            v(Vec3::new(0.0, 1.0, 3.0))
        ])
        .is_empty()
    );
    for t in one_behind.iter().chain(&two_behind) {
        for c in t {
            assert!(c.clip.w >= DEPTH.near * 0.999, "w = {}", c.clip.w);
            assert!(c.clip.z >= -c.clip.w * 1.0001);
            let s = pipeline.to_screen(c.clip).unwrap();
            assert!(s.is_finite() && s.abs().max_element() < 1e4, "{s}");
        }
    }
    // Through the whole renderer: a big triangle through the camera, no NaN anywhere.
    let mesh = Mesh::new(
        vec![
            Vec3::new(-5.0, -1.0, -4.0),
            Vec3::new(5.0, -1.0, -4.0),
            Vec3::new(0.0, -1.0, 5.0),
        ],
        vec![[0, 1, 2]],
    )
    .unwrap();
    for shading in [Shading::PerVertex, Shading::PerPixel] {
        let settings = RasterSettings {
            depth: DEPTH,
            shading,
            ..RasterSettings::default()
        };
        let image = rasterize(
            &[Model::new(mesh.clone(), Vec3::ONE)],
            &camera,
            &LIGHT,
            &settings,
        )
        .unwrap();
        image.to_srgb8().unwrap();
        // The floor fills the bottom row.
        assert!(image.get(8, 8).unwrap().length() > 0.0);
    }
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
    let mesh = mesh_on_the_floor(Path::new(TORUS_OBJ), 0).unwrap();
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
fn the_reference_is_the_unshadowed_ray_cast_and_its_silhouettes_are_where_objects_change() {
    // One pass gives what two passes gave: the colours of lit_unshadowed, bit for bit,
    // and a silhouette flag wherever one of the 8 neighbours sees another object.
    use render_lessons::raycast::lit_unshadowed;
    use render_lessons::render::render;
    let scene = still_life(Vec3::ZERO).unwrap();
    let camera = still_life_pinhole(96, 54).unwrap();
    let one_pass = reference(&scene, &camera).unwrap();
    let colours = render(&camera, |r| lit_unshadowed(&scene, r)).unwrap();
    assert_eq!(one_pass.image, colours);
    let id = |x: i64, y: i64| {
        let ray = camera.ray(x.clamp(0, 95) as u32, y.clamp(0, 53) as u32);
        scene
            .closest(&ray, Interval::AHEAD)
            .map(|found| found.object)
    };
    let mut flagged = 0;
    for y in 0..54i64 {
        for x in 0..96i64 {
            let edge = (-1..=1).any(|dy| (-1..=1).any(|dx| id(x + dx, y + dy) != id(x, y)));
            assert_eq!(
                one_pass.silhouettes[(y * 96 + x) as usize],
                edge,
                "({x}, {y})"
            );
            flagged += usize::from(edge);
        }
    }
    assert!(flagged > 0 && flagged * 5 < 96 * 54, "{flagged}");
}

#[test]
fn unshadowed_lambert_is_lambert_where_nothing_blocks_the_light() {
    use render_lessons::raycast::{lit, lit_unshadowed};
    use render_lessons::spawn::Offset;
    let scene = still_life(Vec3::ZERO).unwrap();
    let camera = still_life_pinhole(96, 54).unwrap();
    let (mut same, mut shadowed) = (0, 0);
    for y in 0..54 {
        for x in 0..96 {
            let ray = camera.ray(x, y);
            let open = lit_unshadowed(&scene, &ray);
            let traced = lit(&scene, &ray, Offset::Scaled);
            if open == traced {
                same += 1;
            } else {
                // A shadow only ever removes light.
                assert!(traced.cmple(open).all(), "({x}, {y}): {traced} > {open}");
                shadowed += 1;
            }
        }
    }
    assert!(same > 4 * shadowed && shadowed > 0, "{same} {shadowed}");
}

fn floor_and_blocker() -> Vec<Model> {
    vec![
        Model::new(Mesh::floor(Vec3::ZERO, 20.0).unwrap(), Vec3::ONE),
        Model::new(
            Mesh::cuboid(Vec3::new(-1.0, 2.0, -1.0), Vec3::new(1.0, 2.5, 1.0)).unwrap(),
            Vec3::ONE,
        ),
    ]
}

const OVERHEAD: PointLight = PointLight {
    position: Vec3::new(0.0, 8.0, 0.5),
    intensity: Vec3::splat(50.0),
};

fn shadows(bias: f32) -> Shadows {
    Shadows {
        size: 256,
        bias,
        centre: Vec3::ZERO,
        radius: 6.0,
    }
}

#[test]
fn shadow_map_shadows_what_is_under_an_occluder() {
    let map = ShadowMap::build(&floor_and_blocker(), &OVERHEAD, &shadows(1.0)).unwrap();
    // The light is straight above: under the slab is dark, beside it is lit.
    assert!(!map.lit(Vec3::new(0.0, 0.0, 0.0), Vec3::Y));
    assert!(!map.lit(Vec3::new(0.6, 0.0, -0.6), Vec3::Y));
    assert!(map.lit(Vec3::new(3.0, 0.0, 0.0), Vec3::Y));
    assert!(map.lit(Vec3::new(-2.5, 0.0, 3.0), Vec3::Y));
    // The slab's own top is lit, and so is a point outside the map.
    assert!(map.lit(Vec3::new(0.2, 2.5, 0.2), Vec3::Y));
    assert!(map.lit(Vec3::new(50.0, 0.0, 0.0), Vec3::Y));
    // The map recorded the slab's top straight below the light: 8 - 2.5 = 5.5 away.
    let centre = map.size() / 2;
    let d = map.distance(centre, centre).unwrap();
    assert!((d - 5.5).abs() < 0.05, "{d}");
}

#[test]
fn shadow_map_bias_trades_acne_for_detached_shadows() {
    // A floor lit at a slant, nothing above it: every point should be lit.
    let light = PointLight {
        position: Vec3::new(6.0, 3.0, 0.0),
        intensity: Vec3::splat(50.0),
    };
    let floor = [Model::new(
        Mesh::floor(Vec3::ZERO, 20.0).unwrap(),
        Vec3::ONE,
    )];
    let dark = |bias| {
        let map = ShadowMap::build(&floor, &light, &shadows(bias)).unwrap();
        let points = (0..40).flat_map(|i| (0..40).map(move |j| (i, j)));
        points
            .filter(|&(i, j)| {
                let p = Vec3::new(-4.0 + 0.2 * i as f32, 0.0, -4.0 + 0.2 * j as f32);
                !map.lit(p, Vec3::Y)
            })
            .count()
    };
    // No bias: the floor shadows itself in a pattern of stripes (acne).
    assert!(dark(0.0) > 100, "{}", dark(0.0));
    // One texel footprint, scaled by the slope: none.
    assert_eq!(dark(1.0), 0);
}

#[test]
fn shadow_map_bad_input_names_the_parameter() {
    let instances = floor_and_blocker();
    let build = |s: Shadows| ShadowMap::build(&instances, &OVERHEAD, &s).unwrap_err();
    assert_eq!(build(shadows(-1.0)).param(), "shadow bias");
    assert_eq!(build(shadows(f32::NAN)).param(), "shadow bias");
    assert_eq!(
        build(Shadows {
            radius: 0.0,
            ..shadows(1.0)
        })
        .param(),
        "shadow radius"
    );
    assert_eq!(
        build(Shadows {
            size: 0,
            ..shadows(1.0)
        })
        .param(),
        "shadow map size"
    );
    let too_close = Shadows {
        radius: 9.0,
        ..shadows(1.0)
    };
    assert!(build(too_close).to_string().contains("shadow radius"));
}

#[test]
fn shadowed_rasterization_is_the_same_on_any_number_of_threads() {
    let camera: Camera = pinhole().into();
    let settings = RasterSettings {
        depth: DEPTH,
        shadows: Some(shadows(1.0)),
        ..RasterSettings::default()
    };
    let draw = |threads| {
        with_threads(threads, || {
            rasterize(&floor_and_blocker(), &camera, &OVERHEAD, &settings)
        })
    };
    assert_eq!(draw(Some(1)).unwrap(), draw(Some(2)).unwrap());
}

#[test]
fn cuboid_and_floor_face_outwards() {
    let cuboid = Mesh::cuboid(Vec3::new(-1.0, 0.0, 2.0), Vec3::new(0.5, 3.0, 2.5)).unwrap();
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

#[test]
fn images_side_by_side() {
    use render_lessons::framebuffer::Framebuffer;
    let a = Framebuffer::from_fn(3, 2, |_, _| Vec3::X).unwrap();
    let b = Framebuffer::from_fn(2, 1, |_, _| Vec3::Z).unwrap();
    let both = Framebuffer::beside(&[&a, &b], 1).unwrap();
    assert_eq!((both.width(), both.height()), (6, 2));
    assert_eq!(both.get(2, 1), Some(Vec3::X));
    assert_eq!(both.get(3, 0), Some(Vec3::ONE), "the gap is white");
    assert_eq!(both.get(4, 0), Some(Vec3::Z));
    assert_eq!(
        both.get(5, 1),
        Some(Vec3::ONE),
        "below the shorter image: white"
    );
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
    // Exercise 2: film [-1.6, 1.6] x [-0.9, 0.9] at s = 1.5, 16 x 9 pixels, the
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
