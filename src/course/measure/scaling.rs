//! Chart 7, model no more than a scene needs: the time to cast a frame against the
//! number of primitives, for the plain list of lesson 08 and for the BVH of this
//! lesson. The list costs one test per primitive per ray; the tree about log n
//! box tests and a few primitive tests. Where the lines cross, the tree starts
//! to pay (its build time is reported beside it).

use std::time::Instant;

use glam::Vec3;

use super::{Measured, Quality};
use crate::camera::{Camera, Film, Frame, PinholeCamera};
use crate::course::chart::{Chart, Scale};
use crate::course::report::{BookNumbers, Quoted};
use crate::error::Result;
use crate::mesh::Mesh;
use crate::ray::{Interval, Ray};
use crate::scene::BvhScene;
use crate::scene::{Intersect, Object, PointLight, Scene};
use crate::shapes::{Shape, Triangle};

/// A uv sphere of radius 1 with `n` x `n` segments (2 n (n - 1) triangles), as a
/// scene of triangle primitives.
pub fn sphere_scene(n: u32) -> Result<Scene> {
    let objects =
        Mesh::uv_sphere(Vec3::ZERO, 1.0, n, n)?.objects(Vec3::new(0.8, 0.5, 0.3))?;
    let light = PointLight {
        position: Vec3::new(0.0, 5.0, 5.0),
        intensity: Vec3::ONE,
    };
    Scene::new(objects, Vec3::ZERO).and_then(|s| s.with_light(light))
}

/// `k` triangles in a fan around the view's centre, a disc of radius 0.9 facing
/// the camera: a scene of very few primitives that most rays hit.
pub fn fan_scene(k: u32) -> Result<Scene> {
    let slices = k.max(3);
    let corner = |i: u32| {
        let a = std::f32::consts::TAU * i as f32 / slices as f32;
        Vec3::new(0.9 * a.cos(), 0.9 * a.sin(), 0.0)
    };
    let objects = (0..k)
        .map(|i| {
            Ok(Object::diffuse(
                Shape::Triangle(Triangle::new(Vec3::ZERO, corner(i), corner(i + 1))?),
                Vec3::new(0.8, 0.5, 0.3),
            ))
        })
        .collect::<Result<Vec<_>>>()?;
    let light = PointLight {
        position: Vec3::new(0.0, 5.0, 5.0),
        intensity: Vec3::ONE,
    };
    Scene::new(objects, Vec3::ZERO).and_then(|s| s.with_light(light))
}

/// The primary rays of a `width` x `height` pinhole view of the sphere, which
/// fills most of the frame.
pub fn rays(width: u32, height: u32) -> Result<Vec<Ray>> {
    let eye = Vec3::new(0.0, 0.4, 3.0);
    let half = 0.42;
    let aspect = width as f32 / height as f32;
    let film = Film::new(
        width,
        height,
        (-half * aspect, half * aspect),
        (-half, half),
    )?;
    let camera: Camera =
        PinholeCamera::new(film, 1.0, Frame::look(eye, -eye, Vec3::Y)?)?.into();
    Ok((0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .map(|(x, y)| camera.ray(x, y))
        .collect())
}

/// Seconds per frame of `rays`, the best of `repeats` runs, one thread, closest
/// hit only; also the number of rays that hit (so the two structures can be
/// checked against each other).
fn seconds_per_frame(
    rays: &[Ray],
    repeats: u32,
    hit: impl Fn(&Ray) -> bool,
) -> (f64, usize) {
    let mut best = f64::INFINITY;
    let mut hits = 0;
    for _ in 0..repeats.max(1) {
        let start = Instant::now();
        hits = rays.iter().filter(|r| hit(r)).count();
        best = best.min(start.elapsed().as_secs_f64());
    }
    (best, hits)
}

/// One row of the chart: the scene's size, the list's and the tree's frame times,
/// the tree's build time, and whether both found the same number of hits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Row {
    /// Primitives in the scene.
    pub primitives: usize,
    /// Seconds per frame through the plain list (`None`: skipped, too slow).
    pub list: Option<f64>,
    /// Seconds per frame through the BVH.
    pub bvh: f64,
    /// Seconds to build the BVH.
    pub build: f64,
    /// Both structures hit the same number of rays (where both ran).
    pub agree: bool,
}

/// Measures each scene of `scenes` with the rays of a `width` x `height` frame;
/// the list only up to `list_limit` primitives.
pub fn rows(
    scenes: Vec<Scene>,
    width: u32,
    height: u32,
    list_limit: usize,
) -> Result<Vec<Row>> {
    let rays = rays(width, height)?;
    let mut rows = Vec::new();
    for scene in scenes {
        let primitives = scene.objects().len();
        let repeats = if primitives < 1000 { 5 } else { 2 };
        let list = (primitives <= list_limit).then(|| {
            seconds_per_frame(&rays, repeats, |r| {
                scene.closest(r, Interval::AHEAD).is_some()
            })
        });
        let start = Instant::now();
        let tree = BvhScene::new(scene);
        let build = start.elapsed().as_secs_f64();
        let (bvh, bvh_hits) = seconds_per_frame(&rays, repeats, |r| {
            tree.closest(r, Interval::AHEAD).is_some()
        });
        rows.push(Row {
            primitives,
            list: list.map(|(s, _)| s),
            bvh,
            build,
            agree: list.is_none_or(|(_, hits)| hits == bvh_hits),
        });
    }
    Ok(rows)
}

// ANCHOR: measure
/// The chart: milliseconds per frame against primitives, log-log, list and BVH.
pub fn measure(quality: Quality) -> Result<Measured> {
    let (width, height) = quality.pick((96, 54), (192, 108));
    let fans = [1, 2, 4, 8].map(fan_scene);
    let spheres: &[u32] =
        quality.pick(&[3, 6, 16, 23, 45], &[3, 6, 16, 23, 45, 71, 224]);
    let mut scenes = fans.into_iter().collect::<Result<Vec<_>>>()?;
    for &n in spheres {
        scenes.push(sphere_scene(n)?);
    }
    let rows = rows(scenes, width, height, 10_000)?;
    let ms = |s: f64| 1e3 * s;
    let list = rows
        .iter()
        .filter_map(|r| Some((r.primitives as f64, ms(r.list?))))
        .collect();
    let bvh = rows
        .iter()
        .map(|r| (r.primitives as f64, ms(r.bvh)))
        .collect();
    let build = rows
        .iter()
        .map(|r| (r.primitives as f64, ms(r.build)))
        .collect();
    let chart = Chart::new(
        &format!(
            "Primary rays of a {width} x {height} frame, one thread: list against BVH"
        ),
        (
            "primitives (1-8: a fan of triangles; 12 and up: a uv sphere)",
            Scale::Log,
        ),
        ("time per frame (ms)", Scale::Log),
    )
    .with("plain list", list)
    .with("BVH (binned SAH)", bvh)
    .with("BVH build", build);
    Ok(Measured {
        findings: findings(&rows),
        quoted: quoted(&rows, width * height),
        chart,
    })
}
// ANCHOR_END: measure

/// The numbers the book quotes from chart 7, all timed but the sizes: table
/// `frames`, every row's frame, build and throughput; values `bvh_mrays` (million
/// rays per second through the tree at the largest size) and `largest` (its
/// number of primitives).
fn quoted(rows: &[Row], rays: u32) -> BookNumbers {
    let ms = |s: f64| format!("{:.2}", 1e3 * s);
    let mrays = |s: f64| f64::from(rays) / s / 1e6;
    let mut table = Quoted::new(
        "frames",
        true,
        &[
            "primitives",
            "list (ms)",
            "BVH (ms)",
            "BVH build (ms)",
            "BVH (M rays/s)",
        ],
    );
    for r in rows {
        table = table.row(vec![
            r.primitives.to_string(),
            r.list.map_or("not run".into(), ms),
            ms(r.bvh),
            ms(r.build),
            format!("{:.2}", mrays(r.bvh)),
        ]);
    }
    let mut fragment = BookNumbers::default().table(table);
    if let Some(last) = rows.last() {
        fragment = fragment
            .value("bvh_mrays", true, format!("{:.2}", mrays(last.bvh)))
            .value("largest", false, last.primitives.to_string());
    }
    fragment
}

fn findings(rows: &[Row]) -> Vec<String> {
    let mut out = Vec::new();
    let crossover = rows.iter().find(|r| r.list.is_some_and(|l| r.bvh < l));
    match crossover {
        Some(r) if r.primitives == rows[0].primitives => out.push(format!(
            "the BVH is faster at every size measured, even {} primitive(s): its root box \
             turns away the rays that miss everything before the costly watertight test",
            r.primitives
        )),
        Some(r) => out.push(format!(
            "crossover: the list is faster below {} primitives, the BVH from there on",
            r.primitives
        )),
        None => out.push("the plain list was faster at every size measured".into()),
    }
    if let Some(r) = rows.iter().rfind(|r| r.list.is_some()) {
        out.push(format!(
            "at {} primitives: list {:.1} ms, BVH {:.2} ms per frame ({:.0}x), build {:.1} ms",
            r.primitives,
            1e3 * r.list.unwrap_or(0.0),
            1e3 * r.bvh,
            r.list.unwrap_or(0.0) / r.bvh,
            1e3 * r.build
        ));
    }
    if rows.iter().all(|r| r.agree) {
        out.push("list and BVH hit exactly the same rays at every size".into());
    } else {
        out.push("WARNING: list and BVH disagree on which rays hit".into());
    }
    out
}
