//! Where a lesson's files go (`--out`), and what it prints.

use std::path::{Path, PathBuf};

use crate::course::diagram::Diagram;
use crate::error::Result;
use crate::framebuffer::Framebuffer;

/// The flag every lesson accepts: the folder its images go to.
#[derive(clap::Args, Clone, Debug)]
pub struct Output {
    /// Folder for the lesson's files (PNG images; lesson 10 adds a PFM, lesson 11
    /// writes its charts as SVG and CSV).
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
}

impl Output {
    /// The path of the file `name` in the output folder.
    pub fn file(&self, name: &str) -> PathBuf {
        self.out.join(name)
    }

    /// Saves a diagram as `name` in the output folder and says so.
    pub fn diagram(&self, name: &str, diagram: &Diagram) -> Result<()> {
        let path = self.file(name);
        diagram.save(&path)?;
        wrote(&path);
        Ok(())
    }

    /// Saves a rendered image as `name` in the output folder and says so.
    pub fn image(&self, name: &str, image: &Framebuffer) -> Result<()> {
        let path = self.file(name);
        image.save_png(&path)?;
        wrote(&path);
        Ok(())
    }

    /// Saves each image under its file name, in the output folder, and says so.
    pub fn images<'a>(
        &self,
        named: impl IntoIterator<Item = (&'a str, &'a Framebuffer)>,
    ) -> Result<()> {
        named
            .into_iter()
            .try_for_each(|(name, image)| self.image(name, image))
    }
}

/// Prints a lesson's text to standard output. A closed pipe (`... | head`) ends the
/// printing quietly instead of panicking as `print!` would.
pub fn print(text: &str) {
    use std::io::Write;
    let _ = std::io::stdout().lock().write_all(text.as_bytes());
}

/// Prints where a file was written.
pub fn wrote(path: &Path) {
    print(&format!("wrote {}\n", path.display()));
}

/// Declares a lesson's images, one field per file, each field beside the name of the
/// file it is saved as:
///
/// ```
/// render_lessons::lesson_images! {
///     /// The lesson's images.
///     Images {
///         ray_cast: "09_ray_cast.png",
///         per_pixel: "09_per_pixel.png",
///     }
/// }
/// assert_eq!(Images::COUNT, 2);
/// ```
///
/// The struct gets `COUNT`, the number of images (for the lesson's memory budget),
/// and `named()`, each image with its file name, for [`Output::images`].
#[macro_export]
macro_rules! lesson_images {
    ($(#[$doc:meta])* $name:ident { $($field:ident: $file:literal),+ $(,)? }) => {
        $(#[$doc])*
        pub struct $name {
            $(#[doc = $file] pub $field: $crate::framebuffer::Framebuffer,)+
        }

        impl $name {
            /// How many images the lesson keeps.
            pub const COUNT: u64 = [$($file),+].len() as u64;

            /// Each image with the name of the file it is saved as.
            pub fn named(
                &self,
            ) -> [(&'static str, &$crate::framebuffer::Framebuffer); Self::COUNT as usize] {
                [$(($file, &self.$field)),+]
            }
        }
    };
}
