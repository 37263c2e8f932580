//! Subdivision: every triangle split in four at the midpoints of its edges. The
//! surface keeps its shape (the new triangles lie in the old ones' planes); only the
//! count grows, by 4 per level, which is what a lesson needs to try its renderers
//! on a mesh of a million triangles made from a small file.

use std::collections::HashMap;

use super::Mesh;
use crate::error::{Error, Result, Shortfall};

/// The most levels [`Mesh::subdivided`] takes: 4^10, about a million times the
/// triangles.
pub const MAX_SUBDIVISIONS: u32 = 10;

/// `levels` if it is at most [`MAX_SUBDIVISIONS`]; the error names `param`.
pub fn check_subdivisions(param: &'static str, levels: u32) -> Result<u32> {
    if levels <= MAX_SUBDIVISIONS {
        Ok(levels)
    } else {
        Err(Error::Machine {
            param,
            shortfall: Shortfall::TooMuch {
                needed: u64::from(levels),
                limit: u64::from(MAX_SUBDIVISIONS),
                unit: "levels",
            },
        })
    }
}

/// The number of triangles after `levels` subdivisions of `triangles`: times
/// 4^levels, saturating instead of overflowing.
pub fn subdivided_count(triangles: usize, levels: u32) -> u64 {
    (triangles as u64).saturating_mul(4u64.saturating_pow(levels))
}

impl Mesh {
    // ANCHOR: subdivided
    /// The mesh with every triangle split in four, `levels` times. A triangle
    /// (a, b, c) whose edges have the midpoints ab, bc and ca becomes (a, ab, ca),
    /// (ab, b, bc), (ca, bc, c) and (ab, bc, ca), each turning the way (a, b, c)
    /// turns. A midpoint is made once per edge and shared by the two triangles of
    /// the edge, so a closed mesh stays closed; its normal is the normalised sum of
    /// the edge's two vertex normals, its texture coordinates their mean.
    pub fn subdivided(&self, levels: u32) -> Result<Mesh> {
        check_subdivisions("subdivide", levels)?;
        let count = subdivided_count(self.triangles.len(), levels);
        // Every edge adds at most one vertex: at most 3 x the triangles in all.
        if count.saturating_mul(3) > u64::from(u32::MAX) {
            return Err(Error::Machine {
                param: "subdivide",
                shortfall: Shortfall::TooMuch {
                    needed: count,
                    limit: u64::from(u32::MAX) / 3,
                    unit: "triangles",
                },
            });
        }
        let mut mesh = self.clone();
        for _ in 0..levels {
            mesh = mesh.split_in_four();
        }
        Ok(mesh)
    }
    // ANCHOR_END: subdivided

    /// One level of [`Mesh::subdivided`].
    fn split_in_four(&self) -> Mesh {
        let mut positions = self.positions.clone();
        let mut normals = self.normals.clone();
        let mut uvs = self.uvs.clone();
        let mut midpoints: HashMap<(u32, u32), u32> = HashMap::new();
        let mut midpoint = |a: u32, b: u32| {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                let (i, j) = (a as usize, b as usize);
                positions.push((positions[i] + positions[j]) * 0.5);
                normals.push((normals[i] + normals[j]).normalize_or_zero());
                if !uvs.is_empty() {
                    uvs.push((uvs[i] + uvs[j]) * 0.5);
                }
                (positions.len() - 1) as u32
            })
        };
        let mut triangles = Vec::with_capacity(4 * self.triangles.len());
        for &[a, b, c] in &self.triangles {
            let (ab, bc, ca) = (midpoint(a, b), midpoint(b, c), midpoint(c, a));
            triangles.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        Mesh {
            positions,
            normals,
            uvs,
            triangles,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn a_square_split_twice_has_32_triangles_on_the_same_plane() {
        let square = Mesh::floor(Vec3::ZERO, 2.0).unwrap();
        let fine = square.subdivided(2).unwrap();
        assert_eq!(fine.triangles.len(), 32);
        // 4 corners, 5 edges -> 9 vertices, then 25: a 5 x 5 grid.
        assert_eq!(fine.positions.len(), 25);
        assert!(fine.positions.iter().all(|p| p.y == 0.0));
        assert!(fine.normals.iter().all(|&n| n == Vec3::Y));
        assert_eq!(fine.degenerate(), 0);
        let area = |m: &Mesh| -> f32 {
            let t = m.triangles.iter();
            t.map(|t| t.map(|i| m.positions[i as usize]))
                .map(|[a, b, c]| (b - a).cross(c - a).length() / 2.0)
                .sum()
        };
        assert!((area(&fine) - area(&square)).abs() < 1e-5);
    }

    #[test]
    fn too_many_levels_are_refused() {
        let square = Mesh::floor(Vec3::ZERO, 2.0).unwrap();
        assert_eq!(square.subdivided(0).unwrap(), square);
        let err = square.subdivided(MAX_SUBDIVISIONS + 1).unwrap_err();
        assert_eq!(err.param(), "subdivide");
    }
}
