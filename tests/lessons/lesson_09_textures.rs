//! Lesson 09, textures (issue 32): a mesh's texture coordinates pick its albedo out
//! of an image, in the rasterizer (interpolated perspective-correctly, as lesson 09
//! teaches), in the ray caster (blended by the barycentric coordinates of the hit)
//! and in the path tracer (the albedo at the hit), all where the projective map of
//! the quad puts each texel.
//!
//! The expected colours are computed here from geometry alone: each pixel's ray
//! meets the quad's plane at a point whose (u, v) follows from the quad's corners
//! (the coordinates are affine on the quad), and the checker square at (u, v) gives
//! the colour. The point light is behind the quads, so the ray caster's and the
//! rasterizer's pixels are their albedo times the ambient share; the path tracer's
//! light is the sky, of radiance 1, which a Lambertian surface reflects as its albedo
//! (one bounce, cosine-sampled: every sample gives the albedo exactly). Nothing else
//! is there to hide a misplaced texel.

use glam::{DVec3, Vec2, Vec3};
use render_lessons::camera::{Camera, Film, PinholeCamera};
use render_lessons::framebuffer::{Framebuffer, to_srgb8};
use render_lessons::lighting::AMBIENT;
use render_lessons::mesh::{Mesh, Model};
use render_lessons::pathtrace::{Settings, radiance};
use render_lessons::raster::{
    CameraTransforms, ClipVertex, Cull, DepthRange, RasterSettings, ScreenVertex,
    Shading, Varyings, rasterize,
};
use render_lessons::raycast::lit_unshadowed;
use render_lessons::render::render;
use render_lessons::rng::Rng;
use render_lessons::scene::{PointLight, Scene};
use render_lessons::texture::{Texture, from_srgb8};
use render_lessons::transform::Transform;

const SIZE: u32 = 128;
/// Checker squares along each side of the texture, and texels along a square's side.
const SQUARES: u32 = 4;
const TEXELS: u32 = 4;
const DARK: Vec3 = Vec3::new(0.1, 0.2, 0.6);
const LIGHT_SQUARE: Vec3 = Vec3::new(0.9, 0.8, 0.3);
/// Behind both quads, so that only the ambient share lights them.
const BEHIND: PointLight = PointLight {
    position: Vec3::new(0.0, -1000.0, -1000.0),
    intensity: Vec3::splat(10.0),
};

/// A checkerboard: square (i, j), column i and row j from the top of the image, is
/// dark where i + j is even.
fn checker() -> Texture {
    let side = SQUARES * TEXELS;
    let texels = (0..side * side)
        .map(|k| square_colour(k % side / TEXELS, k / side / TEXELS))
        .collect();
    Texture::new(side, side, texels).unwrap()
}

fn square_colour(i: u32, j: u32) -> Vec3 {
    if (i + j).is_multiple_of(2) {
        DARK
    } else {
        LIGHT_SQUARE
    }
}

/// The checker's colour at (u, v), if (u, v) lies inside a square by more than half
/// a texel (and a little more for rounding), where bilinear filtering blends the
/// square's own texels only: the square's column is u SQUARES, its row from the top
/// (1 - v) SQUARES.
fn expected(u: f64, v: f64) -> Option<Vec3> {
    let squares = f64::from(SQUARES);
    let (x, y) = (u * squares, (1.0 - v) * squares);
    let margin = 0.6 / f64::from(TEXELS);
    let well_inside = |t: f64| {
        (0.0..squares).contains(&t) && t.fract() > margin && 1.0 - t.fract() > margin
    };
    (well_inside(x) && well_inside(y)).then(|| square_colour(x as u32, y as u32))
}

/// The quad a b c d (a counter-clockwise parallelogram facing the camera at the
/// origin) with texture coordinates (0, 0), (1, 0), (1, 1), (0, 1), textured.
fn quad(corners: [Vec3; 4]) -> Model {
    let [a, b, _, d] = corners;
    let n = (b - a).cross(d - a).normalize();
    let mesh =
        Mesh::with_normals(corners.to_vec(), vec![n; 4], vec![[0, 1, 2], [0, 2, 3]])
            .unwrap()
            .with_uvs(vec![Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y])
            .unwrap();
    Model::new(mesh, Vec3::ONE).textured(checker())
}

fn camera() -> Camera {
    let film = Film::new(SIZE, SIZE, (-1.0, 1.0), (-1.0, 1.0)).unwrap();
    PinholeCamera::at_origin(film, 1.0).unwrap().into()
}

const DEPTH: DepthRange = DepthRange {
    near: 0.1,
    far: 100.0,
};

/// The image of `model` rasterized with per-pixel shading, ray cast as one shape
/// (the point light behind it), and path traced under a sky of radiance 1, one
/// sample through each pixel's centre.
fn three_ways(model: &Model) -> [Framebuffer; 3] {
    let settings = RasterSettings {
        depth: DEPTH,
        shading: Shading::PerPixel,
        cull: Cull::None,
        background: Vec3::ZERO,
        shadows: None,
    };
    let raster = rasterize(std::slice::from_ref(model), &camera(), &BEHIND, &settings);
    let scene = Scene::new(vec![model.object().unwrap()], Vec3::ONE).unwrap();
    let scene = scene.with_light(BEHIND).unwrap();
    let cast = render(&camera(), |r| lit_unshadowed(&scene, r));
    let settings = Settings::default();
    let traced = render(&camera(), |r| {
        radiance(&scene, *r, &mut Rng::new(1, 2), &settings)
    });
    [raster.unwrap(), cast.unwrap(), traced.unwrap()]
}

/// (u, v) where pixel (x, y)'s ray meets the plane of the parallelogram `corners`,
/// in f64, if it meets the quad: solving o + s d = a + u (b - a) + v (d - a).
fn uv_at(x: u32, y: u32, corners: [Vec3; 4]) -> Option<(f64, f64)> {
    let ray = camera().ray(x, y);
    let (o, dir) = (ray.origin().as_dvec3(), ray.direction().as_dvec3());
    let [a, b, _, d] = corners.map(|c| c.as_dvec3());
    let (e1, e2) = (b - a, d - a);
    let n = e1.cross(e2);
    let s = (a - o).dot(n) / dir.dot(n);
    let p = o + s * dir - a;
    // p = u e1 + v e2: the components along the dual basis.
    let uv = |e: DVec3, f: DVec3| p.dot(f.cross(n)) / e.dot(f.cross(n));
    let (u, v) = (uv(e1, e2), uv(e2, e1));
    (s > 0.0 && (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v)).then_some((u, v))
}

/// The three renderers give every pixel whose (u, v) lies well inside a checker
/// square exactly that square's colour (times the ambient share in the ray caster
/// and the rasterizer); returns how many pixels were checked.
fn assert_texture_where_the_projective_map_puts_it(corners: [Vec3; 4]) -> usize {
    let images = three_ways(&quad(corners));
    let mut checked = 0;
    for (y, x) in (0..SIZE).flat_map(|y| (0..SIZE).map(move |x| (y, x))) {
        let Some(colour) = uv_at(x, y, corners).and_then(|(u, v)| expected(u, v))
        else {
            continue;
        };
        let lit = colour * AMBIENT;
        let expected = [
            ("rasterized", lit),
            ("ray cast", lit),
            ("path traced", colour),
        ];
        for (image, (name, colour)) in images.iter().zip(expected) {
            assert_eq!(image.get(x, y).unwrap(), colour, "{name} ({x}, {y})");
        }
        checked += 1;
    }
    checked
}

#[test]
fn a_quad_facing_the_camera_shows_its_texture() {
    let corners = [
        Vec3::new(-1.2, -1.0, -2.5),
        Vec3::new(1.0, -1.1, -3.0),
        Vec3::new(1.1, 1.0, -2.8),
        Vec3::new(-1.1, 1.1, -2.3),
    ];
    // A parallelogram: the fourth corner is a + (b - a) + (d - a).
    let corners = [
        corners[0],
        corners[1],
        corners[1] + corners[3] - corners[0],
        corners[3],
    ];
    let checked = assert_texture_where_the_projective_map_puts_it(corners);
    assert!(checked > 1000, "{checked} pixels");
}

/// A quad receding from 1.5 to 8 units: its far squares are smaller on screen than
/// its near ones. Interpolated linearly in screen space, (u, v) would put many of
/// these pixels in the wrong square; perspective-correctly, none.
#[test]
fn a_receding_quad_shows_its_texture_perspective_correctly() {
    let corners = [
        Vec3::new(-1.0, -1.0, -1.5),
        Vec3::new(1.0, -1.0, -1.5),
        Vec3::new(1.0, 1.0, -8.0),
        Vec3::new(-1.0, 1.0, -8.0),
    ];
    let checked = assert_texture_where_the_projective_map_puts_it(corners);
    assert!(checked > 800, "{checked} pixels");
    // The test has the power to tell: v interpolated linearly between the near and
    // the far edge's rows of pixels names another checker row for many pixels.
    let pipeline = CameraTransforms::new(&camera(), DEPTH).unwrap();
    let row = |p: Vec3| {
        let clip = ClipVertex {
            clip: pipeline.to_clip(&Transform::IDENTITY, p),
            varyings: Varyings::default(),
        };
        ScreenVertex::from_clip(&pipeline, &clip).unwrap().pixel.y
    };
    let (near, far) = (row(corners[0]), row(corners[3]));
    let mut misplaced = 0;
    for (y, x) in (0..SIZE).flat_map(|y| (0..SIZE).map(move |x| (y, x))) {
        if let Some((_, v)) = uv_at(x, y, corners) {
            let affine = f64::from((y as f32 + 0.5 - near) / (far - near));
            let square = |v: f64| ((1.0 - v) * f64::from(SQUARES)) as u32;
            misplaced += usize::from(square(affine) != square(v));
        }
    }
    assert_eq!(misplaced, 1542);
}

/// Bilinear lookup: a texel's centre gives the texel; halfway between two texels,
/// their mean; coordinates repeat beyond 0 and 1; v = 0 is the bottom row.
#[test]
fn a_lookup_is_bilinear_between_texel_centres() {
    let texels = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    let t = Texture::new(2, 2, texels).unwrap();
    let centre = |i: f32, j: f32| Vec2::new((i + 0.5) / 2.0, 1.0 - (j + 0.5) / 2.0);
    assert_eq!(t.sample(centre(0.0, 0.0)), Vec3::ZERO);
    assert_eq!(t.sample(centre(1.0, 0.0)), Vec3::X);
    assert_eq!(t.sample(centre(0.0, 1.0)), Vec3::Y);
    assert_eq!(t.sample(centre(1.0, 1.0)), Vec3::Z);
    assert_eq!(t.sample(centre(0.5, 1.0)), Vec3::new(0.0, 0.5, 0.5));
    assert_eq!(t.sample(centre(0.5, 0.5)), Vec3::splat(0.25));
    assert_eq!(
        t.sample(centre(0.0, 0.0) + Vec2::new(3.0, -2.0)),
        Vec3::ZERO
    );
    // Between the right column and the left, across the edge u = 1 = 0.
    assert_eq!(t.sample(Vec2::new(1.0, 0.75)), Vec3::new(0.5, 0.0, 0.0));
    assert!(t.sample(Vec2::NAN).is_finite());
}

/// The sRGB decoding undoes the framebuffer's encoding, code by code.
#[test]
fn srgb_codes_decode_to_the_linear_values_they_encode() {
    for code in 0..=255u8 {
        assert_eq!(to_srgb8(from_srgb8(code)), code);
    }
    assert_eq!((from_srgb8(0), from_srgb8(255)), (0.0, 1.0));
}

/// `rows` (the top row first) as a TGA file: type 2, uncompressed 24-bit pixels with
/// rows from the bottom, as most writers store them; or type 10, run-length encoded
/// 32-bit pixels with rows from the top, a run packet for each repeated pixel and a
/// raw packet for each other.
pub(crate) fn tga(rows: &[Vec<[u8; 3]>], rle: bool) -> Vec<u8> {
    let (w, h) = (rows[0].len() as u16, rows.len() as u16);
    let (kind, bits, descriptor) = if rle { (10, 32, 0x28) } else { (2, 24, 0) };
    let mut bytes = vec![0, 0, kind, 0, 0, 0, 0, 0, 0, 0, 0, 0];
    bytes.extend(w.to_le_bytes().into_iter().chain(h.to_le_bytes()));
    bytes.extend([bits, descriptor]);
    let stored = |[r, g, b]: [u8; 3]| {
        if rle {
            vec![b, g, r, 255]
        } else {
            vec![b, g, r]
        }
    };
    if !rle {
        bytes.extend(rows.iter().rev().flatten().flat_map(|&p| stored(p)));
        return bytes;
    }
    let pixels: Vec<[u8; 3]> = rows.concat();
    let mut k = 0;
    while k < pixels.len() {
        let run = pixels[k..]
            .iter()
            .take(128)
            .take_while(|&&p| p == pixels[k]);
        let n = run.count();
        bytes.push(if n > 1 { 0x80 | (n - 1) as u8 } else { 0 });
        bytes.extend(stored(pixels[k]));
        k += n;
    }
    bytes
}

/// A texture file is read as its sRGB texels made linear: a PNG written here, and
/// the same image as TGA files, uncompressed and run-length encoded (tinyrenderer's);
/// a file that is not an image, a TGA cut short or of a kind not read, or a texture
/// without texture coordinates to look it up by, is refused with the name of what is
/// wrong.
#[test]
fn a_texture_is_read_from_png_and_tga() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, bytes: &[u8]| {
        let path = dir.path().join(name);
        std::fs::write(&path, bytes).unwrap();
        path
    };
    let rows = vec![
        vec![[0, 0, 0], [255, 0, 0], [255, 0, 0], [255, 0, 0]],
        vec![[0, 128, 0], [10, 20, 250], [7, 7, 7], [7, 7, 7]],
    ];
    let png = dir.path().join("t.png");
    let rgba: Vec<u8> = rows
        .concat()
        .iter()
        .flat_map(|p| [p[0], p[1], p[2], 255])
        .collect();
    render_lessons::files::write_png_rgba(&png, 4, 2, &rgba).unwrap();
    let plain = write("plain.tga", &tga(&rows, false));
    let rle = write("rle.TGA", &tga(&rows, true));
    for path in [&png, &plain, &rle] {
        let t = Texture::read(path).unwrap();
        assert_eq!((t.width(), t.height()), (4, 2));
        for (j, row) in rows.iter().enumerate() {
            for (i, code) in row.iter().enumerate() {
                let expected = Vec3::from(code.map(from_srgb8));
                assert_eq!(t.texel(i as u32, j as u32), expected, "{path:?}");
            }
        }
    }
    let refused = |name: &str, bytes: &[u8], says: &str| {
        let err = Texture::read(write(name, bytes)).unwrap_err();
        let message = err.to_string();
        assert!(
            message.contains(name) && message.contains(says),
            "{message}"
        );
    };
    let whole = tga(&rows, true);
    refused(
        "short.tga",
        &whole[..whole.len() - 3],
        "ends before its last pixel",
    );
    refused("header.tga", &whole[..10], "shorter than a TGA header");
    let mut mapped = whole.clone();
    mapped[2] = 1;
    refused("mapped.tga", &mapped, "type 1");
    refused("t.txt", b"not an image", "PNG or TGA");
    refused("fake.png", b"not an image", "no PNG");
    // A texture on a mesh without texture coordinates.
    let bare = Mesh::floor(Vec3::ZERO, 1.0).unwrap();
    let model = Model::new(bare, Vec3::ONE).textured(checker());
    assert_eq!(model.object().unwrap_err().param(), "texture");
    let settings = RasterSettings::default();
    let err = rasterize(&[model], &camera(), &BEHIND, &settings).unwrap_err();
    assert_eq!(err.param(), "texture");
}
