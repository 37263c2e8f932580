//! Chart 11.2: ray/triangle, the time per test against the leak rate.
//!
//! The cases are STABILITY S4 and S5, with S6 as a finding.
//!
//! The mesh is the closed bumpy UV sphere of lesson 07's stability tests (16 x 16
//! segments, vertex radii 1 to 1.5, wound outwards). Rays from the origin, inside it,
//! are aimed exactly at its vertices and at points on its shared edges: each must hit
//! at least one triangle, and a ray that hits none has leaked through the mesh.
//! Every ray is tested against every triangle, so the time per test is the time of
//! that brute-force loop divided by the number of tests.
//!
//! The methods are Möller-Trumbore, the watertight test of Woop, Benthin and Wald,
//! and, as a comparison written here, Möller-Trumbore with its edge tests widened by
//! a small epsilon (the usual patch for its leaks).
//!
//! This file measures the chart; `boxes.rs` measures the S6 finding below it, and
//! `tables.rs` builds the tables the book quotes from both.

mod boxes;
mod tables;

pub use boxes::{BoxCounts, BoxRejects, box_cases, box_counts, box_rejects};
pub use tables::exact_quoted;

use glam::Vec3;

use super::sphere::fastest;
use super::{Measured, Quality, ns_per_call};
use crate::course::chart::{Chart, Scale};
use crate::error::Result;
use crate::ray::{Interval, Ray};
use crate::shapes::{Barycentric, Triangle};
use tables::quoted_times;

/// The ray/triangle tests on the chart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TriangleMethod {
    /// [`Triangle::moller_trumbore`].
    MollerTrumbore,
    /// Möller-Trumbore with each barycentric test widened by [`EPSILON`].
    MollerTrumboreEpsilon,
    /// [`Triangle::watertight`].
    Watertight,
}

/// How far the epsilon variant of Möller-Trumbore widens its barycentric tests:
/// b1 >= -EPSILON, b2 >= -EPSILON, b1 + b2 <= 1 + EPSILON.
pub const EPSILON: f32 = 1e-6;

impl TriangleMethod {
    /// In the chart's order.
    pub const ALL: [TriangleMethod; 3] = [
        TriangleMethod::MollerTrumbore,
        TriangleMethod::MollerTrumboreEpsilon,
        TriangleMethod::Watertight,
    ];

    /// The legend's name.
    pub fn name(self) -> &'static str {
        match self {
            TriangleMethod::MollerTrumbore => "Möller-Trumbore",
            TriangleMethod::MollerTrumboreEpsilon => {
                "Möller-Trumbore, edges widened by 1e-6"
            }
            TriangleMethod::Watertight => "watertight (Woop et al.)",
        }
    }

    /// Does `ray` hit `tri` at some t > 0?
    pub fn hits(self, tri: &Triangle, ray: &Ray) -> bool {
        match self {
            TriangleMethod::MollerTrumbore => {
                tri.moller_trumbore(ray, Interval::AHEAD).is_some()
            }
            TriangleMethod::MollerTrumboreEpsilon => {
                moller_trumbore_epsilon(tri, ray, Interval::AHEAD).is_some()
            }
            TriangleMethod::Watertight => {
                tri.watertight(ray, Interval::AHEAD).is_some()
            }
        }
    }
}

/// [`Triangle::moller_trumbore`] with the barycentric tests widened by [`EPSILON`]:
/// a ray that passes just outside an edge counts as a hit. The same signature and
/// result as the crate's method (and kept out of line like it), so that the two are
/// timed alike and differ only by the epsilon.
#[inline(never)]
pub fn moller_trumbore_epsilon(
    tri: &Triangle,
    ray: &Ray,
    range: Interval,
) -> Option<Barycentric> {
    let [v0, v1, v2] = tri.vertices();
    let (o, d) = (ray.origin(), ray.direction());
    let (e1, e2) = (v1 - v0, v2 - v0);
    let p = d.cross(e2);
    let det = e1.dot(p);
    if det == 0.0 {
        return None;
    }
    let inv = 1.0 / det;
    let s = o - v0;
    let b1 = s.dot(p) * inv;
    if !(-EPSILON..=1.0 + EPSILON).contains(&b1) {
        return None;
    }
    let q = s.cross(e1);
    let b2 = d.dot(q) * inv;
    if !(b2 >= -EPSILON && b1 + b2 <= 1.0 + EPSILON) {
        return None;
    }
    let t = e2.dot(q) * inv;
    let b = [1.0 - b1 - b2, b1, b2];
    range.contains(t).then_some(Barycentric { t, b })
}

/// A closed bumpy UV sphere of `rings` x `segments` (the mesh of lesson 07's S4/S5
/// tests is 16 x 16), vertex radii in [1, 1.5] from a fixed formula, triangles wound
/// outwards: the vertices and the triangles' vertex indices.
pub fn bumpy_sphere(rings: usize, segments: usize) -> (Vec<Vec3>, Vec<[usize; 3]>) {
    let (n, m) = (rings, segments);
    let mut vertices = vec![Vec3::new(0.0, 1.3, 0.0)]; // north pole
    for i in 1..n {
        let theta = std::f32::consts::PI * i as f32 / n as f32;
        for j in 0..m {
            let phi = std::f32::consts::TAU * j as f32 / m as f32;
            let r = 1.25 + 0.25 * (3.0 * phi + 2.0 * theta).sin() * (5.0 * theta).cos();
            vertices.push(
                r * Vec3::new(
                    theta.sin() * phi.cos(),
                    theta.cos(),
                    theta.sin() * phi.sin(),
                ),
            );
        }
    }
    vertices.push(Vec3::new(0.0, -1.1, 0.0)); // south pole
    let south = vertices.len() - 1;
    let ring = |i: usize, j: usize| 1 + (i - 1) * m + j % m;
    let mut tris = Vec::new();
    for j in 0..m {
        tris.push([0, ring(1, j + 1), ring(1, j)]);
        tris.push([south, ring(n - 1, j), ring(n - 1, j + 1)]);
        for i in 1..n - 1 {
            let (a, b, c, d) = (
                ring(i, j),
                ring(i, j + 1),
                ring(i + 1, j),
                ring(i + 1, j + 1),
            );
            tris.push([a, b, d]);
            tris.push([a, d, c]);
        }
    }
    (vertices, tris)
}

/// The mesh's triangles, and the rays from the origin aimed at every vertex and at
/// `per_edge` evenly spaced points inside every shared edge (1: the midpoints).
pub fn mesh_and_rays(
    (rings, segments): (usize, usize),
    per_edge: usize,
) -> Result<(Vec<Triangle>, Vec<Ray>)> {
    let (vertices, indices) = bumpy_sphere(rings, segments);
    let tris = indices
        .iter()
        .map(|&[a, b, c]| Triangle::new(vertices[a], vertices[b], vertices[c]))
        .collect::<Result<Vec<_>>>()?;
    let mut edges = std::collections::BTreeSet::new();
    for t in &indices {
        for k in 0..3 {
            edges.insert((t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3])));
        }
    }
    let mut targets = vertices.clone();
    for &(a, b) in &edges {
        for k in 1..=per_edge {
            let s = k as f32 / (per_edge + 1) as f32;
            targets.push(vertices[a].lerp(vertices[b], s));
        }
    }
    let rays = targets
        .iter()
        .map(|&target| Ray::new(Vec3::ZERO, target))
        .collect::<Result<Vec<_>>>()?;
    Ok((tris, rays))
}

/// The lessons' mesh: 16 rings of 16 segments.
pub const MESH: (usize, usize) = (16, 16);

/// A mesh of long thin triangles: 3 rings of 256 segments.
pub const SLIVERS: (usize, usize) = (3, 256);

/// Points along each edge: the midpoint only (quick), or seven.
fn per_edge(quality: Quality) -> usize {
    quality.pick(1, 7)
}

/// How many of `rays` hit no triangle of `tris` by `method`.
pub fn leaks(method: TriangleMethod, tris: &[Triangle], rays: &[Ray]) -> usize {
    rays.iter()
        .filter(|ray| !tris.iter().any(|t| method.hits(t, ray)))
        .count()
}

/// Each method's leak rate (share of the rays that hit no triangle) on the mesh, in
/// the order of [`TriangleMethod::ALL`] (no timing: this is what the tests check).
pub fn leak_rates(quality: Quality) -> Result<[f64; 3]> {
    let (tris, rays) = mesh_and_rays(MESH, per_edge(quality))?;
    Ok(TriangleMethod::ALL.map(|m| leaks(m, &tris, &rays) as f64 / rays.len() as f64))
}

/// Nanoseconds per ray/triangle test of each method, in the order of
/// [`TriangleMethod::ALL`]: each ray against every triangle, as in the leak count, the
/// total time divided by the number of tests; the fastest of a few rounds.
fn times(tris: &[Triangle], rays: &[Ray], quality: Quality) -> [f64; 3] {
    let calls = quality.pick(2, 10) * rays.len() as u32;
    let per_test = |method: TriangleMethod| {
        ns_per_call(calls, |i| {
            let ray = &rays[i as usize % rays.len()];
            tris.iter().filter(|t| method.hits(t, ray)).count()
        }) / tris.len() as f64
    };
    fastest(
        quality.pick(3, 5),
        [
            &mut || per_test(TriangleMethod::MollerTrumbore),
            &mut || per_test(TriangleMethod::MollerTrumboreEpsilon),
            &mut || per_test(TriangleMethod::Watertight),
        ],
    )
}

/// The methods not beaten by another on both counts (faster and leaking no more, or
/// leaking less and no slower).
fn pareto_front(points: &[(TriangleMethod, f64, f64)]) -> Vec<TriangleMethod> {
    points
        .iter()
        .filter(|&&(_, ns, leak)| {
            !points.iter().any(|&(_, ns2, leak2)| {
                ns2 <= ns && leak2 <= leak && (ns2 < ns || leak2 < leak)
            })
        })
        .map(|p| p.0)
        .collect()
}

/// The chart: one point per method, x its time per test, y its leak rate in percent
/// on a linear axis (the robust methods' 0 has no place on a log axis).
pub fn measure(quality: Quality) -> Result<Measured> {
    let (tris, rays) = mesh_and_rays(MESH, per_edge(quality))?;
    let ns = times(&tris, &rays, quality);
    let points: Vec<(TriangleMethod, f64, f64)> = TriangleMethod::ALL
        .iter()
        .zip(ns)
        .map(|(&m, ns)| {
            let leak = 100.0 * leaks(m, &tris, &rays) as f64 / rays.len() as f64;
            (m, ns, leak)
        })
        .collect();
    let mut chart = Chart::new(
        "Ray/triangle: time per test against leak rate",
        ("time per ray/triangle test (ns)", Scale::Linear),
        (
            "leak rate (% of rays at shared vertices/edges hitting nothing)",
            Scale::Linear,
        ),
    );
    for &(m, ns, leak) in &points {
        chart = chart.with(m.name(), vec![(ns, leak)]);
    }
    let front = pareto_front(&points);
    let front_names: Vec<&str> = front.iter().map(|m| m.name()).collect();
    let describe: Vec<String> = points
        .iter()
        .map(|(m, ns, leak)| format!("{} {ns:.1} ns, {leak:.2}%", m.name()))
        .collect();
    let BoxRejects {
        counts:
            BoxCounts {
                rays: cases,
                plain,
                conservative,
            },
        plain_ns,
        conservative_ns,
    } = box_rejects(quality)?;
    let (slivers, sliver_rays) = mesh_and_rays(SLIVERS, 1)?;
    let findings = vec![
        format!(
            "{} rays aimed exactly at the {} vertices and at points on the shared edges of a \
             closed mesh of {} triangles: {}",
            rays.len(),
            2 + (MESH.0 - 1) * MESH.1,
            tris.len(),
            describe.join("; ")
        ),
        format!(
            "Pareto front (no other method both faster and leaking less): {}{}",
            front_names.join(", "),
            if front.contains(&TriangleMethod::Watertight) {
                ""
            } else {
                " (on this mesh: see the mesh of slivers below)"
            }
        ),
        format!(
            "the epsilon is a guess, not a bound: on a closed mesh of slivers ({} x {} \
             segments, {} rays) the widened Möller-Trumbore leaks {:.2}%, watertight {:.2}%",
            SLIVERS.0,
            SLIVERS.1,
            sliver_rays.len(),
            100.0
                * leaks(
                    TriangleMethod::MollerTrumboreEpsilon,
                    &slivers,
                    &sliver_rays
                ) as f64
                / sliver_rays.len() as f64,
            100.0 * leaks(TriangleMethod::Watertight, &slivers, &sliver_rays) as f64
                / sliver_rays.len() as f64,
        ),
        format!(
            "S6, box around the triangle, rays at its vertices: plain slab rejects {plain} of \
             {cases} ({:.1}%, {plain_ns:.1} ns), conservative slab {conservative} \
             ({conservative_ns:.1} ns)",
            100.0 * plain as f64 / cases.max(1) as f64
        ),
    ];
    let quoted =
        exact_quoted(quality)?.merge(quoted_times(ns, plain_ns, conservative_ns));
    Ok(Measured {
        chart,
        findings,
        quoted,
    })
}
