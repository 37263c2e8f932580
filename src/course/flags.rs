//! The values of the lessons' flags that name core types (`--sampling mis`,
//! `--scene cornell`, `--up z`): the renderer knows nothing of command lines, so the
//! parsing lives here, with the course's tools.

use clap::ValueEnum;
use clap::builder::PossibleValue;

use crate::pathtrace::settings::Sampling;
use crate::scenes::Up;
use crate::scenes::path_tracing::SceneName;

/// `--sampling uniform|cosine|nee|mis`.
impl ValueEnum for Sampling {
    fn value_variants<'a>() -> &'a [Sampling] {
        &Sampling::ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.flag()).help(self.name()))
    }
}

/// `--scene cornell|two-lights|furnace|grey-furnace|teapot`.
impl ValueEnum for SceneName {
    fn value_variants<'a>() -> &'a [SceneName] {
        &SceneName::ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        let (name, help) = match self {
            SceneName::Cornell => (
                "cornell",
                "smallpt's Cornell box, walls as planes, a square ceiling light",
            ),
            SceneName::TwoLights => (
                "two-lights",
                "A floor under a small and a large spherical light",
            ),
            SceneName::Furnace => (
                "furnace",
                "Inside a glowing sphere of albedo 0.5 (STABILITY S16)",
            ),
            SceneName::GreyFurnace => (
                "grey-furnace",
                "A grey sphere in a white environment (STABILITY S17)",
            ),
            SceneName::Teapot => (
                "teapot",
                "The Cornell box with the Newell teapot (4032 triangles), through a BVH",
            ),
        };
        Some(PossibleValue::new(name).help(help))
    }
}

/// `--up y|z`.
impl ValueEnum for Up {
    fn value_variants<'a>() -> &'a [Up] {
        &[Up::Y, Up::Z]
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        let (name, help) = match self {
            Up::Y => ("y", "y up, as most modelling tools write"),
            Up::Z => ("z", "z up: scans, CAD and 3D-printing files"),
        };
        Some(PossibleValue::new(name).help(help))
    }
}
