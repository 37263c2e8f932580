//! Images: a framebuffer in memory, and the two files it is saved as, PNG and PFM.
//!
//! A framebuffer holds one linear RGB colour per pixel, row 0 at the top. This file
//! saves it as PNG, 8-bit sRGB ([`Framebuffer::save_png`]); [`pfm`] saves and reads
//! it as raw floats.

use std::path::Path;

use glam::Vec3;

use crate::error::{Error, Problem, Result};
use crate::files::write_png_rgba;
use crate::limits::{MAX_RESOLUTION, Resolution};

pub mod pfm;

/// `width` x `height` linear RGB colours, stored row by row from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Framebuffer {
    width: u32,
    height: u32,
    pixels: Vec<Vec3>,
}

impl Framebuffer {
    /// A framebuffer whose pixel (x, y) is `shade(x, y)`.
    pub fn from_fn(
        width: u32,
        height: u32,
        mut shade: impl FnMut(u32, u32) -> Vec3,
    ) -> Result<Self> {
        Resolution::new(width, height)?;
        let pixels = (0..height)
            .flat_map(|y| (0..width).map(move |x| (x, y)))
            .map(|(x, y)| shade(x, y))
            .collect();
        Ok(Framebuffer {
            width,
            height,
            pixels,
        })
    }

    /// A framebuffer from its pixels, row by row from the top.
    pub fn from_pixels(width: u32, height: u32, pixels: Vec<Vec3>) -> Result<Self> {
        Resolution::new(width, height)?;
        if pixels.len() != width as usize * height as usize {
            return Err(Error::Value {
                param: "pixel count",
                problem: Problem::Resolution {
                    value: pixels.len().min(u32::MAX as usize) as u32,
                    max: MAX_RESOLUTION,
                },
            });
        }
        Ok(Framebuffer {
            width,
            height,
            pixels,
        })
    }

    /// `images` in a row, left to right, `gap` white pixels apart, on a white
    /// background where one is shorter than the tallest.
    pub fn beside(images: &[&Framebuffer], gap: u32) -> Result<Self> {
        let height = images.iter().map(|i| i.height).max().unwrap_or(0);
        let width = images
            .iter()
            .map(|i| i.width + gap)
            .sum::<u32>()
            .saturating_sub(gap);
        let mut lefts = Vec::new();
        let mut left = 0;
        for image in images {
            lefts.push(left);
            left += image.width + gap;
        }
        Framebuffer::from_fn(width, height, |x, y| {
            images
                .iter()
                .zip(&lefts)
                .find(|(i, l)| (**l..**l + i.width).contains(&x))
                .and_then(|(i, l)| i.get(x - l, y))
                .unwrap_or(Vec3::ONE)
        })
    }

    /// The mean of all channels of all pixels, summed in f64.
    pub fn mean(&self) -> f64 {
        let sum: f64 = self
            .pixels
            .iter()
            .map(|c| f64::from(c.x) + f64::from(c.y) + f64::from(c.z))
            .sum();
        sum / (3.0 * self.pixels.len() as f64)
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The colour of pixel (x, y), row 0 at the top.
    pub fn get(&self, x: u32, y: u32) -> Option<Vec3> {
        (x < self.width && y < self.height)
            .then(|| self.pixels[(y * self.width + x) as usize])
    }

    /// 8-bit sRGB bytes (RGBA, alpha 255): each linear channel clamped to [0, 1] and
    /// encoded with the sRGB transfer curve. Fails on the first NaN or infinite pixel.
    pub fn to_srgb8(&self) -> Result<Vec<u8>> {
        let mut bytes = Vec::with_capacity(self.pixels.len() * 4);
        for (i, c) in self.pixels.iter().enumerate() {
            if !c.is_finite() {
                let i = i as u32;
                return Err(Error::Value {
                    param: "pixel",
                    problem: Problem::NonFinitePixel {
                        x: i % self.width,
                        y: i / self.width,
                    },
                });
            }
            bytes.extend(c.to_array().map(to_srgb8));
            bytes.push(255);
        }
        Ok(bytes)
    }

    /// Writes the image as an 8-bit sRGB PNG, atomically; refuses NaN pixels.
    pub fn save_png(&self, path: impl AsRef<Path>) -> Result<()> {
        write_png_rgba(path.as_ref(), self.width, self.height, &self.to_srgb8()?)
    }
}

/// A linear value in [0, 1] as an 8-bit sRGB code (IEC 61966-2-1 transfer curve).
pub fn to_srgb8(linear: f32) -> u8 {
    let c = linear.clamp(0.0, 1.0);
    let encoded = if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    (encoded * 255.0 + 0.5) as u8
}
