//! Where a path tracer's noise comes from, pixel by pixel.
//!
//! The error of a pixel after N samples is sigma / sqrt(N), sigma^2 the variance of
//! one sample there (lesson 10, step 1). The image's mean squared error is the mean
//! of sigma^2 / N over the pixels, so the pixels with the largest sigma^2 are where
//! the time goes. This measures sigma^2 in every pixel from `spp` samples,
//! sigma^2 = E\[x^2\] - E\[x\]^2 of the grey value (the mean of the three channels),
//! and sorts it by what the pixel's centre ray meets first: the pixels a strategy
//! cannot improve (seen through glass or in a mirror, where only the specular bounce
//! finds the light) set a ceiling on what any light sampling can gain. So do the
//! caustics anywhere: light that reaches a diffuse surface through mirror or glass,
//! which the estimator finds only by following the specular bounce, whatever the
//! strategy; sigma^2 is measured a second time with them left out.

use crate::camera::Camera;
use crate::ray::Interval;
use glam::{DVec4, Vec2, Vec3};
use rayon::prelude::*;

use crate::error::Result;
use crate::framebuffer::Framebuffer;
use crate::material::Material;
use crate::pathtrace::progressive::pixel_ray;
use crate::pathtrace::{At, Path, PixelSampling, Settings};
use crate::rng::Rng;
use crate::scene::Scene;

/// The variance of one sample in every pixel, and the object each pixel's centre
/// ray meets first.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelVariance {
    width: u32,
    height: u32,
    /// sigma^2 of the grey value, row by row.
    variance: Vec<f64>,
    /// sigma^2 of the same samples with their caustic light left out.
    without_caustics: Vec<f64>,
    /// The object the centre ray meets first, or `None` if it escapes.
    first: Vec<Option<usize>>,
}

/// What the camera sees first in a pixel, for the table of where the variance is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Seen {
    /// A diffuse surface: light sampling helps here.
    Diffuse,
    /// A mirror or glass: the light is found only by the specular bounce.
    Specular,
    /// The lamp itself, or nothing.
    LampOrNothing,
}

impl PixelVariance {
    /// sigma^2 in pixel (`x`, `y`).
    pub fn at(&self, x: u32, y: u32) -> f64 {
        self.variance[(y * self.width + x) as usize]
    }

    /// The mean of sigma^2 over the image: N times the image's expected mean squared
    /// error after N samples.
    pub fn mean(&self) -> f64 {
        self.variance.iter().sum::<f64>() / self.variance.len().max(1) as f64
    }

    /// The mean of sigma^2 over the image with the caustic light left out of every
    /// sample: what the variance would be if caustics cost nothing.
    pub fn mean_without_caustics(&self) -> f64 {
        self.without_caustics.iter().sum::<f64>()
            / self.without_caustics.len().max(1) as f64
    }

    /// The part of [`PixelVariance::mean`] that comes from pixels seeing `seen` first:
    /// their sigma^2 summed, over all the image's pixels. The three parts add up to
    /// the mean.
    pub fn mean_in(&self, scene: &Scene, seen: Seen) -> f64 {
        let part: f64 = self
            .variance
            .iter()
            .zip(&self.first)
            .filter(|(_, first)| classify(scene, **first) == seen)
            .map(|(v, _)| v)
            .sum();
        part / self.variance.len().max(1) as f64
    }

    /// The share of pixels whose centre ray meets `seen` first.
    pub fn pixels_seeing(&self, scene: &Scene, seen: Seen) -> f64 {
        let n = self
            .first
            .iter()
            .filter(|f| classify(scene, **f) == seen)
            .count();
        n as f64 / self.first.len().max(1) as f64
    }

    /// The share of the summed sigma^2 in the `fraction` (0..1) of pixels with the
    /// largest sigma^2.
    pub fn top_share(&self, fraction: f64) -> f64 {
        let mut v = self.variance.clone();
        v.sort_by(|a, b| b.total_cmp(a));
        let k = ((v.len() as f64 * fraction).ceil() as usize).min(v.len());
        let total: f64 = v.iter().sum();
        v[..k].iter().sum::<f64>() / total.max(f64::MIN_POSITIVE)
    }

    /// An image of sigma / (sigma + 1) in grey (sigma the standard deviation): black
    /// where a pixel is noise-free, white where one sample's error dwarfs 1.
    pub fn image(&self) -> Result<Framebuffer> {
        Framebuffer::from_fn(self.width, self.height, |x, y| {
            let sigma = self.at(x, y).sqrt() as f32;
            glam::Vec3::splat(sigma / (sigma + 1.0))
        })
    }
}

fn classify(scene: &Scene, first: Option<usize>) -> Seen {
    match first.map(|i| &scene.objects()[i]) {
        Some(o) if o.is_emissive() => Seen::LampOrNothing,
        Some(o) => match o.material {
            Material::Diffuse { .. } => Seen::Diffuse,
            _ => Seen::Specular,
        },
        None => Seen::LampOrNothing,
    }
}

/// sigma^2 in every pixel of `camera`'s image from `spp` samples with `settings`,
/// each pixel's random stream seeded from (`seed`, x, y), on the current thread pool.
pub fn pixel_variance(
    scene: &Scene,
    camera: &Camera,
    settings: &Settings,
    spp: u32,
    seed: u64,
) -> Result<PixelVariance> {
    let (width, height) = (camera.film().width(), camera.film().height());
    let pixel = |i: usize| -> ((f64, f64), Option<usize>) {
        let (x, y) = ((i % width as usize) as u32, (i / width as usize) as u32);
        let mut rng = Rng::for_pixel(seed, x, y);
        let corner = Vec2::new(x as f32, y as f32);
        // Sums of x, x^2 for the whole sample and for its part without caustics.
        let mut moments = DVec4::ZERO;
        for s in 0..spp {
            let ray =
                pixel_ray(camera, corner, PixelSampling::Independent, spp, s, &mut rng);
            let (sample, caustics) =
                with_caustics(scene, Path::new(scene, ray, &mut rng, settings));
            let grey = f64::from(sample.element_sum() / 3.0);
            let rest = grey - f64::from(caustics.element_sum() / 3.0);
            if grey.is_finite() && rest.is_finite() {
                moments += DVec4::new(grey, grey * grey, rest, rest * rest);
            }
        }
        let m = moments / f64::from(spp.max(1));
        let centre = camera.ray_through(corner + Vec2::splat(0.5), Vec2::splat(0.5));
        let first = scene
            .closest(&centre, Interval::AHEAD)
            .map(|found| found.object);
        let variance = |mean: f64, square: f64| (square - mean * mean).max(0.0);
        ((variance(m.x, m.y), variance(m.z, m.w)), first)
    };
    let n = width as usize * height as usize;
    let (both, first): (Vec<(f64, f64)>, _) = (0..n).into_par_iter().map(pixel).unzip();
    let (variance, without_caustics) = both.into_iter().unzip();
    Ok(PixelVariance {
        width,
        height,
        variance,
        without_caustics,
        first,
    })
}

/// The sample of one path (its light summed as [`crate::pathtrace::radiance`] sums
/// it) and the part of it that is caustic: light seen after a mirror or glass bounce
/// that follows a diffuse vertex (only the specular bounce can find it; light
/// sampling cannot help).
fn with_caustics(scene: &Scene, path: Path<'_, Scene>) -> (Vec3, Vec3) {
    let (mut sample, mut caustics) = (Vec3::ZERO, Vec3::ZERO);
    // A diffuse vertex, then only specular ones since: what is seen now is a caustic.
    let (mut diffuse_seen, mut caustic) = (false, false);
    for vertex in path {
        sample += vertex.emitted;
        if caustic {
            caustics += vertex.emitted;
        }
        sample += vertex.direct;
        if let At::Surface { object, .. } = vertex.at {
            let diffuse =
                matches!(scene.objects()[object].material, Material::Diffuse { .. });
            (diffuse_seen, caustic) =
                (diffuse_seen || diffuse, diffuse_seen && !diffuse);
        }
    }
    (sample, caustics)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pathtrace::{Sampling, radiance};
    use crate::scenes::path_tracing::{Staged, cornell};

    /// The measurement watches the estimator's own path: its sample is, bit for bit,
    /// the one `radiance` returns, and the caustic part is a part of it.
    #[test]
    fn the_watched_sample_is_the_estimators() {
        let Staged { scene, camera } = cornell(16, 12).unwrap();
        for sampling in Sampling::ALL {
            let settings = Settings {
                sampling,
                ..Settings::default()
            };
            for (x, y) in (0..12).flat_map(|y| (0..16).map(move |x| (x, y))) {
                let mut rng = Rng::for_pixel(3, x, y);
                let ray =
                    camera.ray_through(Vec2::new(x as f32, y as f32), rng.next_vec2());
                let mut watched = rng;
                let plain = radiance(&scene, ray, &mut rng, &settings);
                let path = Path::new(&scene, ray, &mut watched, &settings);
                let (sample, caustics) = with_caustics(&scene, path);
                let bits = |v: Vec3| v.to_array().map(f32::to_bits);
                assert_eq!(bits(sample), bits(plain), "({x}, {y}) {sampling:?}");
                assert!(caustics.cmple(sample).all(), "({x}, {y}) {sampling:?}");
                assert_eq!(watched.next_u32(), rng.next_u32());
            }
        }
    }
}
