//! What the path tracer's estimator can be asked to do: the sampling strategy, the
//! path length, Russian roulette, and how rays leave surfaces.

use crate::error::{Error, Problem, Result};
use crate::pathtrace::light::SphereSampling;
use crate::spawn::Offset;

/// How directions at diffuse vertices are chosen, and emitters found. A point light
/// is found the same way by all four: a shadow ray to it at every diffuse vertex
/// (no direction chosen at random can meet a point).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sampling {
    /// Uniform over the hemisphere (BRDF-blind).
    UniformHemisphere,
    /// Cosine-weighted (importance sampling of Lambert's f_r cos).
    Cosine,
    /// Cosine-weighted bounces plus one light sample per diffuse vertex.
    NextEvent,
    /// Both strategies combined by the power heuristic.
    Mis,
}

impl Sampling {
    /// All four, worst first.
    pub const ALL: [Sampling; 4] = [
        Sampling::UniformHemisphere,
        Sampling::Cosine,
        Sampling::NextEvent,
        Sampling::Mis,
    ];

    /// The strategy's name in tables.
    pub fn name(self) -> &'static str {
        match self {
            Sampling::UniformHemisphere => "uniform hemisphere",
            Sampling::Cosine => "cosine",
            Sampling::NextEvent => "next event",
            Sampling::Mis => "MIS",
        }
    }

    /// Its value after the lesson's `--sampling`, also used in file names.
    pub fn flag(self) -> &'static str {
        match self {
            Sampling::UniformHemisphere => "uniform",
            Sampling::Cosine => "cosine",
            Sampling::NextEvent => "nee",
            Sampling::Mis => "mis",
        }
    }
}

/// Everything that chooses how a path is traced.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// How directions are chosen at diffuse vertices.
    pub sampling: Sampling,
    /// How spherical lights are sampled (NextEvent and Mis).
    pub sphere_lights: SphereSampling,
    /// The most bounces a path may take. With d bounces emission is gathered from
    /// at most d + 1 surfaces (d = 0: only the emission the camera ray meets), so the
    /// interior furnace at d = 8 gives 0.5 (1 - 0.5^9) / (1 - 0.5) (STABILITY S16).
    /// `None`: no limit; then Russian roulette must be on.
    pub max_depth: Option<u32>,
    /// Ends paths at random from bounce
    /// [`RR_START`](crate::pathtrace::roulette::RR_START) on, unbiased.
    pub russian_roulette: bool,
    /// How bounce and shadow rays leave their surface (STABILITY S13, S17).
    pub offset: Offset,
}

impl Default for Settings {
    /// MIS, cone-sampled spheres, depth 8, Russian roulette, error-bound offset.
    fn default() -> Settings {
        Settings {
            sampling: Sampling::Mis,
            sphere_lights: SphereSampling::Cone,
            max_depth: Some(8),
            russian_roulette: true,
            offset: Offset::ErrorBound,
        }
    }
}

impl Settings {
    /// `Ok` if paths are certain to end and the offset is a usable number.
    pub fn check(&self) -> Result<()> {
        if self.max_depth.is_none() && !self.russian_roulette {
            return Err(Error::Value {
                param: "max_depth",
                problem: Problem::Invalid {
                    reason: "must be set when Russian roulette is off (paths would never end)",
                },
            });
        }
        if let Offset::Fixed(e) = self.offset
            && !(e.is_finite() && e >= 0.0)
        {
            return Err(Error::Value {
                param: "offset",
                problem: Problem::Invalid {
                    reason: "must be a finite distance >= 0",
                },
            });
        }
        Ok(())
    }
}
