//! Progressive rendering: passes of samples added to per-pixel sums, the image being
//! their mean at any time.
//!
//! Every pixel keeps its own random stream ([`Rng::for_pixel`]) from pass to pass,
//! so its samples are drawn in the same order whatever the number of threads and
//! however the samples are split into passes: with independent pixel samples, one
//! pass of 4 samples and two passes of 2 give the same image bit for bit. (Jittered
//! samples are stratified within a pass, so the split changes which strata are used;
//! a fixed split is still bit for bit repeatable.) Sums are f64: after many samples
//! an f32 sum would stop growing by small samples.

use glam::{DVec3, Vec2, Vec3};
use rayon::prelude::*;

use crate::camera::Camera;
use crate::error::{Error, Problem, Result};
use crate::framebuffer::Framebuffer;
use crate::pathtrace::estimator::radiance;
use crate::pathtrace::settings::Settings;
use crate::ray::Ray;
use crate::rng::Rng;
use crate::sampling::strata;
use crate::scene::Intersect;

/// Where in its pixel each sample's camera ray passes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelSampling {
    /// Uniformly anywhere in the pixel, each sample on its own.
    Independent,
    /// Jittered (stratified): the pixel cut into sqrt(spp) x sqrt(spp) cells, one
    /// uniform sample in each; spp must be a square number.
    Jittered,
}

impl PixelSampling {
    /// `Jittered` if `jitter`, else `Independent` (as a flag chooses).
    pub fn jittered(jitter: bool) -> PixelSampling {
        if jitter {
            PixelSampling::Jittered
        } else {
            PixelSampling::Independent
        }
    }
}

/// Per-pixel sums of radiance samples, and the random streams that continue them.
#[derive(Clone, Debug)]
pub struct Accumulator {
    width: u32,
    height: u32,
    sums: Vec<DVec3>,
    rngs: Vec<Rng>,
    samples: u32,
    non_finite: u64,
}

impl Accumulator {
    /// Empty sums for `camera`'s film, streams seeded from (`seed`, x, y).
    pub fn new(camera: &Camera, seed: u64) -> Accumulator {
        let (width, height) = (camera.film().width(), camera.film().height());
        let rngs = (0..height)
            .flat_map(|y| (0..width).map(move |x| Rng::for_pixel(seed, x, y)))
            .collect();
        Accumulator {
            width,
            height,
            sums: vec![DVec3::ZERO; width as usize * height as usize],
            rngs,
            samples: 0,
            non_finite: 0,
        }
    }

    /// Samples per pixel so far.
    pub fn samples(&self) -> u32 {
        self.samples
    }

    /// How many samples were NaN or infinite and counted as 0 instead. The estimator
    /// guards every division, so this should stay 0; the tests check that it does.
    pub fn non_finite(&self) -> u64 {
        self.non_finite
    }

    // ANCHOR: render_pass
    /// Adds `spp` samples to every pixel, rows in parallel on the current thread
    /// pool, and returns the mean image so far.
    pub fn render_pass(
        &mut self,
        scene: &impl Intersect,
        camera: &Camera,
        settings: &Settings,
        pixels: PixelSampling,
        spp: u32,
    ) -> Result<Framebuffer> {
        check_pass(self, camera, settings, pixels, spp)?;
        let width = self.width as usize;
        let row = |(y, (sums, rngs)): (usize, (&mut [DVec3], &mut [Rng]))| -> u64 {
            let mut bad = 0;
            for (x, (sum, rng)) in sums.iter_mut().zip(rngs).enumerate() {
                for i in 0..spp {
                    let pixel = Vec2::new(x as f32, y as f32);
                    let ray = pixel_ray(camera, pixel, pixels, spp, i, rng);
                    let sample = radiance(scene, ray, rng, settings);
                    // A documented guard, not a fix: counted, and tested to stay 0.
                    if sample.is_finite() {
                        *sum += sample.as_dvec3();
                    } else {
                        bad += 1;
                    }
                }
            }
            bad
        };
        let (sums, rngs) = (&mut self.sums, &mut self.rngs);
        let bad: u64 = sums
            .par_chunks_mut(width)
            .zip(rngs.par_chunks_mut(width))
            .enumerate()
            .map(row)
            .sum();
        self.non_finite += bad;
        self.samples += spp;
        self.image()
    }
    // ANCHOR_END: render_pass

    /// The mean of the samples so far (black before the first pass).
    pub fn image(&self) -> Result<Framebuffer> {
        let n = f64::from(self.samples.max(1));
        let pixels = self.sums.iter().map(|s| (*s / n).as_vec3()).collect();
        Framebuffer::from_pixels(self.width, self.height, pixels)
    }
}

fn check_pass(
    acc: &Accumulator,
    camera: &Camera,
    settings: &Settings,
    pixels: PixelSampling,
    spp: u32,
) -> Result<()> {
    settings.check()?;
    if spp == 0 {
        return Err(Error::Value {
            param: "spp",
            problem: Problem::TooFew { value: spp, min: 1 },
        });
    }
    if pixels == PixelSampling::Jittered && !strata(spp).is_square() {
        return Err(Error::Value {
            param: "spp",
            problem: Problem::Invalid {
                reason: "must be a square number (1, 4, 9, 16, ...) for jittered sampling",
            },
        });
    }
    if (camera.film().width(), camera.film().height()) != (acc.width, acc.height) {
        return Err(Error::Value {
            param: "camera",
            problem: Problem::Invalid {
                reason: "must have the film size the accumulator was made for",
            },
        });
    }
    if acc.samples.checked_add(spp).is_none() {
        return Err(Error::Value {
            param: "spp",
            problem: Problem::Invalid {
                reason: "would overflow the sample count",
            },
        });
    }
    Ok(())
}

/// The camera ray of sample `i` of `spp` in the pixel whose corner is `pixel`: a
/// point in the pixel, then a point on the lens, both drawn from `rng`.
pub fn pixel_ray(
    camera: &Camera,
    pixel: Vec2,
    pixels: PixelSampling,
    spp: u32,
    i: u32,
    rng: &mut Rng,
) -> Ray {
    let position = pixel + pixel_offset(pixels, spp, i, rng);
    camera.ray_through(position, rng.next_vec2())
}

// ANCHOR: pixel_offset
/// Where sample `i` of `spp` falls in its pixel, in [0, 1)^2.
fn pixel_offset(pixels: PixelSampling, spp: u32, i: u32, rng: &mut Rng) -> Vec2 {
    let u = rng.next_vec2();
    match pixels {
        PixelSampling::Independent => u,
        PixelSampling::Jittered => strata(spp).point(i, u),
    }
}
// ANCHOR_END: pixel_offset

/// How the passes of a progressive render are run: where samples fall in their
/// pixel, and the seed of the pixels' streams. They run on the current thread pool;
/// the images do not depend on its size.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Passes {
    /// Where in its pixel each sample's camera ray passes.
    pub pixels: PixelSampling,
    /// The seed of the per-pixel streams.
    pub seed: u64,
}

/// One finished pass of [`render_progressive`].
#[derive(Clone, Debug)]
pub struct Pass {
    /// Samples per pixel so far.
    pub samples: u32,
    /// Samples per pixel this pass added.
    pub added: u32,
    /// The mean image so far.
    pub image: Framebuffer,
}

// ANCHOR: render_progressive
/// A progressive render from one accumulator: passes that end at each of `stops`
/// samples per pixel (increasing), `each` called after every pass. Returns the
/// number of samples dropped as NaN or infinite. An error of `each` (its type `E` is
/// the caller's: a lesson stops on Ctrl-C) ends the render and is returned.
pub fn render_progressive<E: From<Error>>(
    scene: &impl Intersect,
    camera: &Camera,
    settings: &Settings,
    passes: Passes,
    stops: &[u32],
    mut each: impl FnMut(Pass) -> std::result::Result<(), E>,
) -> std::result::Result<u64, E> {
    let mut acc = Accumulator::new(camera, passes.seed);
    for &stop in stops {
        let Some(added) = stop.checked_sub(acc.samples()) else {
            return Err(Error::Value {
                param: "stops",
                problem: Problem::Invalid {
                    reason: "must increase",
                },
            }
            .into());
        };
        let image = acc.render_pass(scene, camera, settings, passes.pixels, added)?;
        let film = camera.film();
        let taken = u64::from(acc.samples())
            * u64::from(film.width())
            * u64::from(film.height());
        if acc.non_finite() == taken {
            // Not one usable sample: the image would be black. Say so instead.
            return Err(Error::Value {
                param: "scene",
                problem: Problem::Invalid {
                    reason: "gave NaN or infinity in every sample: no image to show",
                },
            }
            .into());
        }
        each(Pass {
            samples: stop,
            added,
            image,
        })?;
    }
    Ok(acc.non_finite())
}
// ANCHOR_END: render_progressive

/// The root mean square difference between two images of the same size, over all
/// channels, in f64.
pub fn rmse(a: &Framebuffer, b: &Framebuffer) -> f64 {
    let mut sum = 0.0;
    let mut n = 0.0f64;
    for y in 0..a.height().min(b.height()) {
        for x in 0..a.width().min(b.width()) {
            let d = a.get(x, y).unwrap_or(Vec3::ZERO).as_dvec3()
                - b.get(x, y).unwrap_or(Vec3::ZERO).as_dvec3();
            sum += d.length_squared();
            n += 3.0;
        }
    }
    (sum / n.max(1.0)).sqrt()
}
