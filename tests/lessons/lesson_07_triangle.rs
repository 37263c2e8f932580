//! Lesson 07, the triangle (chapter 07_4): known answers for Möller-Trumbore and the
//! watertight test, a closed mesh that the watertight test never leaks through and
//! Möller-Trumbore does (STABILITY S4, S5), and the barycentric hit point that stays
//! on the plane where o + t d does not (S7).

use crate::common::{self, ray};
use render_lessons::course::measure::triangle::bumpy_sphere;

use glam::Vec3;
use render_lessons::ray::{Interval, Ray};
use render_lessons::shapes::{Barycentric, Shape, Triangle};

// ---------------------------------------------------------------- triangle

/// How many of the rays from the origin towards `targets` hit no triangle at all, for
/// Möller-Trumbore and for the watertight test.
fn leaks(tris: &[Triangle], targets: &[Vec3]) -> (usize, usize) {
    let (mut mt, mut wt) = (0, 0);
    for &target in targets {
        let r = Ray::new(Vec3::ZERO, target).unwrap();
        mt += usize::from(
            !tris
                .iter()
                .any(|t| t.moller_trumbore(&r, Interval::AHEAD).is_some()),
        );
        wt += usize::from(
            !tris
                .iter()
                .any(|t| t.watertight(&r, Interval::AHEAD).is_some()),
        );
    }
    (mt, wt)
}

fn mesh_triangles() -> (Vec<Vec3>, Vec<[usize; 3]>, Vec<Triangle>) {
    let (vertices, indices) = bumpy_sphere(16, 16);
    let tris = indices
        .iter()
        .map(|&[a, b, c]| Triangle::new(vertices[a], vertices[b], vertices[c]).unwrap())
        .collect();
    (vertices, indices, tris)
}

#[test]
fn bumpy_sphere_is_closed_and_outward() {
    let (vertices, indices, tris) = mesh_triangles();
    assert_eq!(vertices.len(), 2 + 15 * 16);
    assert_eq!(tris.len(), 2 * 16 * 15);
    let mut edges = std::collections::HashMap::new();
    for t in &indices {
        for k in 0..3 {
            *edges
                .entry((t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3])))
                .or_insert(0) += 1;
        }
    }
    assert!(
        edges.values().all(|&c| c == 2),
        "every edge shared by exactly two triangles"
    );
    for t in &tris {
        let centroid = t.vertices().iter().sum::<Vec3>() / 3.0;
        assert!(t.normal().dot(centroid) > 0.0, "wound outwards");
    }
    for v in &vertices {
        assert!((1.0..=1.5).contains(&v.length()));
    }
}

#[test]
fn s4_s5_watertight_never_leaks_moller_trumbore_does() {
    let (vertices, indices, tris) = mesh_triangles();
    let (mt_v, wt_v) = leaks(&tris, &vertices);
    let mut edges = std::collections::BTreeSet::new();
    for t in &indices {
        for k in 0..3 {
            edges.insert((t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3])));
        }
    }
    let midpoints: Vec<Vec3> = edges
        .iter()
        .map(|&(a, b)| (vertices[a] + vertices[b]) * 0.5)
        .collect();
    let (mt_e, wt_e) = leaks(&tris, &midpoints);
    let pct = |k: usize, n: usize| 100.0 * k as f64 / n as f64;
    eprintln!(
        "S4 vertices: {} rays, Möller-Trumbore leaks {mt_v} ({:.1}%), watertight {wt_v}",
        vertices.len(),
        pct(mt_v, vertices.len())
    );
    eprintln!(
        "S5 edge midpoints: {} rays, Möller-Trumbore leaks {mt_e} ({:.1}%), watertight {wt_e}",
        midpoints.len(),
        pct(mt_e, midpoints.len())
    );
    assert_eq!(wt_v, 0);
    assert_eq!(wt_e, 0);
    assert!(
        pct(mt_v, vertices.len()) > 1.0,
        "Möller-Trumbore should leak at vertices"
    );
    assert!(
        pct(mt_e, midpoints.len()) > 1.0,
        "Möller-Trumbore should leak at edges"
    );
}

#[test]
fn triangle_known_answers() {
    // The unit right triangle in z = 0, seen from z = 5 looking down -z.
    let t = Triangle::new(Vec3::ZERO, Vec3::X, Vec3::Y).unwrap();
    let r = ray([0.25, 0.5, 5.0], [0.0, 0.0, -1.0]);
    // b1 = x = 0.25, b2 = y = 0.5, b0 = 0.25, t = 5.
    let crossing = Barycentric {
        t: 5.0,
        b: [0.25, 0.25, 0.5],
    };
    assert_eq!(t.moller_trumbore(&r, Interval::AHEAD), Some(crossing));
    assert_eq!(t.watertight(&r, Interval::AHEAD), Some(crossing));
    let h = t.hit(&r, Interval::AHEAD).unwrap();
    assert_eq!(h.point, Vec3::new(0.25, 0.5, 0.0));
    assert_eq!(h.normal, Vec3::Z);
    assert!(h.front_face);
    // Outside (x + y > 1), behind, and parallel: misses.
    let outside = ray([0.75, 0.5, 5.0], [0.0, 0.0, -1.0]);
    let behind = ray([0.25, 0.5, 5.0], [0.0, 0.0, 1.0]);
    let parallel = ray([0.25, 0.25, 0.0], [1.0, 0.0, 0.0]);
    for r in [outside, behind, parallel] {
        assert!(t.moller_trumbore(&r, Interval::AHEAD).is_none());
        assert!(t.watertight(&r, Interval::AHEAD).is_none());
        assert!(Shape::Triangle(t).hit(&r, Interval::AHEAD).is_none());
    }
    // From below: back face, normal still +z.
    let h = t
        .hit(&ray([0.25, 0.5, -5.0], [0.0, 0.0, 1.0]), Interval::AHEAD)
        .unwrap();
    assert!(!h.front_face);
    assert_eq!(h.normal, Vec3::Z);
}

#[test]
fn s7_barycentric_point_stays_on_the_plane() {
    // The unit triangle in the plane x + y + z = 1, hit from distance about 1e4.
    let t = Triangle::new(Vec3::X, Vec3::Y, Vec3::Z).unwrap();
    let off_plane =
        |p: Vec3| ((p.x as f64 + p.y as f64 + p.z as f64) - 1.0).abs() / 3f64.sqrt();
    let mut rng = common::Rng::seeded(0x9E37_79B9_7F4A_7C15);
    let (mut bary, mut ray_point) = (Vec::new(), Vec::new());
    for _ in 0..1000 {
        let (u, v) = (rng.next_f32(), rng.next_f32());
        let (u, v) = if u + v > 1.0 {
            (1.0 - u, 1.0 - v)
        } else {
            (u, v)
        };
        let aim = (1.0 - u - v) * Vec3::X + u * Vec3::Y + v * Vec3::Z;
        let dir =
            Vec3::new(rng.next_f32() - 0.5, rng.next_f32() - 0.5, 0.0) + Vec3::ONE;
        let o = aim + 1e4 * dir.normalize();
        let r = Ray::new(o, aim - o).unwrap();
        if let Some(h) = t.hit(&r, Interval::AHEAD) {
            bary.push(off_plane(h.point));
            ray_point.push(off_plane(r.at(h.t)));
        }
    }
    assert!(
        bary.len() > 900,
        "most rays aimed inside should hit: {}",
        bary.len()
    );
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let (bary_max, ray_max) = (
        bary.iter().cloned().fold(0.0, f64::max),
        ray_point.iter().cloned().fold(0.0, f64::max),
    );
    let (bary_med, ray_med) = (median(&mut bary), median(&mut ray_point));
    eprintln!(
        "S7: barycentric off-plane median {bary_med:.1e} max {bary_max:.1e}; o + t d median {ray_med:.1e} max {ray_max:.1e}"
    );
    assert!(
        bary_max < 1e-6,
        "barycentric point off the plane by {bary_max}"
    );
    assert!(
        ray_med > 1e-5,
        "o + t d should be visibly off the plane: {ray_med}"
    );
    assert!(ray_med > 100.0 * bary_med.max(1e-9));
    // The numbers the S7 pages print: o + t d's median and worst distance from the
    // plane, then the barycentric point's (no sine or cosine: the same everywhere).
    let printed = format!("{ray_med:.1e} {ray_max:.1e} {bary_med:.1e} {bary_max:.1e}");
    assert_eq!(printed, "2.8e-4 2.3e-3 9.7e-9 4.3e-8");
    // "About 29 000 times closer": the ratio of the two medians, to two digits.
    let ratio = format!("{:.1e}", ray_med / bary_med);
    assert!(ratio == "2.8e4" || ratio == "2.9e4", "{ratio}");
    let printed_ratio = 2.8e-4 / 9.7e-9;
    assert_eq!((printed_ratio / 1000.0f64).round() * 1000.0, 29_000.0);
    // The exercise on S6's conservative slab: gamma_3, the factor 1 + 2 gamma_3, and
    // how far it moves a t_far of 100.
    let g3 = render_lessons::float::gamma(3);
    assert_eq!(
        format!("{g3:.2e} {:.1e} {:.1e}", 2.0 * g3, 200.0 * g3),
        "1.79e-7 3.6e-7 3.6e-5"
    );
}

/// Woop, Benthin and Wald's test written out corner by corner, in scalar f32 as the
/// paper prints it, over the whole line (no range: no t bound, no early rejection):
/// `Some((t, b))` where all three edge functions have one sign and det is not 0.
fn watertight_by_the_formula(tri: &Triangle, r: &Ray) -> Option<(f32, [f32; 3])> {
    let (o, d) = (r.origin(), r.direction());
    let kz = d.abs().max_position();
    let (kx, ky) = ((kz + 1) % 3, (kz + 2) % 3);
    let (sx, sy, sz) = (-d[kx] / d[kz], -d[ky] / d[kz], 1.0 / d[kz]);
    let p = tri.vertices().map(|v| {
        let v = v - o;
        (v[kx] + sx * v[kz], v[ky] + sy * v[kz], v[kz])
    });
    let edge = |a: usize, b: usize| {
        let ((ax, ay, _), (bx, by, _)) = (p[a], p[b]);
        ax * by - ay * bx
    };
    let edge_f64 = |a: usize, b: usize| {
        let ((ax, ay, _), (bx, by, _)) = (p[a], p[b]);
        (ax as f64 * by as f64 - ay as f64 * bx as f64) as f32
    };
    let mut e = [edge(1, 2), edge(2, 0), edge(0, 1)];
    if e.contains(&0.0) {
        // An exact 0 sends all three to f64, where each product is exact.
        e = [edge_f64(1, 2), edge_f64(2, 0), edge_f64(0, 1)];
    }
    let det = e[0] + e[1] + e[2];
    let signs = (e.iter().any(|&x| x < 0.0), e.iter().any(|&x| x > 0.0));
    if signs == (true, true) || det == 0.0 {
        return None;
    }
    let z = p.map(|(_, _, z)| z * sz);
    let t_scaled = e[0] * z[0] + e[1] * z[1] + e[2] * z[2];
    let inv = 1.0 / det;
    let b = e.map(|x| x * inv);
    let t = t_scaled * inv;
    (b.iter().all(|x| x.is_finite()) && t.is_finite()).then_some((t, b))
}

/// The library's watertight test keeps the three corners in the lanes of 4-wide
/// vectors (chapter 07_4); lane by lane it must do the formula's arithmetic, so it
/// gives the formula's t and barycentrics bit for bit, hit or miss, for random
/// triangles and rays, rays aimed at corners and edges (where an edge function is 0
/// and f64 decides), and rays along each axis (every permutation of the axes).
#[test]
fn watertight_lanes_are_the_formula_bit_for_bit() {
    let mut rng = common::Rng::seeded(0x0074_1a7e);
    let mut next = || 4.0 * rng.next_f32() - 2.0;
    let (mut hits, mut compared) = (0, 0);
    for n in 0..20_000 {
        let mut point = || Vec3::new(next(), next(), next());
        let Ok(tri) = Triangle::new(point(), point(), point()) else {
            continue;
        };
        let o = point();
        let [v0, v1, v2] = tri.vertices();
        let target = match n % 4 {
            0 => v0,              // a corner
            1 => (v1 + v2) * 0.5, // an edge
            _ => (v0 + v1 + v2) / 3.0 + point() * 0.5,
        };
        let mut d = target - o;
        if n % 7 == 0 {
            d[n % 3] = 0.0; // in a coordinate plane
        }
        let Ok(r) = Ray::new(o, d) else {
            continue;
        };
        let lanes = tri
            .watertight(&r, Interval::EVERYWHERE)
            .map(|c| (c.t.to_bits(), c.b.map(f32::to_bits)));
        let formula = watertight_by_the_formula(&tri, &r)
            .map(|(t, b)| (t.to_bits(), b.map(f32::to_bits)));
        assert_eq!(lanes, formula, "triangle {tri:?}, ray {r:?}");
        compared += 1;
        hits += usize::from(lanes.is_some());
    }
    assert!(
        compared > 19_000 && hits > 5_000,
        "{compared} compared, {hits} hits"
    );
}
