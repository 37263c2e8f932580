//! Lesson 11: the BVH gives the same answers as the plain list, only faster.
//!
//! Every test compares the tree with [`Scene`]'s brute-force loop on the same
//! objects: the same closest hit (the whole `Hit`, bit for bit, and the same
//! object, ties included) and the same `occluded`. No timing here: speed is
//! measured by `cargo bench -p render-benches --bench bvh`.

use crate::common;
use common::Rng;
use std::collections::BTreeSet;

use glam::{Mat4, Vec3};
use render_lessons::bvh::build::Strategy;
use render_lessons::bvh::{Bvh, BvhScene, Child, MAX_DEPTH, Node};
use render_lessons::mesh::Mesh;
use render_lessons::ray::{Interval, Ray};
use render_lessons::scene::{Intersect, Object, PointLight, Scene};
use render_lessons::shapes::{Aabb, Cylinder, Instance, Plane, Quadric, Shape, Sphere, Triangle};
use render_lessons::transform::Transform;

fn object(shape: Shape) -> Object {
    Object::diffuse(shape, Vec3::splat(0.5))
}

fn scene(objects: Vec<Object>) -> Scene {
    let light = PointLight {
        position: Vec3::new(0.0, 10.0, 0.0),
        intensity: Vec3::ONE,
    };
    Scene::new(objects, Vec3::ZERO)
        .and_then(|s| s.with_light(light))
        .unwrap()
}

fn mesh_objects(mesh: &Mesh) -> Vec<Object> {
    mesh.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            object(Shape::Triangle(Triangle::new(a, b, c).unwrap()))
        })
        .collect()
}

/// Rays from random points in a cube of half-size `spread`, half of them aimed at
/// random points of a cube of half-size `target` (so that many hit), half in random
/// directions.
fn random_rays(rng: &mut Rng, n: usize, spread: f32, target: f32) -> Vec<Ray> {
    (0..n)
        .filter_map(|k| {
            let o = rng.point(spread);
            let d = if k % 2 == 0 {
                rng.point(target) - o
            } else {
                rng.point(1.0)
            };
            Ray::new(o, d).ok()
        })
        .collect()
}

/// Checks that the tree and the list agree on every ray; returns how many rays hit.
fn assert_same_answers(scene: &Scene, rays: &[Ray]) -> usize {
    let bvh = BvhScene::new(scene.clone());
    let mut hits = 0;
    for (k, ray) in rays.iter().enumerate() {
        let list = scene.closest(ray, Interval::AHEAD);
        let tree = bvh.closest(ray, Interval::AHEAD);
        match (list, tree) {
            (None, None) => {}
            (Some(a), Some(b)) => {
                hits += 1;
                assert_eq!(a.hit, b.hit, "ray {k}: {ray:?}");
                assert_eq!(a.object, b.object, "ray {k}: {ray:?}");
            }
            (a, b) => panic!("ray {k}: {ray:?}: list {a:?}, tree {b:?}"),
        }
        assert_eq!(
            bvh.closest_object(ray, Interval::AHEAD),
            list.map(|found| found.object),
            "ray {k}: {ray:?}"
        );
        // Shadow-ray questions over a few ranges, including one that ends just
        // before the closest hit.
        let t_hit = list.map_or(10.0, |found| found.hit.t);
        for (t_min, t_max) in [
            (0.0, f32::INFINITY),
            (1e-3, t_hit * 0.999),
            (0.0, t_hit * 1.001),
            (t_hit * 0.5, 2.0 * t_hit),
        ] {
            let range = Interval::new(t_min, t_max);
            assert_eq!(
                scene.occluded(ray, range),
                bvh.occluded(ray, range),
                "ray {k} occluded in ({t_min}, {t_max}): {ray:?}"
            );
        }
    }
    hits
}

fn random_soup(rng: &mut Rng, n: usize) -> Vec<Object> {
    (0..n)
        .map(|k| {
            let c = rng.point(10.0);
            let shape = match k % 5 {
                0 => Shape::Sphere(Sphere::new(c, rng.range(0.05, 1.0)).unwrap()),
                1 => {
                    let half = Vec3::new(rng.range(0.0, 1.0), rng.range(0.0, 1.0), 0.0);
                    Shape::Aabb(Aabb::new(c - half, c + half).unwrap())
                }
                2 => {
                    let half = rng.point(1.0).abs();
                    Shape::Aabb(Aabb::new(c - half, c + half).unwrap())
                }
                3 => loop {
                    let (a, b) = (c + rng.point(1.0), c + rng.point(1.0));
                    if let Ok(t) = Triangle::new(c, a, b) {
                        break Shape::Triangle(t);
                    }
                },
                _ => {
                    let inner = if k % 2 == 0 {
                        Shape::Sphere(Sphere::new(Vec3::ZERO, 0.5).unwrap())
                    } else {
                        Shape::Aabb(Aabb::new(Vec3::splat(-0.5), Vec3::splat(0.5)).unwrap())
                    };
                    let m = Transform::scale(rng.range(0.2, 2.0), rng.range(0.2, 2.0), 1.0)
                        .then(Transform::rotation_y(rng.range(0.0, 6.0)))
                        .then(Transform::rotation_x(rng.range(0.0, 6.0)))
                        .then(Transform::translation(c.x, c.y, c.z));
                    Shape::Instance(Box::new(Instance::new(inner, m).unwrap()))
                }
            };
            object(shape)
        })
        .collect()
}

#[test]
fn same_hits_as_the_list_on_a_1k_triangle_sphere() {
    let mesh = Mesh::uv_sphere(Vec3::new(0.3, -0.2, 0.1), 2.0, 23, 23).unwrap();
    let scene = scene(mesh_objects(&mesh));
    assert_eq!(scene.objects().len(), 1012);
    let rays = random_rays(&mut Rng::seeded(1), 4000, 6.0, 2.5);
    let hits = assert_same_answers(&scene, &rays);
    assert!(hits > 1000, "{hits} hits");
}

/// Rays parallel to an axis (1/d infinite on two axes) starting exactly in the
/// planes of vertices, so that node boxes' faces hold the origin: the slab test's
/// 0 * inf = NaN case, which the traversal's careful path must treat as the list does.
#[test]
fn same_hits_as_the_list_for_axis_parallel_rays_in_box_face_planes() {
    let mesh = Mesh::uv_sphere(Vec3::ZERO, 1.0, 12, 12).unwrap();
    let scene = scene(mesh_objects(&mesh));
    let mut rays = Vec::new();
    for p in mesh.positions.iter().step_by(3) {
        for (o, d) in [
            (Vec3::new(p.x, p.y, 5.0), -Vec3::Z),
            (Vec3::new(-5.0, p.y, p.z), Vec3::X),
            (Vec3::new(p.x, 5.0, p.z), -Vec3::Y),
        ] {
            rays.push(Ray::new(o, d).unwrap());
        }
    }
    let hits = assert_same_answers(&scene, &rays);
    assert!(hits > rays.len() / 2, "{hits} of {} hit", rays.len());
}

#[test]
fn a_ray_along_any_face_of_a_box_hits_in_the_tree_as_in_the_list() {
    // STABILITY S8 for both signs of a zero direction component: the origin in one of
    // the six face planes of the box [-1, 1]^3, the ray running over the face.
    let cube = Aabb::new(Vec3::splat(-1.0), Vec3::splat(1.0)).unwrap();
    let scene = scene(vec![object(Shape::Aabb(cube))]);
    let bvh = BvhScene::new(scene.clone());
    for zero in [0.0f32, -0.0] {
        for axis in 0..3 {
            for side in [-1.0, 1.0] {
                let (along, across) = ((axis + 1) % 3, (axis + 2) % 3);
                let (mut o, mut d) = (Vec3::ZERO, Vec3::ZERO);
                (o[axis], o[along], d[axis], d[across], d[along]) = (side, -5.0, zero, zero, 1.0);
                let r = Ray::new(o, d).unwrap();
                let list = scene.closest(&r, Interval::AHEAD).map(|f| f.hit.t);
                let tree = bvh.closest(&r, Interval::AHEAD).map(|f| f.hit.t);
                assert_eq!(list, Some(4.0), "list, o {o}, d {d:?}");
                assert_eq!(tree, Some(4.0), "tree, o {o}, d {d:?}");
            }
        }
    }
}

#[test]
fn same_hits_as_the_list_on_a_random_soup() {
    let mut rng = Rng::seeded(2);
    let scene = scene(random_soup(&mut rng, 1000));
    let rays = random_rays(&mut rng, 4000, 12.0, 10.0);
    let hits = assert_same_answers(&scene, &rays);
    assert!(hits > 1500, "{hits} hits");
}

#[test]
fn same_hits_as_the_list_with_a_plane_and_a_quadric() {
    let mut rng = Rng::seeded(3);
    let mut objects = random_soup(&mut rng, 300);
    objects.insert(
        0,
        object(Shape::Plane(
            Plane::new(Vec3::new(0.0, -5.0, 0.0), Vec3::Y).unwrap(),
        )),
    );
    // A cylinder x^2 + z^2 = 4 about the y axis: unbounded.
    let cylinder = Mat4::from_diagonal(glam::Vec4::new(1.0, 0.0, 1.0, -4.0));
    objects.push(object(Shape::Quadric(Quadric::new(cylinder).unwrap())));
    let scene = scene(objects);
    let bvh = Bvh::build(scene.objects());
    assert_eq!(bvh.unbounded(), &[0, 301]);
    let rays = random_rays(&mut rng, 4000, 12.0, 10.0);
    assert_same_answers(&scene, &rays);
}

/// The closed bumpy sphere of STABILITY S4/S5, `n` x `n` segments: the same mesh
/// lesson 11's chart 2 measures.
fn bumpy_sphere(n: usize) -> (Vec<Vec3>, Vec<[usize; 3]>) {
    render_lessons::course::measure::triangle::bumpy_sphere(n, n)
}

#[test]
fn watertight_through_the_tree_no_leaks_at_vertices_or_edges() {
    for n in [16, 32] {
        let (vertices, indices) = bumpy_sphere(n);
        let objects = indices
            .iter()
            .map(|&[a, b, c]| {
                object(Shape::Triangle(
                    Triangle::new(vertices[a], vertices[b], vertices[c]).unwrap(),
                ))
            })
            .collect();
        let scene = scene(objects);
        let bvh = BvhScene::new(scene.clone());
        let edges: BTreeSet<(usize, usize)> = indices
            .iter()
            .flat_map(|t| (0..3).map(move |k| (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]))))
            .collect();
        let targets: Vec<Vec3> = vertices
            .iter()
            .copied()
            .chain(
                edges
                    .iter()
                    .map(|&(a, b)| (vertices[a] + vertices[b]) * 0.5),
            )
            .collect();
        let rays: Vec<Ray> = targets
            .iter()
            .map(|&t| Ray::new(Vec3::ZERO, t).unwrap())
            .collect();
        let leaks = rays
            .iter()
            .filter(|r| bvh.closest(r, Interval::AHEAD).is_none())
            .count();
        let list_leaks = rays
            .iter()
            .filter(|r| scene.closest(r, Interval::AHEAD).is_none())
            .count();
        eprintln!(
            "{n}x{n} bumpy sphere, {} rays at vertices and edge midpoints: tree leaks {leaks}, list {list_leaks}",
            rays.len()
        );
        assert_eq!(leaks, 0);
        assert_eq!(list_leaks, 0);
        assert_same_answers(&scene, &rays);
    }
}

#[test]
fn degenerate_builds() {
    let mut rng = Rng::seeded(4);
    let rays = random_rays(&mut rng, 500, 3.0, 1.0);

    // No objects: no nodes, nothing hit.
    let empty = scene(Vec::new());
    let bvh = Bvh::build(empty.objects());
    assert!(bvh.root().is_none() && bvh.nodes().is_empty() && bvh.unbounded().is_empty());
    assert_eq!(bvh.sah_cost(), None);
    assert_same_answers(&empty, &rays);

    // One object: one leaf.
    let one = scene(vec![object(Shape::Sphere(
        Sphere::new(Vec3::ZERO, 0.5).unwrap(),
    ))]);
    let bvh = Bvh::build(one.objects());
    let leaf = Child::Leaf { first: 0, count: 1 };
    assert!(matches!(bvh.root(), Some((_, child)) if child == leaf));
    assert_eq!((bvh.nodes().len(), bvh.node_count()), (0, 1));
    assert_eq!(bvh.primitives(), &[0]);
    assert_same_answers(&one, &rays);

    // 1000 identical triangles: all centroids equal, one leaf; every hit is a
    // thousand-way tie, and the tree returns the first object as the list does.
    let tri = Triangle::new(
        Vec3::new(-1.0, -1.0, 0.0),
        Vec3::new(1.0, -1.0, 0.0),
        Vec3::Y,
    )
    .unwrap();
    let same = scene(vec![object(Shape::Triangle(tri)); 1000]);
    let bvh = BvhScene::new(same.clone());
    let leaf = Child::Leaf {
        first: 0,
        count: 1000,
    };
    assert!(matches!(bvh.bvh().root(), Some((_, child)) if child == leaf));
    let r = Ray::new(Vec3::new(0.0, 0.0, 5.0), -Vec3::Z).unwrap();
    assert_eq!(bvh.closest(&r, Interval::AHEAD).unwrap().object, 0);
    assert_same_answers(&same, &rays);

    // Only planes: no tree at all, everything in the unbounded list.
    let planes = scene(
        (0..5)
            .map(|k| {
                let n = Vec3::new(k as f32 - 2.0, 1.0, 0.5);
                object(Shape::Plane(Plane::new(n * 0.3, n).unwrap()))
            })
            .collect(),
    );
    let bvh = Bvh::build(planes.objects());
    assert!(bvh.root().is_none() && bvh.nodes().is_empty());
    assert_eq!(bvh.unbounded(), &[0, 1, 2, 3, 4]);
    assert_same_answers(&planes, &rays);

    // Zero-size and zero-thickness boxes: points on a line (a root box of no area,
    // where the SAH falls back to the median) and flat squares in one plane.
    let points = scene(
        (0..100)
            .map(|k| {
                let p = Vec3::new(k as f32 * 0.01 - 0.5, 0.0, 0.0);
                object(Shape::Aabb(Aabb::new(p, p).unwrap()))
            })
            .collect(),
    );
    assert_invariants(&points, &Bvh::build(points.objects()));
    assert_same_answers(&points, &rays);
    let flat = scene(
        (0..100)
            .map(|k| {
                let c = Vec3::new(
                    (k % 10) as f32 * 0.2 - 1.0,
                    (k / 10) as f32 * 0.2 - 1.0,
                    0.0,
                );
                object(Shape::Aabb(
                    Aabb::new(c, c + Vec3::new(0.15, 0.15, 0.0)).unwrap(),
                ))
            })
            .collect(),
    );
    assert_invariants(&flat, &Bvh::build(flat.objects()));
    assert_same_answers(&flat, &rays);
}

#[test]
fn a_pathological_distribution_stays_within_the_stack() {
    // Boxes at x = 2^k, k = -120..=126, each 2% of its distance wide: the bins of
    // each split put all but the farthest few boxes into the first bin, so each SAH
    // split peels off only a few and the tree gets about 60 levels deep (61 when
    // written), the deepest this test could make in f32's range. The traversal's
    // fixed stack must still be enough, and the answers the list's.
    let objects: Vec<Object> = (-120..=126)
        .map(|k| {
            let c = Vec3::new(2f32.powi(k), 0.0, 0.0);
            let half = Vec3::splat(0.01 * c.x);
            object(Shape::Aabb(Aabb::new(c - half, c + half).unwrap()))
        })
        .collect();
    let scene = scene(objects);
    let bvh = Bvh::build(scene.objects());
    let depth = assert_invariants(&scene, &bvh);
    eprintln!("247 boxes at x = 2^k: depth {depth}");
    assert!(depth <= MAX_DEPTH);
    let mut rng = Rng::seeded(5);
    let rays: Vec<Ray> = (0..500)
        .map(|_| {
            let o = Vec3::new(-2.0, 0.0, 0.0) + rng.point(0.3) * 1e-30;
            Ray::new(o, Vec3::X + rng.point(1e-3)).unwrap()
        })
        .collect();
    assert_same_answers(&scene, &rays);
}

/// Every primitive in exactly one leaf, each child's box inside its parent's, every
/// node after its parent and reachable once, each primitive's box inside its leaf's,
/// no deeper than [`MAX_DEPTH`], 64 bytes (one cache line) a node; returns the depth.
fn assert_invariants(scene: &Scene, bvh: &Bvh) -> usize {
    let nodes = bvh.nodes();
    assert_eq!(std::mem::size_of::<Node>(), 64);
    assert_eq!(std::mem::align_of::<Node>(), 64);
    let bounded: Vec<usize> = (0..scene.objects().len())
        .filter(|&i| scene.objects()[i].shape.bounds().is_some())
        .collect();
    let mut seen = vec![0usize; scene.objects().len()];
    let mut max_depth = 0;
    // (the child's box, the child, its parent node, its depth)
    let mut stack: Vec<_> = bvh
        .root()
        .map(|(b, c)| (b, c, None, 1))
        .into_iter()
        .collect();
    let mut visited = 0;
    while let Some((bounds, child, parent, depth)) = stack.pop() {
        visited += 1;
        max_depth = max_depth.max(depth);
        match child {
            Child::Leaf { first, count } => {
                assert!(count > 0);
                for &p in &bvh.primitives()[first..first + count] {
                    seen[p] += 1;
                    let b = scene.objects()[p].shape.bounds().unwrap();
                    assert!(bounds.contains(&b), "primitive {p} outside its leaf");
                }
            }
            Child::Node(i) => {
                assert!(parent.is_none_or(|p| i > p), "node {i} after its parent");
                for (b, c) in [0, 1].map(|k| nodes[i].child(k)) {
                    assert!(bounds.contains(&b), "a child of node {i} outside it");
                    stack.push((b, c, Some(i), depth + 1));
                }
            }
        }
    }
    assert_eq!(visited, bvh.node_count(), "every node reachable once");
    for (i, &count) in seen.iter().enumerate() {
        let expected = usize::from(bounded.contains(&i));
        assert_eq!(count, expected, "object {i} in {count} leaves");
    }
    assert_eq!(bvh.primitives().len(), bounded.len());
    assert!(max_depth <= MAX_DEPTH, "depth {max_depth}");
    max_depth
}

#[test]
fn structural_invariants_and_sah_beats_the_median_on_100k_triangles() {
    let mut rng = Rng::seeded(6);
    let soup = scene(random_soup(&mut rng, 2000));
    assert_invariants(&soup, &Bvh::build(soup.objects()));
    assert_invariants(&soup, &Bvh::build_with(soup.objects(), Strategy::Median));

    // 2 x 224 x 223 = 99 904 triangles.
    let mesh = Mesh::uv_sphere(Vec3::ZERO, 1.0, 224, 224).unwrap();
    let scene = scene(mesh_objects(&mesh));
    let sah = Bvh::build(scene.objects());
    let median = Bvh::build_with(scene.objects(), Strategy::Median);
    let depth = assert_invariants(&scene, &sah);
    assert_invariants(&scene, &median);
    let (c_sah, c_median) = (sah.sah_cost().unwrap(), median.sah_cost().unwrap());
    eprintln!(
        "{} triangles: SAH tree {} nodes, depth {depth}, cost {c_sah:.2}; median tree {} nodes, cost {c_median:.2}",
        scene.objects().len(),
        sah.node_count(),
        median.node_count()
    );
    assert!(c_sah < c_median, "SAH {c_sah} vs median {c_median}");
}

/// 4 samples per pixel of the default path tracer, each pixel's bits.
fn path_traced(scene: &impl Intersect, camera: &render_lessons::camera::Camera) -> Vec<[u32; 3]> {
    use render_lessons::pathtrace::{Accumulator, PixelSampling, Settings};
    let settings = Settings::default();
    let image = Accumulator::new(camera, 7)
        .render_pass(scene, camera, &settings, PixelSampling::Independent, 4)
        .unwrap();
    (0..image.height())
        .flat_map(|y| (0..image.width()).map(move |x| (x, y)))
        .map(|(x, y)| image.get(x, y).unwrap().to_array().map(f32::to_bits))
        .collect()
}

/// Lesson 10's path tracer renders a mesh through lesson 11's tree: the torus of
/// lesson 09 (1024 triangles) on a floor under a spherical light, path traced with
/// the default settings (MIS, roulette, error-bound offsets) through the list and
/// through the tree. The tree answers every query as the list does, so the two
/// images are the same, bit for bit.
#[test]
fn the_path_tracer_renders_a_mesh_through_the_tree_as_through_the_list() {
    use render_lessons::material::Material;
    use render_lessons::scenes::TORUS_OBJ;
    use render_lessons::scenes::path_tracing::look_camera;

    let mut objects = Mesh::from_obj(std::path::Path::new(TORUS_OBJ))
        .unwrap()
        .mesh
        .objects(Vec3::new(0.7, 0.5, 0.3))
        .unwrap();
    let (torus_triangles, floor_y) = (objects.len(), -1.0);
    objects.push(Object::diffuse(
        Shape::Plane(Plane::new(Vec3::new(0.0, floor_y, 0.0), Vec3::Y).unwrap()),
        Vec3::splat(0.6),
    ));
    objects.push(Object::emitting(
        Shape::Sphere(Sphere::new(Vec3::new(2.0, 4.0, 3.0), 1.0).unwrap()),
        Material::BLACK,
        Vec3::splat(8.0),
    ));
    let list = Scene::new(objects, Vec3::splat(0.1)).unwrap();
    let tree = BvhScene::new(list.clone());
    assert_eq!(torus_triangles, 1024);
    assert!(tree.bvh().node_count() > 100, "a real tree over the mesh");

    let camera = look_camera(
        32,
        24,
        Vec3::new(0.0, 1.5, 4.0),
        Vec3::new(0.0, -0.4, -1.0),
        0.6,
    )
    .unwrap();
    let through_list = path_traced(&list, &camera);
    assert_eq!(path_traced(&tree, &camera), through_list);
    // Not a blank image: most pixels see the torus or the lit floor, not the sky.
    let sky = Vec3::splat(0.1).to_array().map(f32::to_bits);
    let seen = through_list.iter().filter(|&&p| p != sky).count();
    assert!(seen > through_list.len() / 2, "{seen} pixels see the scene");
}

/// Lesson 10's `--scene teapot`: the Cornell box with the Newell teapot (4032
/// triangles) in place of the mirror ball. The lesson draws it through the tree
/// (`ListOrTree`); here a small render through the list and through the tree are the
/// same, bit for bit.
#[test]
fn lesson_10_renders_the_teapot_in_the_cornell_box_through_the_tree() {
    use render_lessons::bvh::ListOrTree;
    use render_lessons::scenes::path_tracing::{SceneName, Staged};

    let Staged {
        scene: list,
        camera,
    } = SceneName::Teapot.build(16, 12).unwrap();
    assert_eq!(list.objects().len(), 8 - 1 + 4032);
    let tree = BvhScene::new(list.clone());
    assert!(
        tree.bvh().node_count() > 1000,
        "a real tree over the teapot"
    );
    assert_eq!(path_traced(&tree, &camera), path_traced(&list, &camera));
    // The lesson's own choice at its default size: the tree.
    let rays = 160 * 120 * 64;
    assert!(matches!(ListOrTree::new(list, rays), ListOrTree::Tree(_)));
}

#[test]
fn same_hits_as_the_list_with_capped_cylinders() {
    // Capped cylinders are bounded: in the tree, as such and placed by instances,
    // among the random soup; the tree finds what the list finds.
    let mut rng = Rng::seeded(4);
    let mut objects = random_soup(&mut rng, 300);
    for k in 0..200 {
        let c = rng.point(10.0);
        let can = Cylinder::new(
            rng.range(0.1, 1.0),
            -rng.range(0.0, 1.0),
            rng.range(0.1, 1.5),
        );
        let can = Shape::from(can.unwrap());
        let m = if k % 2 == 0 {
            Transform::translation(c.x, c.y, c.z)
        } else {
            Transform::rotation_x(rng.range(0.0, 6.0))
                .then(Transform::rotation_z(rng.range(0.0, 6.0)))
                .then(Transform::translation(c.x, c.y, c.z))
        };
        objects.push(object(Shape::from(Instance::new(can, m).unwrap())));
    }
    objects.push(object(Shape::from(Cylinder::new(0.7, -1.0, 2.0).unwrap())));
    let scene = scene(objects);
    assert!(Bvh::build(scene.objects()).unbounded().is_empty());
    let rays = random_rays(&mut rng, 4000, 12.0, 10.0);
    let hits = assert_same_answers(&scene, &rays);
    assert!(hits > 1500, "{hits} hits");
}
