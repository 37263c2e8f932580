//! A frame as a renderer that keeps going spends it: the framebuffer and, for more
//! than one thread, the thread pool are made once, before the clock starts; one
//! frame is then only the per-pixel work. `render::render` makes a framebuffer
//! (and a progress bar) on every call, on the pool its caller installed; the
//! ray-casting bench times it as it is too, and the difference is what that
//! set-up costs a frame.

use glam::Vec3;
use rayon::prelude::*;
use render_lessons::camera::Camera;
use render_lessons::ray::Ray;

/// A buffer of `width` x `height` colours and a pool of `threads` threads, reused
/// for every frame.
pub struct FrameLoop {
    width: u32,
    pixels: Vec<Vec3>,
    pool: Option<rayon::ThreadPool>,
}

impl FrameLoop {
    /// The buffer for `camera`'s film, and a pool when `threads` > 1 (one thread
    /// runs on the caller's, with no pool at all).
    pub fn new(camera: &Camera, threads: usize) -> FrameLoop {
        let (width, height) = (camera.film().width(), camera.film().height());
        let pool = (threads > 1).then(|| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a thread pool")
        });
        FrameLoop {
            width,
            pixels: vec![Vec3::ZERO; width as usize * height as usize],
            pool,
        }
    }

    /// One frame: every pixel coloured by `shade` of `camera`'s ray through it, rows
    /// in parallel on the pool (row 0 at the top, as `render::render` does).
    pub fn run(&mut self, camera: &Camera, shade: impl Fn(&Ray) -> Vec3 + Sync) {
        let width = self.width as usize;
        let shade_row = |(y, row): (usize, &mut [Vec3])| {
            let mut rays = camera.row(y as u32);
            for pixel in row.iter_mut() {
                *pixel = shade(&rays.next_ray());
            }
        };
        match &self.pool {
            None => self
                .pixels
                .chunks_mut(width)
                .enumerate()
                .for_each(shade_row),
            Some(pool) => pool.install(|| {
                self.pixels
                    .par_chunks_mut(width)
                    .enumerate()
                    .for_each(shade_row)
            }),
        }
    }

    /// The last frame's pixels.
    pub fn pixels(&self) -> &[Vec3] {
        &self.pixels
    }

    /// The buffer, for a caster that writes it itself (the C anchor).
    pub fn pixels_mut(&mut self) -> &mut [Vec3] {
        &mut self.pixels
    }
}
