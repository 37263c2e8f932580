//! The table of a scene as triangles (lesson 09 prints it): vertices and triangles
//! of each tessellated object, their total, and the mesh read from a file.

use crate::course::report::{Table, num};
use crate::mesh::Model;
use crate::scenes::PlacedMesh;

/// One row per object of `instances` (named by `names`) with its vertices and
/// triangles, a row of the total, and a row for `mesh`, read from `file`: how often
/// it was subdivided, what reading it did to its faces, and the triangles its
/// placement left out ([`crate::scenes::placement::bulk`]).
pub fn triangle_table(
    names: &[&str],
    instances: &[Model],
    mesh: &PlacedMesh,
    file: &str,
) -> Table {
    let columns = ["object", "vertices", "triangles"];
    let mut table = Table::new("The scene as triangles", &columns);
    let mut total = 0;
    for (name, i) in names.iter().zip(instances) {
        let (v, t) = (i.mesh.positions.len(), i.mesh.triangles.len());
        total += t;
        table.row(vec![name.to_string(), v.to_string(), t.to_string()]);
    }
    table.row(vec!["all".into(), String::new(), total.to_string()]);
    let m = &mesh.model.mesh;
    let (v, t) = (m.positions.len(), m.triangles.len());
    let split = match mesh.subdivisions {
        0 => String::new(),
        n => format!(" subdivided {n} times"),
    };
    let read = match mesh.counts.to_string() {
        c if c.is_empty() => c,
        c => format!("; {c}"),
    };
    let fit = &mesh.fit;
    let left_out = match fit.left_out {
        0 => String::new(),
        n => {
            let percent = match 100.0 * fit.left_out_area {
                p if p < 0.005 => "under 0.01".to_string(),
                p => num(p, 2),
            };
            format!(
                "; fitted without {n} triangles far from the rest ({percent} % of the area)"
            )
        }
    };
    let textured = if mesh.model.texture.is_some() {
        ", textured"
    } else {
        ""
    };
    let name = format!("mesh ({file}{split}, smooth{textured}{read}{left_out})");
    table.row(vec![name, v.to_string(), t.to_string()]);
    table
}
