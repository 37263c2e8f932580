//! What every lesson's example shares: where it writes its pictures, and how it
//! reports bad input (one line on stderr, exit code 2, never a panic).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::course::diagram::Diagram;
use crate::error::Result;
use crate::framebuffer::Framebuffer;

/// The flag every lesson accepts: the folder its images go to.
#[derive(clap::Args, Clone, Debug)]
pub struct Output {
    /// Folder for the lesson's PNG files.
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
}

/// Runs a lesson's body: on error, prints `error: ...` and exits with code 2.
pub fn run(body: impl FnOnce() -> Result<()>) -> ExitCode {
    match body() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
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

/// Parses `x,y,z` (as typed after a flag such as `--direction 0,0,-1`) into a vector.
pub fn parse_vec3(s: &str) -> std::result::Result<glam::Vec3, String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    let [x, y, z] = parts.as_slice() else {
        return Err(format!("expected three numbers x,y,z, got '{s}'"));
    };
    let mut v = [0.0f32; 3];
    for (slot, text) in v.iter_mut().zip([x, y, z]) {
        *slot = text
            .parse::<f32>()
            .map_err(|_| format!("'{text}' is not a number"))?;
        if !slot.is_finite() {
            return Err(format!("'{text}' is not a finite number"));
        }
    }
    Ok(glam::Vec3::from_array(v))
}

/// Parses a finite number (rejects `nan` and `inf`, which Rust's parser accepts).
pub fn parse_finite(s: &str) -> std::result::Result<f32, String> {
    match s.trim().parse::<f32>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(format!("'{s}' is not a finite number")),
        Err(_) => Err(format!("'{s}' is not a number")),
    }
}

/// The signature of coding exercise 3.1, `pixel_to_plane(x, y, width, height, px, py)`.
pub type PixelToPlane = fn((f32, f32), (f32, f32), u32, u32, u32, u32) -> glam::Vec2;

/// The student's `pixel_to_plane` for lesson 03's `--mine`, once it passes its check
/// (coding exercise 3.1); otherwise an error that says what to do: fix the exercise,
/// or turn the `exercises` feature on.
pub fn my_pixel_to_plane() -> Result<PixelToPlane> {
    #[cfg(feature = "exercises")]
    {
        use crate::course::exercises::{ch03, check};
        match check::check_pixel_to_plane(ch03::pixel_to_plane) {
            check::Outcome::Pass => Ok(ch03::pixel_to_plane),
            outcome => Err(crate::Error::Exercise {
                report: check::PIXEL_TO_PLANE.report(&outcome),
            }),
        }
    }
    #[cfg(not(feature = "exercises"))]
    Err(crate::Error::Exercise {
        report: "--mine runs your code for coding exercise 3.1; turn the exercises on: \
                 cargo run --features exercises --example 03_ortho_camera -- --mine"
            .into(),
    })
}
