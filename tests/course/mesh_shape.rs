//! A mesh as one shape (issue 32): its own tree over its triangles answers what a
//! list of the same triangles answers, one object each (the same `t`, the same
//! triangle, ties included), and its hit carries the shading normal blended from
//! the vertex normals.
//!
//! No timing here: the tree's speed is lesson 11's (`benches/bvh.rs`).

use crate::bvh::random_rays;
use crate::common;
use common::Rng;

use glam::{DVec3, Vec3};
use render_lessons::mesh::{Mesh, Model};
use render_lessons::ray::{Interval, Ray};
use render_lessons::scene::{BvhScene, Intersect, Object, Scene};
use render_lessons::scenes::{TEAPOT_OBJ, asset_path};
use render_lessons::shapes::{PreparedRay, Shape, TriangleMesh};
use render_lessons::transform::Transform;

/// The teapot (2048 quads, some with two equal corners at the lid and the base)
/// turned, stretched and moved: the model transform the shape bakes in.
fn teapot() -> Model {
    let mesh = Mesh::from_obj(asset_path(TEAPOT_OBJ)).unwrap().mesh;
    let place = Transform::rotation_y(0.7)
        .then(Transform::scale(0.5, 0.3, 0.4))
        .then(Transform::translation(0.3, -0.2, 0.1));
    Model::new(mesh, Vec3::ONE).placed(place)
}

/// Rays at random, and rays aimed exactly at the mesh's vertices and at the
/// midpoints of its edges, where two or more triangles meet at the same `t`.
fn rays(rng: &mut Rng, mesh: &TriangleMesh) -> Vec<Ray> {
    let mut rays = random_rays(rng, 4000, 3.0, 1.0);
    for i in (0..mesh.len()).step_by(7) {
        let [a, b, c] = mesh.triangle(i).vertices();
        for target in [a, 0.5 * (a + b), 0.5 * (b + c)] {
            let o = rng.point(3.0);
            rays.extend(Ray::new(o, target - o));
        }
    }
    rays
}

/// On every ray the mesh's own search and the list of its triangles find the same
/// crossing: the same `t` bit for bit and the same triangle (the first listed on a
/// tie), and the hit record has the triangle's point, normal and side.
#[test]
#[ignore = "over 1 s in a debug build: the release suite runs it (.ci/run: `cargo test --release --test course --test lessons -- --ignored`)"]
fn mesh_shape_hits_are_the_triangle_lists() {
    let mut rng = Rng::seeded(32);
    for model in [
        Model::new(Mesh::uv_sphere(Vec3::ZERO, 1.0, 48, 24).unwrap(), Vec3::ONE),
        teapot(),
    ] {
        let mesh = model.shape().unwrap();
        let list = Scene::new(model.objects().unwrap(), Vec3::ZERO).unwrap();
        assert_eq!(mesh.len(), list.objects().len());
        let shape = Shape::from(mesh.clone());
        let (mut hits, mut ties) = (0, 0);
        for (k, ray) in rays(&mut rng, &mesh).iter().enumerate() {
            let expected = list.closest(ray, Interval::AHEAD);
            let found = mesh.closest(&PreparedRay::new(ray), Interval::AHEAD);
            let (Some(e), Some((crossing, triangle))) = (expected, found) else {
                assert!(expected.is_none() && found.is_none(), "ray {k}: {ray:?}");
                continue;
            };
            hits += 1;
            assert_eq!(crossing.t.to_bits(), e.hit.t.to_bits(), "ray {k}");
            assert_eq!(triangle, e.object, "ray {k}: {ray:?}");
            let hit = shape.hit(ray, Interval::AHEAD).unwrap();
            assert_eq!(
                (hit.t, hit.point, hit.normal, hit.front_face, hit.error),
                (
                    e.hit.t,
                    e.hit.point,
                    e.hit.normal,
                    e.hit.front_face,
                    e.hit.error
                ),
                "ray {k}"
            );
            // A tie: another triangle crossed at the very same t.
            let at_t = Interval::new(e.hit.t.next_down(), e.hit.t.next_up());
            let others = list.objects().iter().enumerate().filter(|(j, o)| {
                *j != e.object && o.shape.hit(ray, at_t).is_some_and(|h| h.t == e.hit.t)
            });
            ties += usize::from(others.count() > 0);
        }
        assert!(hits > 1000, "{hits} hits");
        assert!(ties > 10, "{ties} ties");
    }
}

/// A scene holding the teapot (4032 triangles) as one object and a ball answers
/// through its own tree (`BvhScene`) what its list answers, the whole hit record
/// bit for bit.
#[test]
fn a_scene_of_a_mesh_shape_through_a_tree_is_its_list() {
    let mut rng = Rng::seeded(33);
    let ball = render_lessons::shapes::Sphere::new(Vec3::new(1.0, 0.0, 0.0), 0.4);
    let teapot = teapot().object().unwrap();
    assert!(matches!(&teapot.shape, Shape::Mesh(m) if m.len() == 4032));
    let objects = vec![teapot, Object::diffuse(ball.unwrap(), Vec3::ONE)];
    let list = Scene::new(objects, Vec3::ZERO).unwrap();
    let tree = BvhScene::new(list.clone());
    let mut hits = 0;
    for ray in random_rays(&mut rng, 3000, 3.0, 1.0) {
        let expected = list.closest(&ray, Interval::AHEAD);
        assert_eq!(tree.closest(&ray, Interval::AHEAD), expected, "{ray:?}");
        hits += usize::from(expected.is_some());
    }
    assert!(hits > 500, "{hits}");
}

/// The shading normal of a hit is the blend of its triangle's three vertex normals
/// by the hit point's barycentric coordinates, normalised: computed here in f64 from
/// the point itself (the areas of the three triangles it cuts its triangle into) and
/// the model's normals taken to the world by the inverse transpose.
#[test]
fn a_hit_shades_with_the_blend_of_its_vertex_normals() {
    let model = teapot();
    let mesh = model.shape().unwrap();
    let inverse_transpose = model.model.inverse().unwrap().matrix().transpose();
    let world_normal = |i: u32| {
        let n = model.mesh.normals[i as usize];
        inverse_transpose
            .transform_vector3(n)
            .normalize()
            .as_dvec3()
    };
    // The mesh's triangles are the model's with an area, in order.
    let kept: Vec<[u32; 3]> = model
        .mesh
        .triangles
        .iter()
        .copied()
        .filter(|t| {
            let [a, b, c] =
                t.map(|i| model.model.point(model.mesh.positions[i as usize]));
            render_lessons::shapes::Triangle::new(a, b, c).is_ok()
        })
        .collect();
    assert_eq!(kept.len(), mesh.len());
    let mut rng = Rng::seeded(34);
    let (mut checked, mut smooth) = (0, 0);
    for ray in random_rays(&mut rng, 3000, 3.0, 0.5) {
        let Some((_, i)) = mesh.closest(&PreparedRay::new(&ray), Interval::AHEAD)
        else {
            continue;
        };
        let hit = mesh.hit(&ray, Interval::AHEAD).unwrap();
        let [a, b, c] = mesh.triangle(i).vertices().map(|v| v.as_dvec3());
        let p = hit.point.as_dvec3();
        let area = |u: DVec3, v: DVec3, w: DVec3| (v - u).cross(w - u).length();
        let whole = area(a, b, c);
        let weights = [area(p, b, c), area(a, p, c), area(a, b, p)].map(|x| x / whole);
        let [n0, n1, n2] = kept[i].map(world_normal);
        let blend = (weights[0] * n0 + weights[1] * n1 + weights[2] * n2).normalize();
        let blend = if blend.dot(hit.normal.as_dvec3()) < 0.0 {
            -blend
        } else {
            blend
        };
        let error = (hit.shading.as_dvec3() - blend).length();
        assert!(error < 2e-5, "ray {ray:?}: {} against {blend}", hit.shading);
        assert!((hit.shading.length() - 1.0).abs() < 1e-6);
        checked += 1;
        smooth += usize::from(hit.shading.dot(hit.normal) < 0.9999);
    }
    assert!(checked > 500, "{checked}");
    // Most hits are shaded away from their facet's own normal.
    assert!(smooth > checked / 2, "{smooth} of {checked}");
}

/// A mesh without vertex normals shades with each triangle's own normal, bit for
/// bit, as the triangle primitive does.
#[test]
fn a_mesh_without_normals_shades_flat() {
    let sphere = Mesh::uv_sphere(Vec3::ZERO, 1.0, 16, 8).unwrap();
    let mesh = TriangleMesh::new(
        sphere.positions.clone(),
        &sphere.triangles,
        Vec::new(),
        Vec::new(),
    )
    .unwrap();
    let mut rng = Rng::seeded(35);
    let mut hits = 0;
    for ray in random_rays(&mut rng, 500, 3.0, 0.5) {
        if let Some(hit) = mesh.hit(&ray, Interval::AHEAD) {
            assert_eq!(hit.shading, hit.normal);
            hits += 1;
        }
    }
    assert!(hits > 100, "{hits}");
}

/// The crossings of a closed convex mesh are its entry and its exit, those of the
/// list's nearest and farthest triangle; a ray that misses has none.
#[test]
fn a_convex_mesh_is_crossed_twice() {
    let sphere = Mesh::uv_sphere(Vec3::ZERO, 1.0, 32, 16).unwrap();
    let model = Model::new(sphere, Vec3::ONE);
    let shape = Shape::from(model.shape().unwrap());
    let list = model.objects().unwrap();
    let mut rng = Rng::seeded(36);
    let mut crossed = 0;
    for ray in random_rays(&mut rng, 500, 3.0, 0.5) {
        let ts: Vec<f32> = list
            .iter()
            .filter_map(|o| o.shape.hit(&ray, Interval::EVERYWHERE))
            .map(|h| h.t)
            .collect();
        let expected = match ts.iter().copied().reduce(f32::min) {
            Some(first) => vec![first, ts.iter().copied().fold(first, f32::max)],
            None => Vec::new(),
        };
        assert_eq!(shape.crossings(&ray).as_slice(), expected, "{ray:?}");
        crossed += usize::from(!expected.is_empty());
    }
    assert!(crossed > 100, "{crossed}");
}

/// Bad input is named: normals of the wrong count, a NaN coordinate, a corner past
/// the last vertex, a mesh of triangles with no area.
#[test]
fn a_mesh_shape_refuses_bad_input() {
    let p = vec![Vec3::ZERO, Vec3::X, Vec3::Y];
    let param = |r: render_lessons::Result<TriangleMesh>| match r.unwrap_err() {
        render_lessons::Error::Value { param, .. } => param,
        e => panic!("{e}"),
    };
    let t = [[0, 1, 2]];
    let bad = |p: Vec<Vec3>, t: &[[u32; 3]], n: Vec<Vec3>| {
        param(TriangleMesh::new(p, t, n, Vec::new()))
    };
    assert_eq!(bad(p.clone(), &t, vec![Vec3::Z]), "normals");
    assert_eq!(bad(p.clone(), &t, vec![Vec3::NAN; 3]), "normal");
    assert_eq!(bad(p.clone(), &[[0, 1, 3]], Vec::new()), "triangle");
    assert_eq!(bad(vec![Vec3::ZERO; 3], &t, Vec::new()), "mesh");
    assert_eq!(
        bad(vec![Vec3::ZERO, Vec3::X, Vec3::INFINITY], &t, Vec::new()),
        "position"
    );
}
