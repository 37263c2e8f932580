//! Lesson 10's flags, in three groups, and the core values each group makes: the
//! estimator's [`Settings`] (`--sampling`, `--max-depth`, `--rr`/`--no-rr`), the
//! convergence [`Study`] (`--spp`, `--reference-spp`, `--jitter`, `--seed`) and the
//! thin lens (`--aperture`, `--focus`). Every value is checked when it is parsed or
//! when the core value is made, before any work.

use crate::course::convergence::{Study, ladder};
use crate::course::parsers;
use crate::error::Result;
use crate::pathtrace::{Passes, PixelSampling, Sampling, Settings};

/// How the estimator follows a path: `--sampling`, `--max-depth`, `--rr`/`--no-rr`.
#[derive(clap::Args, Clone, Copy, Debug)]
pub struct PathFlags {
    /// How directions are chosen at diffuse surfaces.
    #[arg(long, value_enum, default_value_t = Sampling::Mis)]
    pub sampling: Sampling,
    /// The most bounces a path may take.
    #[arg(long, default_value_t = 8)]
    pub max_depth: u32,
    /// Russian roulette on (the default; the last of --rr and --no-rr wins).
    #[arg(long = "rr", overrides_with = "no_rr")]
    pub rr: bool,
    /// Russian roulette off: every path runs to --max-depth unless it escapes.
    #[arg(long = "no-rr", overrides_with = "rr")]
    pub no_rr: bool,
}

impl PathFlags {
    /// The estimator's settings these flags ask for.
    pub fn settings(&self) -> Settings {
        Settings {
            sampling: self.sampling,
            max_depth: Some(self.max_depth),
            russian_roulette: !self.no_rr,
            ..Settings::default()
        }
    }
}

/// What is rendered and measured: `--spp`, `--reference-spp`, `--jitter`, `--seed`.
#[derive(clap::Args, Clone, Copy, Debug)]
pub struct StudyFlags {
    /// The largest sample count of the ladder 1, 4, 16, ... (powers of 4 up to it).
    #[arg(long, default_value_t = 64)]
    pub spp: u32,
    /// Samples per pixel of the reference image the errors are measured against.
    #[arg(long, default_value_t = 512)]
    pub reference_spp: u32,
    /// Jittered (stratified) pixel samples; every sample count must then be a square.
    #[arg(long)]
    pub jitter: bool,
    /// Seed of the random streams (one per pixel); the images do not depend on
    /// --threads.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
}

impl StudyFlags {
    /// The study these flags ask for, of the estimator with `settings`; an error
    /// naming `--spp` if the ladder is empty.
    pub fn study(&self, settings: Settings) -> Result<Study> {
        Ok(Study {
            settings,
            ladder: ladder(self.spp)?,
            passes: Passes {
                pixels: PixelSampling::jittered(self.jitter),
                seed: self.seed,
            },
            reference_spp: self.reference_spp,
        })
    }
}

/// The thin lens: `--aperture` (0: a pinhole) and `--focus`.
#[derive(clap::Args, Clone, Copy, Debug)]
pub struct LensFlags {
    /// Lens radius of the thin-lens camera (0: pinhole).
    #[arg(long, default_value = "0", value_parser = parsers::non_negative)]
    pub aperture: f32,
    /// Distance of the plane in focus (default: about that of the Cornell box's glass
    /// sphere).
    #[arg(long, default_value = "220", value_parser = parsers::positive)]
    pub focus: f32,
}
