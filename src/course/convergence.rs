//! A convergence study, lesson 10's experiment: one progressive render up a ladder
//! of sample counts, every sampling strategy at the ladder's top, and a reference of
//! many more samples to measure their errors against.

use crate::camera::Camera;
use crate::error::{Error, Problem, Result, Shortfall};
use crate::framebuffer::Framebuffer;
use crate::pathtrace::progressive::{Pass, Passes, PixelSampling, render_progressive};
use crate::pathtrace::settings::{Sampling, Settings};
use crate::scene::Intersect;

/// What a study renders.
#[derive(Clone, Debug, PartialEq)]
pub struct Study {
    /// The estimator's settings for the ladder (the strategies change only the
    /// sampling).
    pub settings: Settings,
    /// The sample counts of the ladder, increasing (see [`ladder`]).
    pub ladder: Vec<u32>,
    /// Pixel sampling, seed and threads of every render (the reference's seed differs).
    pub passes: Passes,
    /// Samples per pixel of the reference (MIS).
    pub reference_spp: u32,
}

/// The images of a study.
#[derive(Clone, Debug)]
pub struct Renders {
    /// (samples per pixel, image) for each rung of the ladder.
    pub ladder: Vec<(u32, Framebuffer)>,
    /// Every strategy's image at the ladder's top, in the order of [`Sampling::ALL`].
    pub strategies: Vec<(Sampling, Framebuffer)>,
    /// The reference.
    pub reference: Framebuffer,
    /// Samples dropped as NaN or infinite: should be 0.
    pub non_finite: u64,
}

/// Which image of a study a pass belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// The ladder.
    Ladder,
    /// A strategy other than the ladder's, at the ladder's top.
    Strategy(Sampling),
    /// The reference.
    Reference,
}

/// The seed of the reference is the study's plus this, so that its noise is
/// independent of the images it measures.
const REFERENCE_SEED_OFFSET: u64 = 0x9e37_79b9;

impl Study {
    /// Samples per pixel [`Study::render`] takes in all, for a progress bar.
    pub fn samples(&self) -> u64 {
        let top = u64::from(self.ladder.last().copied().unwrap_or(0));
        let ladder = match self.passes.pixels {
            PixelSampling::Jittered => self.ladder.iter().map(|&n| u64::from(n)).sum(),
            PixelSampling::Independent => top,
        };
        ladder + (Sampling::ALL.len() as u64 - 1) * top + u64::from(self.reference_spp)
    }

    /// `Ok` unless jittered passes would be asked for a sample count that is not a
    /// square: checked before the first pass, so that a bad `--spp` writes nothing.
    fn check_jittered(&self, reference_stops: &[u32]) -> Result<()> {
        if self.passes.pixels != PixelSampling::Jittered {
            return Ok(());
        }
        let square = |n: u32| {
            let root = f64::from(n).sqrt().round() as u32;
            root * root == n
        };
        let not_square = |param| Error::Value {
            param,
            problem: Problem::Invalid {
                reason: "must be a square number (1, 4, 9, 16, ...) for jittered sampling",
            },
        };
        if !self.ladder.iter().all(|&n| square(n)) {
            return Err(not_square("spp"));
        }
        let mut previous = 0;
        for &stop in reference_stops {
            if !square(stop - previous) {
                return Err(not_square("reference-spp"));
            }
            previous = stop;
        }
        Ok(())
    }

    // ANCHOR: render
    /// Every image of the study, each a progressive render: the ladder is one render
    /// stopping at each rung; the other strategies render the ladder's top; the
    /// reference renders MIS in passes of 16, with its own seed. Jittered passes need
    /// a square number of samples (1, 4, 16 are; 3, 12, 48 are not), so with them
    /// every rung is rendered afresh. `watch` sees every pass, and of which image; its
    /// error (of the caller's type `E`) stops the study.
    pub fn render<E: From<Error>>(
        &self,
        scene: &impl Intersect,
        camera: &Camera,
        mut watch: impl FnMut(Part, &Pass) -> std::result::Result<(), E>,
    ) -> std::result::Result<Renders, E> {
        let reference_stops = stops_of_16(self.reference_spp, "reference-spp")?;
        self.check_jittered(&reference_stops)?;
        let top = *self.ladder.last().ok_or(Error::Value {
            param: "spp",
            problem: Problem::TooFew { value: 0, min: 1 },
        })?;
        let mut non_finite = 0;
        let mut render = |part, settings: Settings, passes, stops: &[u32]| {
            let mut images = Vec::new();
            non_finite +=
                render_progressive(scene, camera, &settings, passes, stops, |pass| {
                    watch(part, &pass)?;
                    images.push((pass.samples, pass.image));
                    Ok::<(), E>(())
                })?;
            Ok::<_, E>(images)
        };
        let (settings, passes) = (self.settings, self.passes);
        let mut ladder = Vec::new();
        match passes.pixels {
            PixelSampling::Independent => {
                ladder = render(Part::Ladder, settings, passes, &self.ladder)?
            }
            PixelSampling::Jittered => {
                for &spp in &self.ladder {
                    ladder.extend(render(Part::Ladder, settings, passes, &[spp])?);
                }
            }
        }
        let mut strategies = Vec::new();
        for sampling in Sampling::ALL {
            let image = if sampling == settings.sampling {
                ladder.last().cloned()
            } else {
                let other = Settings {
                    sampling,
                    ..settings
                };
                render(Part::Strategy(sampling), other, passes, &[top])?.pop()
            };
            strategies.extend(image.map(|(_, image)| (sampling, image)));
        }
        let mis = Settings {
            sampling: Sampling::Mis,
            ..settings
        };
        let seed = passes.seed.wrapping_add(REFERENCE_SEED_OFFSET);
        let passes = Passes { seed, ..passes };
        let reference = render(Part::Reference, mis, passes, &reference_stops)?;
        let reference = reference.into_iter().last().map(|(_, image)| image);
        Ok(Renders {
            ladder,
            strategies,
            reference: reference.ok_or(Error::Value {
                param: "reference-spp",
                problem: Problem::TooFew { value: 0, min: 1 },
            })?,
            non_finite,
        })
    }
    // ANCHOR_END: render
}

/// The sample counts 1, 4, 16, ... up to `spp` (`spp` itself last if it is not a
/// power of 4): the error should halve from one to the next.
pub fn ladder(spp: u32) -> Result<Vec<u32>> {
    spp_in_range("spp", spp)?;
    let mut steps: Vec<u32> = std::iter::successors(Some(1u32), |n| n.checked_mul(4))
        .take_while(|&n| n <= spp)
        .collect();
    if steps.last() != Some(&spp) {
        steps.push(spp);
    }
    Ok(steps)
}

/// The most samples per pixel a study takes: a million, 2^14 times the lesson's
/// 64 (at 160 x 120 it would run for days; any more is a typo).
pub const MAX_SPP: u32 = 1 << 20;

/// `Ok` if `spp` lies in 1..=[`MAX_SPP`]; an error naming `param` otherwise.
fn spp_in_range(param: &'static str, spp: u32) -> Result<()> {
    if spp == 0 {
        return Err(Error::Value {
            param,
            problem: Problem::TooFew { value: 0, min: 1 },
        });
    }
    if spp > MAX_SPP {
        return Err(Error::Machine {
            param,
            shortfall: Shortfall::TooMuch {
                needed: u64::from(spp),
                limit: u64::from(MAX_SPP),
                unit: "samples per pixel",
            },
        });
    }
    Ok(())
}

/// Stops every 16 samples up to `spp` (and `spp` itself), so that a long render
/// can be watched as it sharpens. An error naming `param` if `spp` is 0.
fn stops_of_16(spp: u32, param: &'static str) -> Result<Vec<u32>> {
    spp_in_range(param, spp)?;
    let mut stops: Vec<u32> = (1..=spp / 16).map(|i| i * 16).collect();
    if stops.last() != Some(&spp) {
        stops.push(spp);
    }
    Ok(stops)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ladder_is_powers_of_4_then_spp() {
        assert_eq!(ladder(64).unwrap(), [1, 4, 16, 64]);
        assert_eq!(ladder(100).unwrap(), [1, 4, 16, 64, 100]);
        assert_eq!(ladder(1).unwrap(), [1]);
        assert_eq!(ladder(0).unwrap_err().param(), "spp");
    }
}
