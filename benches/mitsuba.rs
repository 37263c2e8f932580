//! The Mitsuba anchor of the path-tracing bench: Mitsuba 3 renders the scene the
//! crate describes (lesson 10's Cornell box, `scripts/cross_check.py`'s
//! `mitsuba_dict`) on one thread, timed inside its own process by
//! `scripts/cross_check.py time` (the kernels of `llvm_ad_rgb` compiled by a first,
//! untimed render). Mitsuba lives in the venv `scripts/cross-check` installs
//! (`target/cross-check/venv`, pinned by `scripts/cross_check_requirements.txt`);
//! `llvm_ad_rgb` needs libLLVM 16 or later (Debian: `libllvm19`), which the script
//! finds or names.

use std::path::{Path, PathBuf};
use std::process::Command;

use render_lessons::framebuffer::Framebuffer;
use render_lessons::framebuffer::pfm::load_pfm;

/// The variants timed, fastest first.
pub const VARIANTS: [&str; 2] = ["llvm_ad_rgb", "scalar_rgb"];

/// The scene, image and estimator of the comparison, as `cross_check.py time` and
/// the crate's `cross-check render` take them: lesson 10's Cornell box, MIS, at most
/// 8 bounces (Mitsuba's max_depth 9: it counts the camera ray), no Russian roulette.
#[derive(Clone, Copy, Debug)]
pub struct View {
    /// Pixels across.
    pub width: u32,
    /// Pixels down.
    pub height: u32,
    /// The most bounces a path takes (the crate's count).
    pub max_depth: u32,
}

/// One timed Mitsuba render.
#[derive(Debug)]
pub struct Render {
    /// Mitsuba's version, e.g. "3.9.1".
    pub version: String,
    /// The render's wall-clock time.
    pub seconds: f64,
    /// Path samples: pixels times samples per pixel.
    pub samples: u64,
    /// The image (mean radiance per pixel).
    pub image: Framebuffer,
}

/// The repository's root (this package is its folder `benches/`).
fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The venv's Python, or why there is none and how to make it.
fn python() -> Result<PathBuf, String> {
    let python = root().join("target/cross-check/venv/bin/python");
    if python.exists() {
        Ok(python)
    } else {
        Err("Mitsuba is not installed: run scripts/cross-check once, which installs \
             Mitsuba 3 into target/cross-check/venv (pip, scripts/cross_check_requirements.txt)"
            .to_string())
    }
}

/// Renders `view` in Mitsuba's `variant` at `spp` samples per pixel with `seed`,
/// on one thread, writing the image to `out`; an error says why it could not
/// (no venv, no libLLVM for `llvm_ad_rgb`, a failed render).
pub fn render(
    variant: &str,
    view: View,
    spp: u32,
    seed: u64,
    out: &Path,
) -> Result<Render, String> {
    let output = Command::new(python()?)
        .current_dir(root())
        .arg("scripts/cross_check.py")
        .arg("time")
        .args(["--scene", "cornell", "--sampling", "mis", "--threads", "1"])
        .args(["--variant", variant])
        .args(["--max-depth", &view.max_depth.to_string()])
        .args(["--width", &view.width.to_string()])
        .args(["--height", &view.height.to_string()])
        .args(["--spp", &spp.to_string(), "--seed", &seed.to_string()])
        .arg("--out")
        .arg(out)
        .output()
        .map_err(|e| format!("could not run the venv's Python: {e}"))?;
    if !output.status.success() {
        let stderr = String::from_utf8_lossy(&output.stderr);
        let last = stderr.lines().last().unwrap_or("no message").trim();
        return Err(last.to_string());
    }
    let stdout = String::from_utf8_lossy(&output.stdout);
    let line = stdout.lines().last().unwrap_or_default();
    let json: serde_json::Value = serde_json::from_str(line)
        .map_err(|e| format!("cross_check.py time printed '{line}': {e}"))?;
    let field = |name: &str| {
        json.get(name)
            .cloned()
            .ok_or(format!("cross_check.py time printed no '{name}': {line}"))
    };
    let seconds = field("seconds")?
        .as_f64()
        .ok_or("seconds is not a number")?;
    let samples = field("samples")?.as_u64().ok_or("samples is not a count")?;
    let version = field("mitsuba")?.as_str().unwrap_or("?").to_string();
    let image = load_pfm(out).map_err(|e| e.to_string())?;
    Ok(Render {
        version,
        seconds,
        samples,
        image,
    })
}

/// How far apart two images' expected values are, as a z-score: the mean over the
/// pixels of their difference, in units of its standard error (the pixels are
/// independent, so the spread of the per-pixel differences estimates it). Two
/// renderers of the same scene give |z| of a few at most; a different scene, depth
/// or light gives hundreds (and images of different sizes infinity).
pub fn z_of_means(a: &Framebuffer, b: &Framebuffer) -> f64 {
    let (w, h) = (a.width(), a.height());
    if (w, h) != (b.width(), b.height()) {
        return f64::INFINITY;
    }
    let d: Vec<f64> = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| {
            let (p, q) = (a.get(x, y), b.get(x, y));
            let (p, q) = (p.unwrap_or_default(), q.unwrap_or_default());
            f64::from((p - q).element_sum()) / 3.0
        })
        .collect();
    let n = d.len() as f64;
    let mean = d.iter().sum::<f64>() / n;
    let var = d.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    mean / (var / n).sqrt()
}
