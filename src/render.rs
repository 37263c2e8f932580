//! Rendering an image: one call of a per-ray function for every pixel, rows in
//! parallel (rayon), with a progress bar on a terminal (indicatif).
//!
//! Each pixel's colour depends only on its own ray, so the image is the same bit for
//! bit whatever the number of threads.

use glam::Vec3;
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;

use crate::camera::Camera;
use crate::error::{Error, Result, Shortfall};
use crate::framebuffer::Framebuffer;
use crate::ray::Ray;

/// Renders with more pixels than this show a progress bar (when stderr is a terminal).
pub const PROGRESS_PIXELS: u64 = 1 << 20;

// ANCHOR: render
/// The image `camera` sees, each pixel coloured by `shade` of its ray through the
/// pixel centre, rows in parallel on the current thread pool (see [`with_threads`]).
pub fn render(
    camera: &Camera,
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
    pixels
        .par_chunks_mut(width as usize)
        .enumerate()
        .for_each(shade_row);
    progress.finish_and_clear();
    Framebuffer::from_pixels(width, height, pixels)
}
// ANCHOR_END: render

// ANCHOR: with_threads
/// Runs `work` on a pool of `threads` worker threads, or, for `None`, on the pool it
/// is called from (rayon's global pool, one thread per core, unless the caller
/// installed another).
///
/// The renderers ([`render`], the rasterizer, the path tracer) take no thread
/// count: they run on the current pool. A program makes its pool once, here,
/// around all its work (a lesson from its `--threads`), instead of every call
/// making one; the images are the same bit for bit whatever the count.
pub fn with_threads<T: Send, E: Send + From<Error>>(
    threads: Option<usize>,
    work: impl FnOnce() -> std::result::Result<T, E> + Send,
) -> std::result::Result<T, E> {
    match threads {
        None => work(),
        Some(n) => thread_pool(n)?.install(work),
    }
}
// ANCHOR_END: with_threads

/// A pool of `threads` worker threads, for a caller that runs many pieces of work
/// on it (`pool.install(...)`, as [`with_threads`] does once); an error
/// ([`crate::error::Shortfall::ThreadPool`]) if the system would not start them.
pub fn thread_pool(threads: usize) -> Result<rayon::ThreadPool> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| Error::Machine {
            param: "threads",
            shortfall: Shortfall::ThreadPool {
                threads,
                message: e.to_string(),
            },
        })
}

/// A bar counting rows, hidden for small work (`work` below [`PROGRESS_PIXELS`]:
/// pixels, or pixels times primitives for a brute-force cast) and when stderr is not
/// a terminal (indicatif hides itself then).
pub(crate) fn progress_bar(work: u64, rows: u32) -> ProgressBar {
    if work <= PROGRESS_PIXELS {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(u64::from(rows));
    if let Ok(style) =
        ProgressStyle::with_template("{bar:40} {pos}/{len} rows, {eta} left")
    {
        bar.set_style(style);
    }
    bar
}
