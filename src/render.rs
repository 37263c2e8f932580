//! Rendering an image: one call of a per-ray function for every pixel, rows in
//! parallel (rayon), with a progress bar on a terminal (indicatif).
//!
//! Each pixel's colour depends only on its own ray, so the image is the same bit for
//! bit whatever the number of threads.

use glam::Vec3;
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;

use crate::camera::Camera;
use crate::error::{Error, Result};
use crate::framebuffer::Framebuffer;
use crate::ray::Ray;

/// Renders with more pixels than this show a progress bar (when stderr is a terminal).
pub const PROGRESS_PIXELS: u64 = 1 << 20;

// ANCHOR: render
/// The image `camera` sees, each pixel coloured by `shade` of its ray through the
/// pixel centre. `threads` = `None` uses every core.
pub fn render(
    camera: &Camera,
    threads: Option<usize>,
    shade: impl Fn(&Ray) -> Vec3 + Sync,
) -> Result<Framebuffer> {
    let (width, height) = (camera.film().width(), camera.film().height());
    let progress = progress_bar(u64::from(width) * u64::from(height), height);
    let mut pixels = vec![Vec3::ZERO; width as usize * height as usize];
    let shade_row = |(y, row): (usize, &mut [Vec3])| {
        let mut rays = camera.row(y as u32);
        for pixel in row.iter_mut() {
            *pixel = shade(&rays.next_ray());
        }
        progress.inc(1);
    };
    in_pool(threads, || {
        pixels
            .par_chunks_mut(width as usize)
            .enumerate()
            .for_each(shade_row)
    })?;
    progress.finish_and_clear();
    Framebuffer::from_pixels(width, height, pixels)
}
// ANCHOR_END: render

/// Runs `work` on a pool of `threads` threads, or on rayon's global pool.
pub fn in_pool<T: Send>(threads: Option<usize>, work: impl FnOnce() -> T + Send) -> Result<T> {
    match threads {
        None => Ok(work()),
        Some(n) => {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| Error::Io {
                    path: "thread pool".into(),
                    message: e.to_string(),
                })?;
            Ok(pool.install(work))
        }
    }
}

/// A bar counting rows, hidden for small work (`work` below [`PROGRESS_PIXELS`]:
/// pixels, or pixels times primitives for a brute-force cast) and when stderr is not
/// a terminal (indicatif hides itself then).
pub(crate) fn progress_bar(work: u64, rows: u32) -> ProgressBar {
    if work <= PROGRESS_PIXELS {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(u64::from(rows));
    if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} rows, {eta} left") {
        bar.set_style(style);
    }
    bar
}
