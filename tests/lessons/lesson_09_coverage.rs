//! Lesson 09, clipping and coverage (chapters 09_2 and 09_3): triangles clipped at the
//! near plane, shared edges covered exactly once, the z-buffer's result independent
//! of the drawing order, and perspective-correct interpolation.

use crate::lesson_09_rasterization::{DEPTH, LIGHT, film};

use std::collections::HashMap;

use glam::{Vec2, Vec3};
use render_lessons::camera::{Camera, Film, PinholeCamera};
use render_lessons::mesh::{Mesh, Model};
use render_lessons::raster::{
    CameraTransforms, ClipVertex, Cull, RasterSettings, ScreenVertex, Shading,
    Varyings, clip_triangle, rasterize, rasterize_triangle,
};
use render_lessons::scenes::squares::{Squares, squares};
use render_lessons::transform::Transform;

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
        let t =
            [centre, corners[i], corners[(i + 1) % corners.len()]].map(screen_vertex);
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
                    Some(false) => {
                        assert_eq!(covered, 0, "outside drawn at ({x}, {y})")
                    }
                    None => {}
                }
            }
        }
    }
    // A square split along its diagonal through pixel centres: area exactly once.
    let [a, b, c, d] = [(2.5, 2.5), (12.5, 2.5), (12.5, 12.5), (2.5, 12.5)]
        .map(|(x, y)| Vec2::new(x, y));
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
        let a = rasterize(&[near.clone(), far.clone()], &camera, &light, &settings)
            .unwrap();
        let b = rasterize(&[far.clone(), near.clone()], &camera, &light, &settings)
            .unwrap();
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
    let camera: Camera = PinholeCamera::at_origin(
        Film::new(64, 64, (-1.0, 1.0), (-1.0, 1.0)).unwrap(),
        1.0,
    )
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
            ..Default::default()
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
            let (a, e1, e2) =
                (corners[0], corners[1] - corners[0], corners[3] - corners[0]);
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
            let screen_v = (f.y as f32 + 0.5 - screen[0].pixel.y)
                / (screen[2].pixel.y - screen[0].pixel.y);
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
    let one_behind =
        clip_triangle(&[v(in_front[0]), v(in_front[1]), v(Vec3::new(0.0, 1.0, 2.0))]);
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
