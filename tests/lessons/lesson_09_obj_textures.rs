//! Lesson 09, textured models from files (issue 32): an OBJ file's normals (`vn`),
//! texture coordinates (`vt`) and material texture (`mtllib`, `usemtl`, `map_Kd`),
//! read as tinyrenderer's models write them (`f v/vt/vn`, a TGA texture). The
//! models are small equivalents written here: tinyrenderer's head may be used as
//! an example of a renderer, not shared by this one (its readme), so lesson 09
//! takes it by path (`--mesh ... --texture ...`).

use std::path::{Path, PathBuf};

use glam::{Vec2, Vec3};
use render_lessons::error::Error;
use render_lessons::mesh::{LoadedMesh, Mesh};
use render_lessons::scenes::still_life_shadows;
use render_lessons::scenes::{Up, mesh_on_the_floor, still_life, still_life_pinhole};
use render_lessons::texture::{Texture, from_srgb8};

use crate::examples::rasterization as lesson;
use crate::lesson_09_textures::tga;

/// A scratch folder, and a function that writes `bytes` to a file of it.
fn scratch() -> (tempfile::TempDir, impl Fn(&str, &[u8]) -> PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path().to_path_buf();
    (dir, move |name: &str, bytes: &[u8]| {
        let path = root.join(name);
        std::fs::write(&path, bytes).unwrap();
        path
    })
}

/// A 2 x 2 checker of two colours, as 8-bit sRGB codes, saved as a run-length
/// encoded TGA file, as tinyrenderer's textures are.
const DARK: [u8; 3] = [40, 60, 160];
const BRIGHT: [u8; 3] = [230, 200, 80];

fn write_checker(path: &Path) {
    let rows = vec![vec![DARK, BRIGHT], vec![BRIGHT, DARK]];
    std::fs::write(path, tga(&rows, true)).unwrap();
}

/// A unit square in z = 0 as tinyrenderer writes a model: positions, texture
/// coordinates with a third number, normals that lean (not the face's), one quad
/// face naming all three per corner, its material's texture in a library.
const SQUARE: &str = "\
mtllib square.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt  0.0 0.0 0.000
vt  1.0 0.0 0.000
vt  1.0 1.0 0.000
vt  0.0 1.0 0.000
vn -1 -1 1
vn 1 -1 1
vn 1 1 1
vn -1 1 1
g square
s 1
usemtl checker
f 1/1/1 2/2/2 3/3/3 4/4/4
";

const LIBRARY: &str = "\
newmtl other
Kd 1 0 0
newmtl checker
Kd 0.8 0.8 0.8
map_Kd -s 1 1 1 checker.tga
";

fn load(path: &Path) -> LoadedMesh {
    Mesh::from_obj(path).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_textured_obj_keeps_its_normals_texture_coordinates_and_texture() {
    let (_dir, write) = scratch();
    let obj = write("square.obj", SQUARE.as_bytes());
    write("square.mtl", LIBRARY.as_bytes());
    write_checker(&obj.with_file_name("checker.tga"));
    let loaded = load(&obj);
    let mesh = &loaded.mesh;
    assert_eq!(mesh.triangles, [[0, 1, 2], [0, 2, 3]]);
    assert_eq!(
        mesh.positions,
        [Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y]
    );
    assert_eq!(mesh.uvs, [Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y]);
    // The file's normals, made unit: (+-1, +-1, 1) / sqrt 3.
    let expected = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
        .map(|(x, y)| Vec3::new(x, y, 1.0) / 3f32.sqrt());
    for (n, e) in mesh.normals.iter().zip(expected) {
        assert!((*n - e).length() < 1e-6, "{n} {e}");
    }
    // The material's texture, beside its library, and read as sRGB.
    let texture_path = loaded.texture.clone().unwrap();
    assert_eq!(texture_path, obj.with_file_name("checker.tga"));
    let texture = Texture::read(&texture_path).unwrap();
    assert_eq!(texture.texel(0, 0), Vec3::from(DARK.map(from_srgb8)));
    assert_eq!(texture.texel(1, 0), Vec3::from(BRIGHT.map(from_srgb8)));
}

/// A position used with two texture coordinates (a seam, where a texture's image
/// is cut open) becomes two vertices; a corner written `v//vn` or with negative
/// numbers names the same attributes; a file whose corners do not all have texture
/// coordinates gets none, and its normals are the triangles' average.
#[test]
fn seams_split_vertices_and_partial_attributes_are_left_out() {
    let (_dir, write) = scratch();
    // Two triangles sharing the edge 1-3; across it, vertex 3 has another (u, v).
    let seam = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
                vt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 0.5\nvt 0 1\n\
                f 1/1 2/2 3/3\nf -4/-5 -2/-2 -1/-1\n";
    let mesh = load(&write("seam.obj", seam.as_bytes())).mesh;
    assert_eq!(mesh.positions.len(), 5, "vertex 3 twice");
    assert_eq!(mesh.triangles.len(), 2);
    let uv_of = |p: Vec3| {
        let at: Vec<Vec2> = (0..mesh.positions.len())
            .filter(|&i| mesh.positions[i] == p)
            .map(|i| mesh.uvs[i])
            .collect();
        at
    };
    assert_eq!(
        uv_of(Vec3::new(1.0, 1.0, 0.0)),
        [Vec2::ONE, Vec2::splat(0.5)]
    );
    assert_eq!(uv_of(Vec3::ZERO), [Vec2::ZERO]);
    // v//vn: the normals only.
    let normals = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nf 1//1 2//1 3//1\n";
    let mesh = load(&write("normals.obj", normals.as_bytes())).mesh;
    assert!(mesh.uvs.is_empty());
    assert_eq!(mesh.normals, [Vec3::Z; 3]);
    // One corner without a texture coordinate: none at all, and averaged normals.
    let partial = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 1 0 0\nf 1/1/1 2//1 3/1/1\n";
    let mesh = load(&write("partial.obj", partial.as_bytes())).mesh;
    assert!(mesh.uvs.is_empty());
    assert_eq!(
        mesh.normals,
        [Vec3::X; 3],
        "the file's, every corner has one"
    );
    let bare = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2 3\n";
    let mesh = load(&write("bare.obj", bare.as_bytes())).mesh;
    assert!(mesh.uvs.is_empty());
    assert_eq!(mesh.normals, [Vec3::Z; 3], "the triangle's");
    // A library that is not there leaves the model untextured (models travel
    // without theirs); a material it does not hold, too.
    let missing = "mtllib nowhere.mtl\nusemtl m\n".to_string() + bare;
    assert_eq!(
        load(&write("missing.obj", missing.as_bytes())).texture,
        None
    );
}

/// A corner that names a texture coordinate or a normal not defined above, or an
/// attribute that is not a number, is refused at its line.
#[test]
fn bad_attributes_are_refused_at_their_line() {
    let (_dir, write) = scratch();
    let triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (body, line, says) in [
        ("vt 0 0\nf 1/2 2/1 3/1\n", 5, "texture coordinate 2, of 1"),
        ("vn 0 0 1\nf 1//1 2//0 3//1\n", 5, "normal 0, of 1"),
        ("vt 0 x\nf 1 2 3\n", 4, "'x'"),
        ("vn 0 0\n", 4, "needs 3 numbers"),
        ("vt nan 0\n", 4, "not a finite number"),
        ("f 1/a 2 3\n", 4, "not a number"),
    ] {
        let path = write("bad.obj", (triangle.to_string() + body).as_bytes());
        let err = Mesh::from_obj(&path).unwrap_err();
        let Error::File {
            line: at, message, ..
        } = &err
        else {
            panic!("{err}");
        };
        assert_eq!(*at, Some(line), "{body}: {err}");
        assert!(message.contains(says), "{body}: {err}");
    }
}

/// Lesson 09 with a textured model read from its file, as `--mesh` reads one: the
/// floor and the square drawn both ways show both of the texture's colours, and no
/// compared pixel differs between the ray caster and the rasterizer. A texture
/// given with `--texture` replaces the material's; one that is not an image, or a
/// texture on a mesh without texture coordinates, is refused.
#[test]
fn lesson_09_draws_a_textured_model_both_ways() {
    let (_dir, write) = scratch();
    let obj = write("square.obj", SQUARE.as_bytes());
    write("square.mtl", LIBRARY.as_bytes());
    write_checker(&obj.with_file_name("checker.tga"));
    let scene = still_life(Vec3::ZERO).unwrap();
    let camera = still_life_pinhole(160, 90).unwrap();
    let mesh = mesh_on_the_floor(&obj, Up::Y, 0, &camera).unwrap();
    assert!(mesh.model.texture.is_some());
    let shadows = still_life_shadows(256, 1.0);
    let run = lesson::images(&scene, &camera, 16, shadows, &mesh.model).unwrap();
    let agreement = run.agreements.iter().find(|(l, ..)| *l == "floor + mesh");
    let agreement = agreement.unwrap().2;
    assert_eq!(agreement.differing, 0, "{agreement:?}");
    // Both colours of the checker, lit, in both images: the bluer and the yellower.
    for image in [&run.images.mesh_raster, &run.images.mesh_ray_cast] {
        let pixels = (0..90).flat_map(|y| (0..160).map(move |x| (x, y)));
        let colours: Vec<Vec3> =
            pixels.map(|(x, y)| image.get(x, y).unwrap()).collect();
        assert!(colours.iter().any(|c| c.z > 2.0 * c.x && c.z > 0.05));
        assert!(colours.iter().any(|c| c.x > 2.0 * c.z && c.x > 0.05));
    }
    let numbers = lesson::numbers(&scene, 16, (&mesh, "square.obj"), &run).unwrap();
    let row = "mesh (square.obj, smooth, textured; 1 faces triangulated)";
    assert!(numbers.contains(row), "{numbers}");
    // --texture: another image instead, one red texel.
    let other = obj.with_file_name("red.png");
    render_lessons::files::write_png_rgba(&other, 1, 1, &[255, 0, 0, 255]).unwrap();
    let textured = mesh.clone().textured(Some(&other)).unwrap();
    let red = Texture::new(1, 1, vec![Vec3::X]).unwrap();
    assert_eq!(textured.model.texture.as_deref(), Some(&red));
    let text = write("text.tga", b"not an image");
    assert!(mesh.clone().textured(Some(&text)).is_err());
}
