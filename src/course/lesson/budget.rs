//! The checks a lesson makes on its flags' values before any work: image sizes
//! and threads within the machine's limits, ranges that are not empty; and the
//! runner of a lesson that renders images, which makes them first.

use std::process::ExitCode;

use super::{Output, run};
use crate::course::failure::LessonResult;
use crate::course::mine;
use crate::error::{Problem, Result};
use crate::limits::image_side;
use crate::render::with_threads;

/// The flags of a lesson that renders images of lesson 08's scene (lessons 08 and
/// 09): their size and the worker threads.
#[derive(clap::Args, Clone, Copy, Debug)]
pub struct ImageFlags {
    /// Image width in pixels.
    #[arg(long, default_value_t = 480)]
    pub width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 270)]
    pub height: u32,
    /// Worker threads (default: every core). The images do not depend on it.
    #[arg(long)]
    pub threads: Option<usize>,
}

impl ImageFlags {
    /// The size and thread count, checked ([`budget`]) for a run that holds `images`
    /// images of this size at once.
    pub fn check(&self, images: u64) -> Result<CheckedImage> {
        let threads = budget(self.width, self.height, self.threads, images)?;
        Ok(CheckedImage {
            width: self.width,
            height: self.height,
            threads,
        })
    }

    /// Runs a lesson that renders images, with [`run`]'s one-line errors: the flags
    /// checked first for the `images` images the lesson holds at once, then `lesson`,
    /// given the image size, on a pool of `--threads` workers ([`with_threads`]).
    pub fn run(
        &self,
        images: u64,
        lesson: impl FnOnce((u32, u32)) -> LessonResult<()> + Send,
    ) -> ExitCode {
        run(|| self.within_budget(images, &[], None, lesson))
    }

    /// [`ImageFlags::run`] with `--mine` pictures ([`mine::Picture`]): `mine` gives
    /// them first (the student's functions checked, so that a failing check stops
    /// the lesson before any work), the budget counts them among the images held,
    /// and after `lesson` each is drawn at the same size, saved in `out`, and compared
    /// with the lesson's picture it should equal, in one printed line
    /// ([`mine::compared`]).
    pub fn run_with_mine(
        &self,
        images: u64,
        out: &Output,
        mine: impl FnOnce() -> LessonResult<Vec<mine::Picture>>,
        lesson: impl FnOnce((u32, u32)) -> LessonResult<()> + Send,
    ) -> ExitCode {
        run(|| self.within_budget(images, &mine()?, Some(out), lesson))
    }

    /// The body of [`ImageFlags::run`] and [`ImageFlags::run_with_mine`].
    fn within_budget(
        &self,
        images: u64,
        pictures: &[mine::Picture],
        out: Option<&Output>,
        lesson: impl FnOnce((u32, u32)) -> LessonResult<()> + Send,
    ) -> LessonResult<()> {
        let checked = self.check(images + pictures.len() as u64)?;
        with_threads(checked.threads, || {
            lesson(checked.size())?;
            if let Some(out) = out {
                for picture in pictures {
                    let image = (picture.draw)(checked.size())?;
                    out.image(picture.file, &image)?;
                    if let Some(line) =
                        mine::compared(&image, picture.file, &out.file(picture.like))
                    {
                        super::print(&format!("{line}\n"));
                    }
                }
            }
            Ok(())
        })
    }
}

/// `--width`, `--height` and `--threads` once [`ImageFlags::check`] has passed
/// them: each side within `limits::MAX_RESOLUTION`, the images within the memory
/// limit, the thread count within `limits::MAX_THREADS`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CheckedImage {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Worker threads; `None` for every core.
    pub threads: Option<usize>,
}

impl CheckedImage {
    /// The image size, `(width, height)` in pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }
}

/// Checks `--width`, `--height` and `--threads` before any work: each side within
/// `limits::MAX_RESOLUTION`, the memory of `images` images of that size (16 bytes
/// a pixel: the linear colour and its 8-bit copy) within
/// [`crate::limits::memory_limit`], the thread count within
/// [`crate::limits::MAX_THREADS`]. Returns the thread count.
pub fn budget(
    width: u32,
    height: u32,
    threads: Option<usize>,
    images: u64,
) -> Result<Option<usize>> {
    image_side("--width", width)?;
    image_side("--height", height)?;
    let bytes = crate::limits::images(images, width, height, 16);
    crate::limits::memory("--width x --height", bytes)?;
    crate::limits::threads("--threads", threads)
}

/// `(min, max)` if `min < max` and twice the span between them is a finite number; the
/// error names `flags`, the two flags that set them (`"--x-min/--x-max"`).
pub fn extent(flags: &'static str, min: f32, max: f32) -> Result<(f32, f32)> {
    if min.partial_cmp(&max) != Some(std::cmp::Ordering::Less) {
        return Err(crate::error::Error::Value {
            param: flags,
            problem: Problem::EmptyRange { min, max },
        });
    }
    // Twice the span must be finite too: the figures leave a margin around it.
    if !(2.0 * (max - min)).is_finite() {
        return Err(crate::error::Error::Value {
            param: flags,
            problem: Problem::Invalid {
                reason: "span more than f32 can draw (1.7e38)",
            },
        });
    }
    Ok((min, max))
}
