//! Lesson 09's book-only figures: the pipeline on one triangle, and the lesson's
//! images side by side (ray cast | per pixel | per vertex, the shadows both ways, the
//! shadow map's bias both ways wrong, the mesh both ways), rendered at the book's
//! settings from the same core calls as the lesson.

use glam::{Vec2, Vec3};
use render_lessons::camera::{Camera, Film, Frame, PinholeCamera};
use render_lessons::course::compare::reference;
use render_lessons::course::diagram::{Diagram, Place, Rgb, palette};
use render_lessons::course::lesson::Output;
use render_lessons::error::Problem;
use render_lessons::framebuffer::{Framebuffer, to_srgb8};
use render_lessons::mesh::{Mesh, Model, tessellate};
use render_lessons::raster::Shading::{PerPixel, PerVertex};
use render_lessons::raster::{CameraTransforms, Shadows, floor_settings, point_light};
use render_lessons::raster::{
    ClipVertex, Cull, DepthRange, Fragment, ScreenVertex, Varyings,
};
use render_lessons::raster::{RasterSettings, rasterize, rasterize_triangle};
use render_lessons::raycast::lit;
use render_lessons::render::render;
use render_lessons::scenes::squares::{Squares, squares};
use render_lessons::scenes::{TEAPOT_OBJ, TORUS_OBJ, Up, floor_and_mesh};
use render_lessons::scenes::{
    mesh_on_the_floor, still_life, still_life_pinhole, still_life_shadows,
};
use render_lessons::spawn::Offset;
use render_lessons::texture::Texture;
use render_lessons::transform::Transform;
use render_lessons::{Error, Result};

/// Writes `09_side_by_side.png`, `09_shadows.png`, `09_shadow_bias.png`,
/// `09_mesh.png`, `09_teapot.png`, `09_texture.png`, `09_z_buffer.png` and
/// `09_pipeline_stages.png`:
/// lesson 09 at its defaults (480 x 270, spheres of 64 segments, a 1024^2 shadow map, a
/// bias of one texel footprint), and with `--mesh assets/meshes/teapot.obj`.
pub fn figures(output: &Output) -> Result<()> {
    let scene = still_life(Vec3::ZERO)?;
    let camera = still_life_pinhole(480, 270)?;
    let shadows = still_life_shadows(1024, 1.0);
    let torus = std::path::Path::new(TORUS_OBJ);
    let mesh = mesh_on_the_floor(torus, Up::Y, 0, &camera)?.model;
    let instances = tessellate(&scene, 64)?;
    let light = point_light(&scene)?;
    let book = floor_settings(&scene);
    let draw = |instances: &[Model], shading, shadows: Option<Shadows>| {
        rasterize(instances, &camera, &light, &book.with(shading, shadows))
    };
    let mapped = |bias| draw(&instances, PerPixel, Some(shadows.with_bias(bias)));
    let ray_cast = reference(&scene, &camera)?.image;
    let per_pixel = draw(&instances, PerPixel, None)?;
    let per_vertex = draw(&instances, PerVertex, None)?;
    let traced = render(&camera, |r| lit(&scene, r, Offset::Scaled))?;
    let (shadow_map, acne, peter_pan) = (mapped(1.0)?, mapped(0.0)?, mapped(50.0)?);
    let mesh_cast = reference(&floor_and_mesh(&scene, &mesh)?, &camera)?.image;
    let mesh_raster = draw(&[instances[0].clone(), mesh], PerPixel, None)?;
    let teapot = std::path::Path::new(TEAPOT_OBJ);
    let teapot = mesh_on_the_floor(teapot, Up::Y, 0, &camera)?.model;
    let teapot_cast = reference(&floor_and_mesh(&scene, &teapot)?, &camera)?.image;
    let teapot_raster = draw(&[instances[0].clone(), teapot], PerPixel, None)?;
    let square = checkered_square()?;
    let square_cast = reference(&floor_and_mesh(&scene, &square)?, &camera)?.image;
    let square_raster = draw(&[instances[0].clone(), square], PerPixel, None)?;
    let three = [&ray_cast, &per_pixel, &per_vertex];
    output.diagram("09_side_by_side.png", &captioned(&three, &SIDE_BY_SIDE)?)?;
    let panels = [
        ("09_shadows.png", vec![&traced, &shadow_map]),
        ("09_shadow_bias.png", vec![&acne, &peter_pan]),
        ("09_mesh.png", vec![&mesh_cast, &mesh_raster]),
        ("09_teapot.png", vec![&teapot_cast, &teapot_raster]),
        ("09_texture.png", vec![&square_cast, &square_raster]),
    ];
    for (name, images) in panels {
        output.image(name, &Framebuffer::beside(&images, 8)?)?;
    }
    output.image("09_z_buffer.png", &z_buffer()?)?;
    output.diagram("09_pipeline_stages.png", &stages()?)
}

/// A square of side 5 just above the floor of the still life, textured with
/// a checkerboard of 8 x 8 squares (256 x 256 texels), its texture coordinates 0 to 1
/// from corner to corner: receding, its squares shrink with distance.
fn checkered_square() -> Result<Model> {
    let side = 256;
    let texels = (0..side * side)
        .map(|k: u32| match (k % side / 32 + k / side / 32) % 2 {
            0 => Vec3::new(0.1, 0.2, 0.6),
            _ => Vec3::new(0.9, 0.8, 0.3),
        })
        .collect();
    let texture = Texture::new(side, side, texels)?;
    // Mesh::floor's corners run (-x, -z), (-x, +z), (+x, +z), (+x, -z).
    let uvs = vec![Vec2::Y, Vec2::ZERO, Vec2::X, Vec2::ONE];
    let square = Mesh::floor(Vec3::new(0.0, 0.02, 0.5), 5.0)?.with_uvs(uvs)?;
    Ok(Model::new(square, Vec3::ONE).textured(texture))
}

/// The z-buffer's two squares (`scenes::squares`), rasterized with the red one first
/// and with the blue one first, each pixel drawn as a 24 x 24 block so the 16 x 9
/// image can be seen: the two images are the same.
pub fn z_buffer() -> Result<Framebuffer> {
    let Squares {
        near,
        far,
        camera,
        light,
    } = squares()?;
    let settings = RasterSettings::default();
    let orders = [[near.clone(), far.clone()], [far, near]];
    let mut images = Vec::new();
    for models in &orders {
        let image = rasterize(models, &camera, &light, &settings)?;
        let block = 24;
        let big = Framebuffer::from_fn(
            image.width() * block,
            image.height() * block,
            |x, y| image.get(x / block, y / block).unwrap_or(Vec3::ZERO),
        )?;
        images.push(big);
    }
    Framebuffer::beside(&images.iter().collect::<Vec<_>>(), 8)
}

/// The captions of `09_side_by_side.png`, left to right.
pub const SIDE_BY_SIDE: [&str; 3] = [
    "ray cast",
    "rasterized, per pixel",
    "rasterized, per vertex",
];

/// Size of a strip's captions in pixels: the page shows a strip of three 480 px
/// renders about half size, so they are set twice the size of a diagram's labels.
const CAPTION_SIZE: f32 = 30.0;

/// `images` in a row, 8 white pixels apart, each under its caption.
pub fn captioned(images: &[&Framebuffer], captions: &[&str]) -> Result<Diagram> {
    let strip = Framebuffer::beside(images, 8)?;
    let band = (CAPTION_SIZE * 1.6) as u32;
    let (w, h) = (strip.width(), strip.height() + band);
    let mut d = Diagram::new(w, h, (0.0, w as f32), (0.0, h as f32))?;
    d.image_px(0, band, w, &strip.to_srgb8()?);
    let mut left = 0.0;
    for (image, caption) in images.iter().zip(captions) {
        let centre = Vec2::new(left + 0.5 * image.width() as f32, 0.5 * band as f32);
        d.text_px(centre, caption, CAPTION_SIZE, palette::INK, Place::Centre);
        left += (image.width() + 8) as f32;
    }
    Ok(d)
}

/// The figure: Lecture 2's pipeline on one triangle, in four panels. The triangle's
/// vertices in the world, the same vertices in clip space divided by w (NDC), the
/// pixel centres the rasterizer finds inside it, and the colours interpolated
/// between its three vertex colours.
pub fn stages() -> Result<Diagram> {
    let film = Film::new(16, 12, (-0.6, 0.6), (-0.45, 0.45))?;
    let frame = Frame::look(
        Vec3::new(0.0, 1.0, 4.0),
        Vec3::new(0.0, -0.25, -1.0),
        Vec3::Y,
    )?;
    let camera: Camera = PinholeCamera::new(film, 1.0, frame)?.into();
    let pipeline = CameraTransforms::new(
        &camera,
        DepthRange {
            near: 0.5,
            far: 20.0,
        },
    )?;
    let world = [
        Vec3::new(-1.5, 0.0, 0.5),
        Vec3::new(1.6, 0.2, -0.5),
        Vec3::new(-0.2, 1.7, -1.0),
    ];
    let colours = [Vec3::X, Vec3::Y, Vec3::Z];
    let vertex = |i: usize| ClipVertex {
        clip: pipeline.to_clip(&Transform::IDENTITY, world[i]),
        varyings: Varyings {
            world: world[i],
            normal: Vec3::Z,
            colour: colours[i],
            ..Default::default()
        },
    };
    let screen = [0, 1, 2].map(|i| ScreenVertex::from_clip(&pipeline, &vertex(i)));
    let [Some(a), Some(b), Some(c)] = screen else {
        return Err(Error::Value {
            param: "w of a stage-figure vertex",
            problem: Problem::NotPositive { value: 0.0 },
        });
    };
    let mut fragments = Vec::new();
    rasterize_triangle(&[a, b, c], Cull::None, 16, 0..12, |f| fragments.push(f));
    stage_panels(&world, &[a, b, c], &fragments)
}

fn stage_panels(
    world: &[Vec3; 3],
    screen: &[ScreenVertex; 3],
    fragments: &[Fragment],
) -> Result<Diagram> {
    // Four panels in two rows of two (1 2 above, 3 4 below), in one coordinate
    // system, each 20 units wide and 17 high; the pixel grid of panels 3 and 4 is
    // 16 x 12 units, row 0 at the top.
    let mut d = Diagram::new(800, 700, (0.0, 40.0), (-1.5, 32.5))?;
    d.title("One triangle through the pipeline");
    let at = |k: f32, x: f32, y: f32| {
        let (column, row) = (k % 2.0, (k / 2.0).floor());
        Vec2::new(20.0 * column + 2.0 + x, 17.0 * (1.0 - row) + 2.0 + y)
    };
    let label = |d: &mut Diagram, k: f32, s: &str| {
        d.text(at(k, 8.0, -1.0), s, palette::INK, Place::Below)
    };
    // 1: world (x, y), scaled to fit.
    let w2 = world.map(|v| at(0.0, 5.0 * (v.x + 1.6), 5.0 * (v.y + 0.5)));
    d.outline(&w2, palette::INK, 2.0);
    for (i, p) in w2.iter().enumerate() {
        d.dot(*p, 5.0, palette::INK);
        d.text(*p, &format!("v{i}"), palette::INK, Place::Above);
    }
    label(&mut d, 0.0, "1. three vertices (world x, y)");
    // 2: NDC: the square [-1, 1]^2 drawn 16 x 12.
    let ndc = |x: f32, y: f32| at(1.0, 8.0 + 8.0 * x, 6.0 + 6.0 * y);
    let square =
        [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].map(|(x, y)| ndc(x, y));
    for i in 0..4 {
        d.dashed(square[i], square[(i + 1) % 4], palette::GRID, 1.0);
    }
    let n2 = screen.map(|v| ndc(v.pixel.x / 8.0 - 1.0, 1.0 - v.pixel.y / 6.0));
    d.outline(&n2, palette::INK, 2.0);
    for p in &n2 {
        d.dot(*p, 5.0, palette::INK);
    }
    label(&mut d, 1.0, "2. P V x, divided by w (NDC)");
    // 3 and 4: the pixel grid and the triangle in pixels.
    let pixel = |k: f32, x: f32, y: f32| at(k, x, 12.0 - y);
    for k in [2.0, 3.0] {
        for x in 0..=16 {
            let x = x as f32;
            d.line(pixel(k, x, 0.0), pixel(k, x, 12.0), palette::GRID, 1.0);
        }
        for y in 0..=12 {
            let y = y as f32;
            d.line(pixel(k, 0.0, y), pixel(k, 16.0, y), palette::GRID, 1.0);
        }
    }
    for f in fragments {
        let (x, y) = (f.x as f32, f.y as f32);
        d.dot(pixel(2.0, x + 0.5, y + 0.5), 4.0, palette::HIT);
        let cell = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
            .map(|(dx, dy)| pixel(3.0, x + dx, y + dy));
        let c = f.varyings.colour;
        let rgb = Rgb(to_srgb8(c.x), to_srgb8(c.y), to_srgb8(c.z));
        d.fill(&cell, rgb, 255);
    }
    for k in [2.0, 3.0] {
        let tri = screen.map(|v| pixel(k, v.pixel.x, v.pixel.y));
        d.outline(&tri, palette::INK, 1.5);
    }
    label(&mut d, 2.0, "3. pixel centres inside (edge functions)");
    label(&mut d, 3.0, "4. colours interpolated (barycentric)");
    Ok(d)
}
