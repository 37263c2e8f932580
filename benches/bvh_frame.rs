//! One or more frames of the BVH bench's near view (or its far one; 480 x 270 unless
//! told) on one thread, through this crate's tree, obvhs's `Bvh2` or Embree, each
//! tree built before the frames: what `valgrind --tool=callgrind` counts in
//! `scripts/instructions-per-ray --bvh` (`--far` for the far view), which runs it for
//! 1 and 2 frames and divides the difference by the number of rays.
//!
//!     cargo build --release -p render-benches --bin bvh-frame
//!     target/release/bvh-frame TREE [WIDTH HEIGHT [FRAMES [near|far]]]
//!     target/release/bvh-frame check [WIDTH HEIGHT]
//!
//! TREE is `ours` (`BvhScene::closest_object`), `obvhs` (`Bvh2::ray_traverse` with
//! its Möller-Trumbore test) or `embree` (`rtcIntersect1`, when the Embree anchor was
//! built), the same question as in `benches/bvh.rs`. `check` compares Embree's hits
//! with the crate's on the frame's rays (`embree::Agreement`, as the bench does
//! before it times them) and fails when they differ; without Embree it says so and
//! passes, as `.ci/run` runs it on machines with and without it.
//!
//! The line it prints ends with the time the frames took, the tree's build left
//! out, which `scripts/instructions-per-ray --bvh --clock` turns into cycles per ray.

use std::process::ExitCode;
use std::time::{Duration, Instant};

use obvhs::ray::RayHit;
use render_benches::args::{self, number};
use render_benches::embree::{self, Agreement, EmbreeMesh, flat_rays};
use render_benches::mesh_view::{
    FAR, NEAR, camera, obvhs_ray, obvhs_triangles, rays, sphere_mesh, sphere_scene,
};
use render_lessons::ray::Interval;
use render_lessons::scene::BvhScene;
use render_lessons::scene::Intersect;

/// The most rays a frame may have: 4096 x 4096, about half a gigabyte of rays.
const MAX_RAYS: u64 = 4096 * 4096;

fn main() -> ExitCode {
    args::main("bvh-frame", run)
}

fn run(args: Vec<String>) -> Result<String, String> {
    let tree = args.first().map(String::as_str).unwrap_or_default();
    if !["ours", "obvhs", "embree", "check"].contains(&tree) || args.len() > 5 {
        return Err(format!(
            "usage: bvh-frame ours|obvhs|embree [WIDTH HEIGHT [FRAMES [near|far]]], or check \
             [WIDTH HEIGHT] (TREE was '{tree}')"
        ));
    }
    let width = number(&args, 1, "WIDTH", 480)?;
    let height = number(&args, 2, "HEIGHT", 270)?;
    let frames = number(&args, 3, "FRAMES", 1)?;
    let distance = match args.get(4).map(String::as_str) {
        None | Some("near") => NEAR,
        Some("far") => FAR,
        Some(other) => {
            return Err(format!("CAMERA must be near or far, not '{other}'"));
        }
    };
    if u64::from(width) * u64::from(height) > MAX_RAYS {
        return Err(format!(
            "WIDTH x HEIGHT must be at most {MAX_RAYS} rays (they are kept in memory), not {width} x {height}"
        ));
    }
    let scene = sphere_scene(224);
    let rays = rays(&camera(width, height, distance));
    let mut hits = 0;
    let took: Duration;
    if tree == "check" || tree == "embree" {
        let mesh = EmbreeMesh::new(&sphere_mesh(224));
        // Without Embree the check passes (a machine without it is an ordinary one);
        // a frame through it cannot be counted.
        let Some(built) = mesh.build() else {
            let missing = embree::MISSING.to_string();
            return if tree == "check" {
                Ok(missing)
            } else {
                Err(missing)
            };
        };
        let embree = built?;
        if tree == "check" {
            let agreement = Agreement::of(&BvhScene::new(scene), &embree, &rays);
            return if agreement.holds() {
                Ok(format!("{width}x{height} rays: {agreement}"))
            } else {
                Err(agreement.to_string())
            };
        }
        let flat = flat_rays(&rays);
        let start = Instant::now();
        for _ in 0..frames {
            hits += embree.count_hits(&flat);
        }
        took = start.elapsed();
    } else if tree == "ours" {
        let ours = BvhScene::new(scene);
        let start = Instant::now();
        for _ in 0..frames {
            hits += rays
                .iter()
                .filter(|r| ours.closest_object(r, Interval::AHEAD).is_some())
                .count();
        }
        took = start.elapsed();
    } else {
        let triangles = obvhs_triangles(&scene);
        let params = obvhs::BvhBuildParams::medium_build();
        let mut build_time = std::time::Duration::ZERO;
        let bvh2 = obvhs::bvh2::builder::build_bvh2_from_tris(
            &triangles,
            params,
            &mut build_time,
        );
        let start = Instant::now();
        for _ in 0..frames {
            hits += rays
                .iter()
                .filter(|r| {
                    let mut hit = RayHit::none();
                    bvh2.ray_traverse(obvhs_ray(r), &mut hit, |ray, id| {
                        triangles[bvh2.primitive_indices[id] as usize].intersect(ray)
                    })
                })
                .count();
        }
        took = start.elapsed();
    }
    Ok(format!(
        "{tree}: {frames} frame(s) of {width}x{height}, {hits} rays hit, in {:.6} s",
        took.as_secs_f64()
    ))
}
