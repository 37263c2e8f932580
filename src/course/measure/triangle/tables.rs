//! The tables the book quotes from chart 11.2: the leaks of each ray/triangle test
//! (S4, S5, the slivers) and the S6 box rejections, exact and measured without a
//! clock; and the times, which only the lesson measures.

use super::boxes::{BoxCounts, box_cases, box_counts};
use super::{
    MESH, SLIVERS, TriangleMethod, bumpy_sphere, leaks, mesh_and_rays, per_edge,
};
use crate::course::measure::Quality;
use crate::course::report::{BookNumbers, Quoted};
use crate::error::Result;
use crate::ray::Ray;
use crate::shapes::Triangle;

/// `k` of `n` as "k (p%)".
fn share(k: usize, n: usize) -> String {
    format!("{k} ({:.2}%)", 100.0 * k as f64 / n.max(1) as f64)
}

/// The exact numbers the book quotes from chart 2, measured at `quality` (no
/// timing): table `leaks`, each method's leaks on the rays at the lesson mesh's
/// vertices (S4), at its edge midpoints (S5), on the chart's whole ray set and on
/// the mesh of slivers; table `boxes`, the S6 rejections of both slab tests.
pub fn exact_quoted(quality: Quality) -> Result<BookNumbers> {
    let (vertices, _) = bumpy_sphere(MESH.0, MESH.1);
    let (tris, midpoint_rays) = mesh_and_rays(MESH, 1)?;
    let (at_vertices, at_midpoints) = midpoint_rays.split_at(vertices.len());
    let (_, chart_rays) = mesh_and_rays(MESH, per_edge(quality))?;
    let (slivers, sliver_rays) = mesh_and_rays(SLIVERS, 1)?;
    let mut leaks_table = Quoted::new(
        "leaks",
        false,
        &[
            "rays aimed at",
            "rays",
            "Möller-Trumbore",
            "widened by 1e-6",
            "watertight",
        ],
    );
    let sets: [(String, &[Triangle], &[Ray]); 4] = [
        ("vertices (S4)".into(), &tris, at_vertices),
        ("edge midpoints (S5)".into(), &tris, at_midpoints),
        (
            format!("vertices + {} per edge", per_edge(quality)),
            &tris,
            &chart_rays,
        ),
        ("a mesh of slivers".into(), &slivers, &sliver_rays),
    ];
    for (name, tris, rays) in sets {
        let mut cells = vec![name, rays.len().to_string()];
        cells.extend(
            TriangleMethod::ALL.map(|m| share(leaks(m, tris, rays), rays.len())),
        );
        leaks_table = leaks_table.row(cells);
    }
    let BoxCounts {
        rays: cases,
        plain,
        conservative,
    } = box_counts(&box_cases(quality)?);
    let boxes = Quoted::new(
        "boxes",
        false,
        &["slab test", "rays at a vertex", "rejected"],
    )
    .row(vec!["plain".into(), cases.to_string(), share(plain, cases)])
    .row(vec![
        "conservative".into(),
        cases.to_string(),
        share(conservative, cases),
    ]);
    Ok(BookNumbers::default().table(leaks_table).table(boxes))
}

/// The times the book quotes from chart 2: table `times` (each triangle test, and
/// both slab tests, with the ratio to the naive one), and the rows `cost` for the
/// cost table of "Where methods fail".
pub(super) fn quoted_times(
    ns: [f64; 3],
    plain_ns: f64,
    conservative_ns: f64,
) -> BookNumbers {
    let mut times =
        Quoted::new("times", true, &["test", "ns per test", "x the naive test"]);
    for (m, t) in TriangleMethod::ALL.iter().zip(ns) {
        times = times.row(vec![
            m.name().to_string(),
            format!("{t:.1}"),
            format!("{:.2}", t / ns[0]),
        ]);
    }
    times = times
        .row(vec![
            "plain slab (S6)".into(),
            format!("{plain_ns:.1}"),
            "1.00".into(),
        ])
        .row(vec![
            "conservative slab (S6)".into(),
            format!("{conservative_ns:.1}"),
            format!("{:.2}", conservative_ns / plain_ns),
        ]);
    let cost = Quoted::new(
        "cost",
        true,
        &["case", "naive / robust", "ns per test", "robust / naive"],
    )
    .row(vec![
        "S4, S5".into(),
        "Möller-Trumbore / watertight".into(),
        format!("{:.1} / {:.1}", ns[0], ns[2]),
        format!("{:.2}x", ns[2] / ns[0]),
    ])
    .row(vec![
        "S6".into(),
        "plain / conservative slab".into(),
        format!("{plain_ns:.1} / {conservative_ns:.1}"),
        format!("{:.2}x", conservative_ns / plain_ns),
    ]);
    BookNumbers::default().table(times).table(cost)
}
