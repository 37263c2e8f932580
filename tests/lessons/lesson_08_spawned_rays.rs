//! Rays spawned from a hit must not find their own surface again (STABILITY S13,
//! and issue 20's far-sphere case): for every shape (the capped cylinder too), and
//! through an instance, the error-bound offset (pbrt-v4 section 6.8) gives 0 re-hits
//! from near and far, while the scaled offset of Wachter and Binder fails when the
//! camera is far from a surface near the origin (its offset follows |p|, the point's
//! error follows t).
//!
//! Each surface here is convex (or flat): a ray leaving it on the side of the
//! normal it starts from can never meet it again, so every re-hit is a rounding
//! artefact. The reference is geometry, not a number computed another way.

use crate::common::unit_sphere;
use glam::{Vec2, Vec3};
use render_lessons::material::Material;
use render_lessons::pathtrace::{Settings, radiance};
use render_lessons::ray::{Interval, Ray};
use render_lessons::rng::Rng;
use render_lessons::sampling::uniform_sphere;
use render_lessons::scene::{Object, Scene};
use render_lessons::scenes::path_tracing::look_camera;
use render_lessons::shapes::{
    Aabb, Cylinder, Hit, Instance, Plane, Quad, Quadric, Shape, Sphere, Triangle,
};
use render_lessons::spawn::{Offset, Start};
use render_lessons::transform::Transform;

/// The camera distances of the issue: 10, 300, 1e4 and 1e6 radii.
const DISTANCES: [f32; 4] = [10.0, 300.0, 1e4, 1e6];

/// The direction from the shape towards the camera (any direction not along an axis).
fn towards_camera() -> Vec3 {
    Vec3::new(0.3, -0.2, 5.0).normalize()
}

/// Re-hits and spawned rays for `shape`, seen from `distance` along
/// [`towards_camera`], with primary rays aimed at `targets` (points on or inside the
/// surface), `spawned` rays from each hit in directions uniform on the sphere. A
/// `solid` shape keeps only the directions on the side its outward normal points to
/// (the others go inside it, where the far side is a real hit); a flat one keeps
/// every direction and starts each ray on the side it goes to. With `raw_point` the
/// ray starts from o + t d, as the renderers did before the hit point was projected
/// onto its surface, instead of the hit's point.
fn re_hits(
    shape: &Shape,
    distance: f32,
    targets: &[Vec3],
    spawned: u32,
    solid: bool,
    offset: Offset,
    raw_point: bool,
) -> (u32, u32) {
    let camera = distance * towards_camera();
    let mut rng = Rng::for_pixel(7, distance.to_bits(), 0);
    let (mut wrong, mut total) = (0, 0);
    for (i, &target) in targets.iter().enumerate() {
        let origin = camera + Vec3::splat(i as f32 * 1e-3);
        let ray = Ray::new(origin, target - origin).unwrap();
        let Some(hit) = shape.hit(&ray, Interval::AHEAD) else {
            continue;
        };
        let (w, t) = spawn(
            shape,
            &ray,
            &hit,
            How {
                solid,
                offset,
                raw_point,
            },
            spawned,
            &mut rng,
        );
        (wrong, total) = (wrong + w, total + t);
    }
    (wrong, total)
}

/// How rays leave a hit: see [`re_hits`].
#[derive(Clone, Copy)]
struct How {
    solid: bool,
    offset: Offset,
    raw_point: bool,
}

/// Re-hits of `shape` among `spawned` rays leaving `hit` (of `ray`) in directions
/// uniform on the sphere, started as `how` says; and how many rays were spawned.
fn spawn(
    shape: &Shape,
    ray: &Ray,
    hit: &Hit,
    how: How,
    spawned: u32,
    rng: &mut Rng,
) -> (u32, u32) {
    let point = if how.raw_point {
        ray.at(hit.t)
    } else {
        hit.point
    };
    let (mut wrong, mut total) = (0, 0);
    for _ in 0..spawned {
        let w = uniform_sphere(rng.next_vec2());
        let side = if w.dot(hit.normal) >= 0.0 {
            hit.normal
        } else if how.solid {
            continue;
        } else {
            -hit.normal
        };
        let Start {
            point: start,
            t_min,
        } = how.offset.start(point, hit.error, side);
        let Ok(out) = Ray::new(start, w) else {
            continue;
        };
        total += 1;
        wrong += u32::from(
            shape
                .hit(&out, Interval::new(t_min, f32::INFINITY))
                .is_some(),
        );
    }
    (wrong, total)
}

/// `n` x `n` points on a disc of radius `r` around `centre`, facing the camera.
fn targets(centre: Vec3, r: f32, n: u32) -> Vec<Vec3> {
    let axis = towards_camera();
    let u = axis.cross(Vec3::Y).normalize();
    let v = axis.cross(u);
    (0..n * n)
        .map(|i| {
            let (a, b) = ((i % n) as f32 + 0.5, (i / n) as f32 + 0.5);
            let (x, y) = (2.0 * a / n as f32 - 1.0, 2.0 * b / n as f32 - 1.0);
            centre + r * (x * u + y * v) * std::f32::consts::FRAC_1_SQRT_2
        })
        .collect()
}

/// Asserts 0 re-hits of `shape` at every distance, with a real number of rays.
fn assert_never_re_hit(name: &str, shape: &Shape, aim: &[Vec3], solid: bool) {
    for d in DISTANCES {
        let (wrong, total) =
            re_hits(shape, d, aim, 16, solid, Offset::ErrorBound, false);
        eprintln!("{name} from {d:e}: {wrong} of {total}");
        assert!(total > 1000, "{name} from {d:e}: only {total} rays spawned");
        assert_eq!(wrong, 0, "{name} from {d:e}: {wrong} of {total} re-hit");
    }
}

#[test]
fn sphere_is_never_re_hit_from_near_or_far() {
    assert_never_re_hit(
        "sphere",
        &Shape::from(unit_sphere()),
        &targets(Vec3::ZERO, 0.9, 24),
        true,
    );
}

#[test]
fn far_sphere_is_never_re_hit_from_near_or_far() {
    // The sphere itself far from the world origin: |p| about 1e4.
    let centre = Vec3::new(1e4, 5e3, 2.5e3);
    let sphere = Shape::Sphere(Sphere::new(centre, 1.0).unwrap());
    let camera = |d: f32| centre + d * towards_camera();
    for d in [10.0, 300.0] {
        let mut wrong = 0;
        for (i, target) in targets(centre, 0.9, 24).into_iter().enumerate() {
            let origin = camera(d) + Vec3::splat(i as f32 * 1e-3);
            let ray = Ray::new(origin, target - origin).unwrap();
            let hit = sphere.hit(&ray, Interval::AHEAD).unwrap();
            let Start {
                point: start,
                t_min,
            } = Offset::ErrorBound.start(hit.point, hit.error, hit.normal);
            for k in 0..16 {
                let w = uniform_sphere(Vec2::new((k as f32 + 0.5) / 16.0, 0.37));
                let w = if w.dot(hit.normal) < 0.0 { -w } else { w };
                let out = Ray::new(start, w).unwrap();
                wrong += u32::from(
                    sphere
                        .hit(&out, Interval::new(t_min, f32::INFINITY))
                        .is_some(),
                );
            }
        }
        assert_eq!(wrong, 0, "sphere at {centre} seen from {d}");
    }
}

#[test]
fn scaled_offset_fails_on_the_point_o_plus_t_d_seen_from_far_away() {
    // The failing method keeps its test. From o + t d, the point the renderers used
    // before, the scaled offset follows |p| (about 1 here) while the point's error
    // follows t (about the distance); a fixed epsilon fails too.
    let (sphere, aim) = (Shape::from(unit_sphere()), targets(Vec3::ZERO, 0.9, 24));
    let run = |d: f32, offset: Offset, raw: bool| {
        re_hits(&sphere, d, &aim, 16, true, offset, raw)
    };
    let (near, _) = run(10.0, Offset::Scaled, true);
    let (far, total) = run(1e4, Offset::Scaled, true);
    eprintln!(
        "scaled offset from o + t d: {near} re-hits from 10, {far} of {total} from 1e4"
    );
    assert_eq!(near, 0);
    assert!(far * 10 > total, "{far} of {total}");
    let (fixed, total) = run(1e4, Offset::Fixed(1e-4), true);
    eprintln!("fixed t > 1e-4 from o + t d: {fixed} of {total} from 1e4");
    assert!(fixed * 10 > total, "{fixed} of {total}");
    // Projected onto the sphere, the point's error follows |p| again, and the same
    // scaled offset holds.
    assert_eq!(run(1e4, Offset::Scaled, false).0, 0);
}

#[test]
fn plane_is_never_re_hit_from_near_or_far() {
    let plane = Shape::Plane(Plane::new(Vec3::ZERO, Vec3::new(0.2, 1.0, 0.4)).unwrap());
    assert_never_re_hit("plane", &plane, &targets(Vec3::ZERO, 1.0, 24), false);
}

#[test]
fn quad_is_never_re_hit_from_near_or_far() {
    let q = Quad::new(
        Vec3::new(-1.0, -0.8, 0.1),
        Vec3::new(2.0, 0.3, 0.1),
        Vec3::new(-0.2, 1.7, 0.3),
    )
    .unwrap();
    let aim = targets(q.point(0.5, 0.5), 0.5, 24);
    assert_never_re_hit("quad", &Shape::Quad(q), &aim, false);
}

#[test]
fn box_is_never_re_hit_from_near_or_far() {
    let b = Aabb::new(Vec3::splat(-1.0), Vec3::new(1.0, 0.5, 2.0)).unwrap();
    assert_never_re_hit("box", &Shape::Aabb(b), &targets(Vec3::ZERO, 0.9, 24), true);
}

#[test]
fn triangle_is_never_re_hit_from_near_or_far() {
    let tri = Triangle::new(
        Vec3::new(-1.0, -1.0, 0.2),
        Vec3::new(1.2, -0.7, -0.1),
        Vec3::new(0.1, 1.3, 0.3),
    )
    .unwrap();
    let aim = targets(Vec3::new(0.1, -0.1, 0.13), 0.4, 24);
    assert_never_re_hit("triangle", &Shape::Triangle(tri), &aim, false);
}

#[test]
fn convex_quadrics_are_never_re_hit_from_near_or_far() {
    let shapes = [
        (
            "ellipsoid",
            Quadric::ellipsoid(Vec3::new(1.0, 0.6, 1.4)).unwrap(),
        ),
        ("cylinder", Quadric::cylinder(0.8).unwrap()),
        ("paraboloid", Quadric::paraboloid().unwrap()),
    ];
    for (name, q) in shapes {
        let aim = targets(Vec3::new(0.0, 0.0, 0.5), 0.5, 24);
        assert_never_re_hit(name, &Shape::Quadric(q), &aim, true);
    }
}

#[test]
fn capped_cylinder_is_never_re_hit_from_near_or_far() {
    let can = Cylinder::new(0.8, -0.5, 0.5).unwrap();
    // Seen end on: the top cap, the rim, and the side beyond it.
    let aim = targets(Vec3::new(0.0, 0.0, 0.5), 0.9, 24);
    assert_never_re_hit("cylinder end on", &Shape::Cylinder(can), &aim, true);
    // Turned about x: the side, a cap and both rims.
    let turned = Instance::new(can.into(), Transform::rotation_x(1.3)).unwrap();
    let aim = targets(Vec3::ZERO, 0.9, 24);
    assert_never_re_hit("cylinder turned", &turned.into(), &aim, true);
}

#[test]
fn capped_cylinder_side_is_never_re_hit_seen_from_the_side() {
    // The camera across the axis, so that the side, not a cap, is hit: its point
    // projected onto the circle, whose error bound alone keeps spawned rays out.
    let can = Shape::Cylinder(Cylinder::new(0.8, -0.5, 0.5).unwrap());
    let across = Vec3::new(5.0, 0.3, -0.2).normalize();
    let how = How {
        solid: true,
        offset: Offset::ErrorBound,
        raw_point: false,
    };
    for d in DISTANCES {
        let mut rng = Rng::for_pixel(8, d.to_bits(), 0);
        let (mut wrong, mut total, mut sides) = (0, 0, 0);
        for i in 0..24 * 24 {
            let (a, b) = ((i % 24) as f32 / 23.0 - 0.5, (i / 24) as f32 / 23.0 - 0.5);
            let origin = d * across + Vec3::splat(i as f32 * 1e-3);
            let target = Vec3::new(0.0, 1.5 * a, 0.9 * b);
            let ray = Ray::new(origin, target - origin).unwrap();
            let Some(hit) = can.hit(&ray, Interval::AHEAD) else {
                continue;
            };
            sides += u32::from(hit.normal.z == 0.0);
            let (w, t) = spawn(&can, &ray, &hit, how, 16, &mut rng);
            (wrong, total) = (wrong + w, total + t);
        }
        eprintln!("cylinder side from {d:e}: {wrong} of {total}, {sides} side hits");
        assert!(sides > 200, "from {d:e}: only {sides} side hits");
        assert_eq!(wrong, 0, "from {d:e}: {wrong} of {total} re-hit");
    }
}

#[test]
fn instanced_sphere_is_never_re_hit_from_near_or_far() {
    let place = Transform::scale(2.0, 0.5, 1.0)
        .then(Transform::rotation_y(0.7))
        .then(Transform::translation(0.5, -0.25, 0.1));
    let instance = Instance::new(Shape::from(unit_sphere()), place).unwrap();
    let aim = targets(Vec3::new(0.5, -0.25, 0.1), 0.4, 24);
    assert_never_re_hit(
        "instanced sphere",
        &Shape::Instance(Box::new(instance)),
        &aim,
        true,
    );
}

/// 10^x for x uniform in [-8, 8]: a coordinate of any size f32 holds comfortably.
fn log_uniform(rng: &mut Rng) -> f32 {
    10f32.powf(-8.0 + 16.0 * rng.next_f32())
}

/// Re-hits of random triangles whose coordinates range from 1e-8 to 1e8, each hit by
/// a ray from a random origin aimed at a random point of it, with 16 rays spawned
/// from every hit in directions uniform on the sphere, each started on the side it
/// goes to (pbrt-v4's `Triangle, Reintersect` test, written again here).
fn triangle_re_hits(offset: Offset, raw_point: bool) -> (u32, u32) {
    let (mut wrong, mut total) = (0, 0);
    for i in 0..1000 {
        let mut rng = Rng::for_pixel(20, i, 0);
        let mut point = || {
            Vec3::new(
                log_uniform(&mut rng),
                log_uniform(&mut rng),
                log_uniform(&mut rng),
            )
        };
        let (v0, v1, v2, origin) = (point(), point(), point(), point());
        let Ok(tri) = Triangle::new(v0, v1, v2) else {
            continue;
        };
        let (mut a, mut b) = (rng.next_f32(), rng.next_f32());
        if a + b >= 1.0 {
            (a, b) = (1.0 - a, 1.0 - b);
        }
        let target = a * v0 + b * v1 + (1.0 - a - b) * v2;
        let Ok(ray) = Ray::new(origin, target - origin) else {
            continue;
        };
        let Some(hit) = tri.hit(&ray, Interval::AHEAD) else {
            continue;
        };
        let how = How {
            solid: false,
            offset,
            raw_point,
        };
        let (w, t) = spawn(&Shape::Triangle(tri), &ray, &hit, how, 16, &mut rng);
        (wrong, total) = (wrong + w, total + t);
    }
    (wrong, total)
}

#[test]
fn triangles_with_coordinates_up_to_1e8_are_never_re_hit() {
    let (wrong, total) = triangle_re_hits(Offset::ErrorBound, false);
    eprintln!("error bound: {wrong} of {total}");
    assert!(total > 5000, "only {total} rays spawned");
    assert_eq!(wrong, 0, "{wrong} of {total} re-hit");
}

#[test]
fn scaled_offset_from_o_plus_t_d_fails_on_triangles_with_large_coordinates() {
    // The failing method keeps its test: from o + t d, the scaled offset follows |p|
    // while the point's error follows t and the corners' coordinates.
    let (wrong, total) = triangle_re_hits(Offset::Scaled, true);
    eprintln!("scaled offset: {wrong} of {total}");
    assert!(wrong > 0, "{wrong} of {total}");
}

/// The far-sphere furnace: a diffuse sphere of albedo 0.8 at the world origin under a
/// uniform sky of radiance 1, seen from `distance` by a camera whose view the sphere
/// fills. A convex sphere never sees itself, so every path is camera -> sphere -> sky
/// and every pixel's exact value is 0.8; a re-hit multiplies by 0.8 again. Returns
/// the mean and the standard deviation of one sample over `n` samples.
fn far_furnace(distance: f32, n: u32) -> (f64, f64) {
    let sphere = Shape::from(unit_sphere());
    let grey = Material::diffuse(Vec3::splat(0.8)).unwrap();
    let scene = Scene::new(vec![Object::new(sphere, grey)], Vec3::ONE).unwrap();
    let eye = distance * towards_camera();
    let camera = look_camera(16, 16, eye, -eye, 0.5 / distance).unwrap();
    let settings = Settings::default();
    let mut rng = Rng::for_pixel(11, 0, 0);
    let (mut sum, mut sum2) = (0.0f64, 0.0f64);
    for i in 0..n {
        let pixel = Vec2::new((i % 16) as f32 + 0.5, ((i / 16) % 16) as f32 + 0.5);
        let x = f64::from(
            radiance(
                &scene,
                camera.ray_through(pixel, Vec2::ZERO),
                &mut rng,
                &settings,
            )
            .x,
        );
        (sum, sum2) = (sum + x, sum2 + x * x);
    }
    let mean = sum / f64::from(n);
    (mean, (sum2 / f64::from(n) - mean * mean).max(0.0).sqrt())
}

#[test]
fn far_sphere_furnace_is_0_8_from_near_and_far() {
    let n = 8192;
    for d in DISTANCES {
        let (mean, sigma) = far_furnace(d, n);
        let noise = 3.0 * sigma / f64::from(n).sqrt();
        eprintln!("furnace from {d:e}: mean {mean}, 3 sigma/sqrt(N) {noise:e}");
        assert!(
            (mean - 0.8).abs() <= noise + 1e-6,
            "from {d:e}: mean {mean}"
        );
    }
}

/// Page 08_1: "The acne spares the box and the floor." Of the pixels of lesson 08's
/// far image that the fixed epsilon changes (by more than two levels of 255 in a
/// channel, as the lesson counts them), those on the box or the floor are changed
/// the same with the scaled offset (moving the scene changed them, not the epsilon);
/// every other shows a sphere or the triangle.
#[test]
fn the_acne_of_the_fixed_epsilon_spares_the_box_and_the_floor() {
    use crate::examples::ray_casting as lesson;
    use render_lessons::scenes::{STILL_LIFE_OBJECTS, still_life, still_life_cameras};
    let ((width, height), far) = ((480, 270), Vec3::new(1e4, 0.0, 0.0));
    let images = lesson::images((width, height), 1e-4, far).unwrap();
    let scene = still_life(far).unwrap();
    let [_, camera] = still_life_cameras(width, height, far).unwrap();
    let (mut acne, mut moved) = (0, 0);
    for y in 0..height {
        for x in 0..width {
            let clean = images.lambert.get(x, y).unwrap();
            let fixed = images.far_fixed_epsilon.get(x, y).unwrap();
            if (clean - fixed).abs().max_element() <= 2.0 / 255.0 {
                continue;
            }
            let object = scene.closest_object(&camera.ray(x, y), Interval::AHEAD);
            let shows = object.map_or("the sky", |i| STILL_LIFE_OBJECTS[i]);
            if ["box", "floor"].contains(&shows) {
                let scaled = images.far_scaled_offset.get(x, y).unwrap();
                assert_eq!(fixed, scaled, "({x}, {y}): {shows}");
                moved += 1;
            } else {
                acne += 1;
            }
        }
    }
    // The page's 2797 pixels (the acne snapshot counts them): three on the box and
    // the floor, which the scaled offset's 8 include.
    assert_eq!((acne, moved), (2794, 3));
}
