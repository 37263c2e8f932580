//! What the machine can give a run, checked before any work starts: the memory a
//! set of images or a mesh will need, and the number of worker threads. A flag
//! that asks for more is refused with the estimate and the limit, instead of an
//! abort (allocation failure) half way through or a run that never ends.

use crate::error::{Error, Problem, Result, Shortfall};

/// The largest width or height of an image, in pixels.
pub const MAX_RESOLUTION: u32 = 16_384;

/// An image's size in pixels, both sides checked once to lie between 1 and
/// [`MAX_RESOLUTION`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Resolution {
    width: u32,
    height: u32,
}

impl Resolution {
    /// `width` x `height` pixels; an error naming `width` or `height` if a side is 0
    /// or above [`MAX_RESOLUTION`].
    pub fn new(width: u32, height: u32) -> Result<Resolution> {
        Ok(Resolution {
            width: image_side("width", width)?,
            height: image_side("height", height)?,
        })
    }

    /// The width in pixels.
    pub fn width(self) -> u32 {
        self.width
    }

    /// The height in pixels.
    pub fn height(self) -> u32 {
        self.height
    }
}

/// `value` pixels if that is a side an image may have, 1 to [`MAX_RESOLUTION`];
/// otherwise an error naming `param` (e.g. `shadow map size`, or a flag).
pub fn image_side(param: &'static str, value: u32) -> Result<u32> {
    if (1..=MAX_RESOLUTION).contains(&value) {
        Ok(value)
    } else {
        Err(Error::Value {
            param,
            problem: Problem::Resolution {
                value,
                max: MAX_RESOLUTION,
            },
        })
    }
}

/// The most worker threads a render may ask for: more than enough for any machine
/// a student has, far below what makes a thread pool fail.
pub const MAX_THREADS: usize = 256;

/// The memory a run may use: half of what the machine has (`MemTotal` in
/// /proc/meminfo), or 4 GiB where that cannot be read. The machine's memory, not
/// what is free at the moment: a run refused is one that could not work even on
/// an idle machine, and the same run is refused or not from one minute to the next.
pub fn memory_limit() -> u64 {
    let available = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|text| {
            text.lines()
                .find(|l| l.starts_with("MemTotal:"))
                .and_then(|l| l.split_whitespace().nth(1))
                .and_then(|kib| kib.parse::<u64>().ok())
        })
        .map(|kib| kib.saturating_mul(1024));
    available.map_or(4 << 30, |bytes| bytes / 2)
}

/// `Ok` if `bytes` (the run's estimate, for the flag `param`) fits in
/// [`memory_limit`].
pub fn memory(param: &'static str, bytes: u64) -> Result<()> {
    let limit = memory_limit();
    if bytes <= limit {
        Ok(())
    } else {
        Err(Error::Machine {
            param,
            shortfall: Shortfall::TooMuch {
                needed: bytes,
                limit,
                unit: "bytes",
            },
        })
    }
}

/// The bytes of `count` images of `width` x `height` pixels at `per_pixel` bytes
/// each, saturating instead of overflowing.
pub fn images(count: u64, width: u32, height: u32, per_pixel: u64) -> u64 {
    count
        .saturating_mul(u64::from(width))
        .saturating_mul(u64::from(height))
        .saturating_mul(per_pixel)
}

/// A thread count for `param`: `None` (every core) stays `None`; 0 and more than
/// [`MAX_THREADS`] are refused.
pub fn threads(param: &'static str, threads: Option<usize>) -> Result<Option<usize>> {
    match threads {
        Some(0) => Err(Error::Value {
            param,
            problem: Problem::TooFew { value: 0, min: 1 },
        }),
        Some(n) if n > MAX_THREADS => Err(Error::Machine {
            param,
            shortfall: Shortfall::TooMuch {
                needed: n as u64,
                limit: MAX_THREADS as u64,
                unit: "threads",
            },
        }),
        other => Ok(other),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_small_image_fits_and_an_absurd_one_does_not() {
        assert!(memory("width", images(1, 640, 480, 16)).is_ok());
        let err = memory("width", images(4, u32::MAX, u32::MAX, 16)).unwrap_err();
        assert_eq!(err.param(), "width");
        assert!(err.to_string().contains("GiB"), "{err}");
    }

    #[test]
    fn thread_counts_are_capped() {
        assert_eq!(threads("threads", None), Ok(None));
        assert_eq!(threads("threads", Some(2)), Ok(Some(2)));
        assert_eq!(threads("threads", Some(0)).unwrap_err().param(), "threads");
        let err = threads("threads", Some(100_000)).unwrap_err();
        assert!(err.to_string().contains("256"), "{err}");
    }
}
