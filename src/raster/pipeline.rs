//! The pipeline of Lecture 2 ("Rasterization Pipeline"), stage after stage: modeling
//! (a vertex list and a triangle list) -> transform -> lighting -> primitive
//! rasterization with a z-buffer -> per-pixel shading. Each stage has its own file
//! ([`super::projection`], [`super::shade`](mod@super::shade), [`super::clip`],
//! [`super::rasterize`](mod@super::rasterize)); this one runs them in order.
//!
//! The work runs in two parallel stages: vertices and triangles (transform, light,
//! clip, project), then bands of rows, each band drawing every triangle in list
//! order into its own rows. A pixel is only ever touched by one band, always in the
//! same triangle order, so the image is the same bit for bit whatever the number of
//! threads.

use std::ops::Range;

use glam::Vec3;
use rayon::prelude::*;

use super::{
    CameraTransforms, ClipVertex, RasterSettings, ScreenVertex, Shading, ShadowMap,
    Varyings, Viewer, clip_triangle, rasterize_triangle, shade,
};
use crate::camera::Camera;
use crate::error::{Result, finite3};
use crate::framebuffer::Framebuffer;
use crate::mesh::Model;
use crate::scene::PointLight;
use crate::texture::Texture;
use crate::transform::Transform;

/// Rows per band of the parallel fragment stage.
pub const BAND_ROWS: u32 = 16;

/// The viewer as lighting needs it.
pub fn viewer(camera: &Camera) -> Viewer {
    match camera.pinhole() {
        Some(c) => Viewer::Point(c.frame().position()),
        None => Viewer::Direction(camera.frame().basis().w()),
    }
}

/// What lighting needs besides the surface: the light, the viewer, and the shadow
/// map if there is one.
struct Lights<'a> {
    light: &'a PointLight,
    viewer: Viewer,
    shadow_map: Option<&'a ShadowMap>,
}

impl Lights<'_> {
    /// Lambert's law at `p` with normal `n` on a surface whose own normal is `n_g`,
    /// the light visible unless the shadow map says otherwise.
    fn shade(&self, p: Vec3, (n, n_g): (Vec3, Vec3), albedo: Vec3) -> Vec3 {
        shade(p, (n, n_g), albedo, self.light, &self.viewer, || {
            self.shadow_map.is_none_or(|m| m.lit(p, n))
        })
    }
}

// ANCHOR: rasterize
/// The image of `models` seen by `camera` and lit by `light`: Lecture 2's
/// pipeline, with a shadow map first if `settings` asks for one. Bands of rows in
/// parallel on the current thread pool; the image does not depend on its size.
pub fn rasterize(
    models: &[Model],
    camera: &Camera,
    light: &PointLight,
    settings: &RasterSettings,
) -> Result<Framebuffer> {
    finite3("background", settings.background)?;
    finite3("light position", light.position)?;
    finite3("light intensity", light.intensity)?;
    let transforms = CameraTransforms::new(camera, settings.depth)?;
    let (width, height) = (camera.film().width(), camera.film().height());
    let mut colours = vec![settings.background; width as usize * height as usize];
    let shadow_map = match &settings.shadows {
        Some(shadows) => Some(ShadowMap::build(models, light, shadows)?),
        None => None,
    };
    let shadow_map = shadow_map.as_ref();
    let screen = setup(models, &transforms, camera, light, settings, shadow_map)?;
    let lights = Lights {
        light,
        viewer: viewer(camera),
        shadow_map,
    };
    in_bands(
        &screen.triangles,
        width,
        height,
        &mut colours,
        |mine, rows, pixels| {
            draw_band(&screen, mine, rows, width, pixels, &lights, settings);
        },
    );
    Framebuffer::from_pixels(width, height, colours)
}
// ANCHOR_END: rasterize

/// The screen triangles of every model, in order, and each one's texture.
pub(super) struct Screen<'a> {
    pub(super) triangles: Vec<[ScreenVertex; 3]>,
    pub(super) textures: Vec<Option<&'a Texture>>,
}

/// Vertex and triangle stage: every model's vertices transformed (and lit, for
/// Gouraud shading), its triangles clipped and projected to screen triangles, in
/// order, each with its model's texture if it has one.
pub(super) fn setup<'a>(
    models: &'a [Model],
    transforms: &CameraTransforms,
    camera: &Camera,
    light: &PointLight,
    settings: &RasterSettings,
    shadow_map: Option<&ShadowMap>,
) -> Result<Screen<'a>> {
    let lights = Lights {
        light,
        viewer: viewer(camera),
        shadow_map,
    };
    let mut screen = Screen {
        triangles: Vec::new(),
        textures: Vec::new(),
    };
    for model in models {
        let vertices =
            transform_vertices(model, transforms, &lights, settings.shading)?;
        let triangles: Vec<_> = model
            .mesh
            .triangles
            .par_iter()
            .flat_map_iter(|t| {
                let t = t.map(|i| vertices[i as usize]);
                clip_triangle(&t).into_iter().filter_map(|c| {
                    let [a, b, c] = c.map(|v| ScreenVertex::from_clip(transforms, &v));
                    Some([a?, b?, c?])
                })
            })
            .collect();
        let texture = model.checked_texture()?;
        screen.textures.extend(triangles.iter().map(|_| texture));
        screen.triangles.extend(triangles);
    }
    Ok(screen)
}

// ANCHOR: vertex_stage
/// The vertex stage: world position (model matrix), world normal (inverse transpose
/// of the model matrix), clip position (projection x view), texture coordinates,
/// and the colour to interpolate: lit here for Gouraud shading, the albedo for
/// per-pixel shading. A textured model's vertices are lit as white: its fragments
/// take their albedo from the texture.
fn transform_vertices(
    model: &Model,
    transforms: &CameraTransforms,
    lights: &Lights,
    shading: Shading,
) -> Result<Vec<ClipVertex>> {
    let albedo = match model.checked_texture()? {
        Some(_) => Vec3::ONE,
        None => finite3("colour", model.colour)?,
    };
    let normal_matrix = model.model.inverse()?.matrix().transpose();
    let mesh = &model.mesh;
    Ok((0..mesh.positions.len())
        .into_par_iter()
        .map(|i| {
            let world = model.model.point(mesh.positions[i]);
            let normal = normal_matrix
                .transform_vector3(mesh.normals[i])
                .normalize_or_zero();
            let colour = match shading {
                Shading::PerVertex => lights.shade(world, (normal, normal), albedo),
                Shading::PerPixel => albedo,
            };
            ClipVertex {
                clip: transforms.to_clip(&Transform::IDENTITY, world),
                varyings: Varyings {
                    world,
                    normal,
                    colour,
                    uv: mesh.uvs.get(i).copied().unwrap_or_default(),
                },
            }
        })
        .collect())
}
// ANCHOR_END: vertex_stage

/// Splits `buffer` (`width` x `height`, row by row) into bands of [`BAND_ROWS`]
/// rows and calls `draw(mine, rows, band)` for each, in parallel, where `mine` lists
/// (in order) the triangles whose rows may touch the band. Sorting triangles into
/// bands first means a band never even looks at the triangles far from it.
pub(super) fn in_bands<T: Send>(
    triangles: &[[ScreenVertex; 3]],
    width: u32,
    height: u32,
    buffer: &mut [T],
    draw: impl Fn(&[u32], Range<u32>, &mut [T]) + Sync,
) {
    let bands = height.div_ceil(BAND_ROWS) as usize;
    let mut bins = vec![Vec::new(); bands];
    for (k, t) in triangles.iter().enumerate() {
        let lo = t.iter().map(|v| v.pixel.y).fold(f32::INFINITY, f32::min);
        let hi = t
            .iter()
            .map(|v| v.pixel.y)
            .fold(f32::NEG_INFINITY, f32::max);
        // One row of margin: pixel centres sit half a row inside.
        if !(hi >= -1.0 && lo <= height as f32 + 1.0) {
            continue;
        }
        let row =
            |y: f32| (y.clamp(0.0, (height - 1) as f32) as u32 / BAND_ROWS) as usize;
        for bin in &mut bins[row(lo - 1.0)..=row(hi + 1.0)] {
            bin.push(k as u32);
        }
    }
    buffer
        .par_chunks_mut(width as usize * BAND_ROWS as usize)
        .zip(bins.par_iter())
        .enumerate()
        .for_each(|(i, (band, mine))| {
            let first = i as u32 * BAND_ROWS;
            draw(mine, first..(first + BAND_ROWS).min(height), band);
        });
}

// ANCHOR: draw_band
/// The fragment stage for one band of rows: its triangles in order, a z-buffer
/// with the test "nearer than what is there" (depth less-than), and the shading, on
/// the side of the triangle the viewer sees, with a textured triangle's albedo looked
/// up at the fragment's texture coordinates, interpolated perspective-correctly as
/// every attribute is.
fn draw_band(
    screen: &Screen,
    mine: &[u32],
    rows: Range<u32>,
    width: u32,
    pixels: &mut [Vec3],
    lights: &Lights,
    settings: &RasterSettings,
) {
    let mut depth = vec![f32::INFINITY; pixels.len()];
    let first_row = rows.start;
    for &k in mine {
        let triangle = &screen.triangles[k as usize];
        let [a, b, c] = triangle.each_ref().map(|v| v.varyings.world);
        let facet = (b - a).cross(c - a); // the triangle's own normal
        rasterize_triangle(triangle, settings.cull, width, rows.clone(), |f| {
            let i = ((f.y - first_row) * width + f.x) as usize;
            if f.depth < depth[i] {
                depth[i] = f.depth;
                let v = f.varyings;
                let texel = screen.textures[k as usize].map(|t| t.sample(v.uv));
                pixels[i] = match (settings.shading, texel) {
                    (Shading::PerVertex, None) => v.colour,
                    (Shading::PerVertex, Some(albedo)) => v.colour * albedo,
                    (Shading::PerPixel, albedo) => {
                        let albedo = albedo.unwrap_or(v.colour);
                        lights.shade(v.world, (v.normal, facet), albedo)
                    }
                };
            }
        });
    }
}
// ANCHOR_END: draw_band
