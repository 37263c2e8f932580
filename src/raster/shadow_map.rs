//! The shadow map (Williams 1978, "Casting curved shadows on curved surfaces"): the
//! trick a rasterizer uses for the shadows it cannot ask for. Render the scene once
//! from the light, keeping in every texel the distance to the nearest surface the
//! light sees; then a point is in shadow when it lies farther from the light than
//! what the map recorded in its direction.
//!
//! It answers the shadow-ray question of lesson 08 with a lookup instead of a ray,
//! and pays for that with artefacts the ray caster never shows: acne when the bias is
//! too small (a surface shadows itself, as in lesson 08's fixed epsilon), light
//! leaking under contact points when it is too large ("Peter Panning"), and blocky
//! shadow edges, one block per texel, when the map is coarse.

use glam::Vec3;

use super::{CameraTransforms, Cull, DepthRange, RasterSettings, rasterize_triangle};
use crate::camera::{Camera, Film, Frame, PinholeCamera};
use crate::error::{Error, Problem, Result, finite3, non_negative, positive};
use crate::limits::image_side;
use crate::mesh::Model;
use crate::scene::PointLight;
use crate::transform::Transform;

/// How to build a shadow map: its resolution, its bias, and the part of the scene
/// the light's camera frames (a sphere around `centre`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shadows {
    /// Texels along each side of the square map.
    pub size: u32,
    /// How much farther than the recorded distance a point must be to count as
    /// shadowed, in texel footprints (see [`ShadowMap::lit`]).
    pub bias: f32,
    /// Where the light's camera looks.
    pub centre: Vec3,
    /// The radius around `centre` it frames; points outside the map count as lit.
    pub radius: f32,
}

impl Shadows {
    /// The same map with another bias.
    pub fn with_bias(self, bias: f32) -> Shadows {
        Shadows { bias, ..self }
    }
}

/// Distances from the light to the nearest surface, one per texel, and the light's
/// camera that maps world points to texels.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadowMap {
    transforms: CameraTransforms,
    light: Vec3,
    size: u32,
    bias: f32,
    texel_angle: f32,
    distance: Vec<f32>,
}

impl ShadowMap {
    // ANCHOR: build
    /// Pass 1: rasterize `models` from the light, keeping the nearest distance
    /// |x - light| per texel (a z-buffer that stores distance instead of depth).
    pub fn build(
        models: &[Model],
        light: &PointLight,
        shadows: &Shadows,
    ) -> Result<Self> {
        let camera = light_camera(light.position, shadows)?;
        let (lo, hi) = camera.film().x_extent();
        let texel_angle = (hi - lo) / shadows.size as f32;
        let depth = DepthRange {
            near: 1e-3 * shadows.radius,
            far: 1e3 * shadows.radius + (shadows.centre - light.position).length(),
        };
        let transforms = CameraTransforms::new(&camera, depth)?;
        let settings = RasterSettings {
            depth,
            cull: Cull::None,
            ..RasterSettings::default()
        };
        let triangles = super::pipeline::setup(
            models,
            &transforms,
            &camera,
            light,
            &settings,
            None,
        )?
        .triangles;
        let size = shadows.size;
        let mut distance = vec![f32::INFINITY; size as usize * size as usize];
        super::pipeline::in_bands(
            &triangles,
            size,
            size,
            &mut distance,
            |mine, rows, texels| {
                for &k in mine {
                    rasterize_triangle(
                        &triangles[k as usize],
                        Cull::None,
                        size,
                        rows.clone(),
                        |f| {
                            let i = ((f.y - rows.start) * size + f.x) as usize;
                            let d = (f.varyings.world - light.position).length();
                            texels[i] = texels[i].min(d);
                        },
                    );
                }
            },
        );
        Ok(ShadowMap {
            transforms,
            light: light.position,
            size,
            bias: shadows.bias,
            texel_angle,
            distance,
        })
    }
    // ANCHOR_END: build

    // ANCHOR: lit
    /// Pass 2, for each shaded point: is the light visible from `p` (normal `n`)?
    /// Project `p` into the map and compare its distance d to the light with the
    /// distance recorded there. One texel stands for a patch of surface of width
    /// about s = d (texel angle); tilted by theta from the light, that patch spans
    /// s tan(theta) in distance, so the map can be off by that much. The comparison
    /// forgives bias x s (1 + tan theta) (tan capped at 10): a slope-scaled bias in
    /// texels. Points outside the map are lit.
    pub fn lit(&self, p: Vec3, n: Vec3) -> bool {
        let clip = self.transforms.to_clip(&Transform::IDENTITY, p);
        let Some(texel) = self.transforms.to_screen(clip) else {
            return true;
        };
        let (x, y) = (texel.x.floor(), texel.y.floor());
        let size = self.size as f32;
        if !(0.0..size).contains(&x) || !(0.0..size).contains(&y) {
            return true;
        }
        let recorded = self.distance[y as usize * self.size as usize + x as usize];
        let d = (p - self.light).length();
        let cos = (n.dot(self.light - p) / d).abs().clamp(0.0, 1.0);
        let tan = ((1.0 - cos * cos).sqrt() / cos).min(10.0);
        let footprint = self.texel_angle * d;
        d - self.bias * footprint * (1.0 + tan) <= recorded
    }
    // ANCHOR_END: lit

    /// Texels along each side.
    pub fn size(&self) -> u32 {
        self.size
    }

    /// The recorded distance of texel (x, y), row 0 at the top; infinite where the
    /// light sees nothing.
    pub fn distance(&self, x: u32, y: u32) -> Option<f32> {
        (x < self.size && y < self.size)
            .then(|| self.distance[(y * self.size + x) as usize])
    }
}

/// A pinhole camera at the light, looking at `shadows.centre`, whose square film
/// frames the sphere of `shadows.radius` around it.
fn light_camera(light: Vec3, shadows: &Shadows) -> Result<Camera> {
    let size = shadows.size;
    image_side("shadow map size", size)?;
    non_negative("shadow bias", shadows.bias)?;
    let radius = positive("shadow radius", shadows.radius)?;
    let direction = finite3("shadow centre", shadows.centre)? - light;
    let distance = direction.length();
    if distance <= radius {
        return Err(Error::Value {
            param: "distance from the light to the shadow centre, minus the shadow radius",
            problem: Problem::NotPositive {
                value: distance - radius,
            },
        });
    }
    let up = if direction.normalize().y.abs() > 0.9 {
        Vec3::Z
    } else {
        Vec3::Y
    };
    let half = radius / (distance * distance - radius * radius).sqrt();
    let film = Film::new(size, size, (-half, half), (-half, half))?;
    Ok(PinholeCamera::new(film, 1.0, Frame::look(light, direction, up)?)?.into())
}
