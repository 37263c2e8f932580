//! A polygon cut into triangles by ear clipping. The faces of a model's file have any
//! number of corners, convex or not, and the renderers draw triangles only.

use glam::DVec3;

/// A face that ear clipping cannot cut: a whole turn round its corners found no
/// ear, which a simple polygon always has, so its edges cross.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NotSimple;

// ANCHOR: ear_clip
/// Cuts the polygon whose corners are `corners` (indices into `positions`, in
/// order) into triangles by ear clipping: appends to `triangles` those with an
/// area, each turning the way the polygon turns, and returns how many had none.
///
/// An *ear* is a corner b whose triangle (a, b, c) with its two neighbours turns
/// the way the polygon turns and holds no other corner: cutting it off leaves a
/// polygon of one corner fewer. Every simple polygon of four corners or more has
/// two ears (G. H. Meisters, "Polygons have ears", American Mathematical Monthly
/// 82, 1975), so cutting ears one at a time ends in one triangle (D. Eberly,
/// "Triangulation by Ear Clipping", Geometric Tools, 2002). The way the polygon
/// turns is its normal by Newell's method, n = sum of (p_i - p_0) x (p_i+1 - p_0)
/// (F. Tampieri, Graphics Gems III, 1992), which also serves a face that is not
/// quite flat. A corner whose triangle has no area (a repeated corner, or three on
/// a line) is cut off as it comes, and counted.
///
/// The search starts at the second corner and goes on from the corner after each
/// cut, so a convex polygon becomes the fan round its first corner: a quad a b c d
/// becomes a b c and a c d. Fails when a whole turn finds no ear.
pub fn ear_clip(
    corners: &[u32],
    positions: &[DVec3],
    triangles: &mut Vec<[u32; 3]>,
) -> Result<usize, NotSimple> {
    let at = |k: usize| positions[corners[k] as usize];
    let normal = (1..corners.len().saturating_sub(1))
        .map(|k| (at(k) - at(0)).cross(at(k + 1) - at(0)))
        .sum::<DVec3>();
    let mut ring: Vec<usize> = (0..corners.len()).collect();
    let (mut without_area, mut k, mut tried) = (0, 1, 0);
    while ring.len() > 3 {
        let n = ring.len();
        k %= n;
        let ear = [ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n]];
        let [a, b, c] = ear.map(at);
        let cross = (b - a).cross(c - a);
        let holds = |&r: &usize| {
            let p = at(r);
            ![a, b, c].contains(&p) && inside(p, [a, b, c], normal)
        };
        if cross == DVec3::ZERO || (cross.dot(normal) > 0.0 && !ring.iter().any(holds))
        {
            without_area += usize::from(cross == DVec3::ZERO);
            if cross != DVec3::ZERO {
                triangles.push(ear.map(|r| corners[r]));
            }
            ring.remove(k);
            tried = 0;
        } else {
            (k, tried) = (k + 1, tried + 1);
            if tried == n {
                return Err(NotSimple);
            }
        }
    }
    let last = [ring[0], ring[1], ring[2]];
    let [a, b, c] = last.map(at);
    if (b - a).cross(c - a) == DVec3::ZERO {
        return Ok(without_area + 1);
    }
    triangles.push(last.map(|r| corners[r]));
    Ok(without_area)
}
// ANCHOR_END: ear_clip

/// Whether `p` lies in the triangle `t` or on its edges, seen along `normal`: on
/// the inner side of each of the three edges.
fn inside(p: DVec3, [a, b, c]: [DVec3; 3], normal: DVec3) -> bool {
    [(a, b), (b, c), (c, a)]
        .iter()
        .all(|&(from, to)| (to - from).cross(p - from).dot(normal) >= 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cut(corners: &[(f64, f64)]) -> (Result<usize, NotSimple>, Vec<[u32; 3]>) {
        let positions: Vec<DVec3> = corners
            .iter()
            .map(|&(x, y)| DVec3::new(x, y, 0.0))
            .collect();
        let order: Vec<u32> = (0..corners.len() as u32).collect();
        let mut triangles = Vec::new();
        (ear_clip(&order, &positions, &mut triangles), triangles)
    }

    /// Twice the signed area of the polygon (shoelace formula) and of the triangles.
    fn areas(corners: &[(f64, f64)], triangles: &[[u32; 3]]) -> (f64, f64) {
        let n = corners.len();
        let polygon = (0..n)
            .map(|k| {
                let ((x0, y0), (x1, y1)) = (corners[k], corners[(k + 1) % n]);
                x0 * y1 - x1 * y0
            })
            .sum();
        let cut = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| corners[i as usize]);
                (b.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (b.1 - a.1)
            })
            .sum();
        (polygon, cut)
    }

    #[test]
    fn a_convex_polygon_becomes_the_fan_round_its_first_corner() {
        let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        assert_eq!(cut(&square), (Ok(0), vec![[0, 1, 2], [0, 2, 3]]));
        let pentagon = [(3.0, 0.0), (4.0, 0.0), (4.3, 1.0), (3.5, 1.6), (2.7, 1.0)];
        let fan = vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]];
        assert_eq!(cut(&pentagon), (Ok(0), fan));
    }

    #[test]
    fn an_l_whose_first_corner_is_the_inner_one_is_covered_exactly() {
        // The fan round the reflex corner (1, 1) would stick out of the L.
        let l = [
            (1.0, 1.0),
            (0.0, 1.0),
            (0.0, 0.0),
            (2.0, 0.0),
            (2.0, 2.0),
            (1.0, 2.0),
        ];
        let (skipped, triangles) = cut(&l);
        assert_eq!(skipped, Ok(0));
        assert_eq!(triangles.len(), 4);
        let (polygon, cut) = areas(&l, &triangles);
        assert_eq!((polygon, cut), (6.0, 6.0));
        assert!(areas(&l, &[[0, 1, 2]]).1 > 0.0);
    }

    #[test]
    fn a_star_is_covered_by_triangles_that_all_turn_its_way() {
        // Ten corners, alternately at radius 1 and 0.4.
        let star: Vec<(f64, f64)> = (0..10)
            .map(|k| {
                let r = if k % 2 == 0 { 1.0 } else { 0.4 };
                let t = std::f64::consts::PI * k as f64 / 5.0;
                (r * t.cos(), r * t.sin())
            })
            .collect();
        let (skipped, triangles) = cut(&star);
        assert_eq!((skipped, triangles.len()), (Ok(0), 8));
        let (polygon, cut) = areas(&star, &triangles);
        assert!((polygon - cut).abs() < 1e-12, "{polygon} {cut}");
        for t in &triangles {
            assert!(areas(&star, &[*t]).1 > 0.0, "{t:?}");
        }
    }

    #[test]
    fn corners_without_area_are_cut_off_and_counted() {
        // A quad with its first corner twice (a pole of the teapot): one triangle.
        let positions = [DVec3::ZERO, DVec3::X, DVec3::Y];
        let mut triangles = Vec::new();
        assert_eq!(ear_clip(&[0, 0, 1, 2], &positions, &mut triangles), Ok(1));
        assert_eq!(triangles, [[0, 1, 2]]);
        // Four corners on a line: two triangles, neither with an area.
        let line = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.0)];
        assert_eq!(cut(&line), (Ok(2), vec![]));
    }

    #[test]
    fn a_polygon_whose_edges_cross_is_refused() {
        // A bow tie: its two halves turn opposite ways, so it turns neither way and
        // no corner is an ear.
        let crossed = [(0.0, 0.0), (2.0, 2.0), (2.0, 0.0), (0.0, 2.0)];
        assert_eq!(cut(&crossed).0, Err(NotSimple));
    }
}
