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
