//! What every lesson's example shares: where it writes its pictures, and how it
//! reports bad input (one line on stderr, exit code 2, never a panic).

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::course::diagram::Diagram;
use crate::course::failure::{Failure, LessonResult};
use crate::course::mine;
use crate::error::Result;
use crate::framebuffer::Framebuffer;
use crate::render::with_threads;

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
    /// and after `lesson` each is drawn at the same size and saved in `out`.
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
                    out.image(picture.file, &(picture.draw)(checked.size())?)?;
                }
            }
            Ok(())
        })
    }
}

/// `--width`, `--height` and `--threads` once [`ImageFlags::check`] has passed
/// them: each side within `camera::MAX_RESOLUTION`, the images within the memory
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
    pixels("--width", width, crate::limits::MAX_RESOLUTION)?;
    pixels("--height", height, crate::limits::MAX_RESOLUTION)?;
    let bytes = crate::limits::images(images, width, height, 16);
    crate::limits::memory("--width x --height", bytes)?;
    crate::limits::threads("--threads", threads)
}

/// Runs a lesson's body: on error, prints `error: ...` and exits with code 2; on
/// Ctrl-C ([`check_interrupt`]) with code 130. In the body, `?` turns the
/// renderer's errors into a [`Failure`].
pub fn run(body: impl FnOnce() -> LessonResult<()>) -> ExitCode {
    match body() {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Interrupted) => {
            eprintln!("interrupted (Ctrl-C): every file written so far is whole");
            ExitCode::from(130)
        }
        Err(Failure::Render(e)) => {
            eprintln!("error: {}", as_typed(&e));
            ExitCode::from(2)
        }
        Err(other) => {
            eprintln!("error: {other}");
            ExitCode::from(2)
        }
    }
}

/// Set by Ctrl-C once [`stop_on_ctrl_c`] has been called.
static INTERRUPTED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// From now on Ctrl-C does not kill the lesson: it asks it to stop at the next
/// [`check_interrupt`], so that a long render ends with every finished image saved
/// (each written whole, never half) and says which are complete. For lessons whose
/// work comes in steps (lesson 10's passes, lesson 11's charts).
pub fn stop_on_ctrl_c() {
    let _ = ctrlc::set_handler(|| {
        INTERRUPTED.store(true, std::sync::atomic::Ordering::SeqCst);
        eprintln!("\nCtrl-C: stopping after the current step, keeping what is done");
    });
}

/// `Err(Failure::Interrupted)` once Ctrl-C was pressed (see [`stop_on_ctrl_c`]);
/// [`run`] then exits with code 130, the shell's code for an interrupt.
pub fn check_interrupt() -> LessonResult<()> {
    if INTERRUPTED.load(std::sync::atomic::Ordering::SeqCst) {
        Err(Failure::Interrupted)
    } else {
        Ok(())
    }
}

/// The long flags of the command [`parse`] read, to name them in errors.
static FLAGS: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();

/// The error's message, its parameter written as the flag the user typed when the
/// lesson has one of that name: "screen distance must ..." becomes
/// "--screen-distance must ...".
fn as_typed(e: &crate::error::Error) -> String {
    let message = e.to_string();
    let param = e.param();
    let flag = param.replace(' ', "-");
    let known = FLAGS.get().is_some_and(|flags| flags.contains(&flag));
    match message.strip_prefix(param) {
        Some(rest) if known => format!("--{flag}{rest}"),
        _ => message,
    }
}

/// Prints a lesson's text to standard output. A closed pipe (`... | head`) ends the
/// printing quietly instead of panicking as `print!` would.
pub fn print(text: &str) {
    use std::io::Write;
    let _ = std::io::stdout().lock().write_all(text.as_bytes());
}

/// The lesson's flags from the command line, checked before any work:
///
/// - a flag's value may start with a minus sign (`--point -1,-2,-3`,
///   `--angle -inf`): it is the value, never taken for another flag;
/// - `--out` must be a folder this program can write to (it is created if missing),
///   so that a bad folder is reported before minutes of rendering, not after.
///
/// On bad input it prints a one-line error naming the flag and exits with code 2,
/// as clap does.
pub fn parse<A: clap::Parser>() -> A {
    let command = A::command();
    let flags = command.get_arguments().filter_map(|a| a.get_long());
    let _ = FLAGS.set(flags.map(str::to_string).collect());
    let args = negative_values(&command, std::env::args_os().collect());
    let matches = command.get_matches_from(args);
    if let Some(out) = matches.try_get_one::<PathBuf>("out").ok().flatten()
        && let Err(message) = writable(out)
    {
        eprintln!("error: --out {}: {message}", out.display());
        std::process::exit(2);
    }
    A::from_arg_matches(&matches).unwrap_or_else(|e| e.exit())
}

/// The command line with `--flag -value` written `--flag=-value` wherever `--flag`
/// takes a value and the next word starts with one minus sign (`-1,-2,-3`, `-inf`),
/// so that clap reads it as the value and not as an unknown short flag.
fn negative_values(command: &clap::Command, args: Vec<OsString>) -> Vec<OsString> {
    let takes_value = |word: &str| {
        word.strip_prefix("--").is_some_and(|name| {
            command
                .get_arguments()
                .any(|a| a.get_long() == Some(name) && a.get_action().takes_values())
        })
    };
    let mut out: Vec<OsString> = Vec::with_capacity(args.len());
    let mut words = args.into_iter().peekable();
    while let Some(word) = words.next() {
        let next_is_negative = words
            .peek()
            .and_then(|n| n.to_str())
            .is_some_and(|n| n.starts_with('-') && !n.starts_with("--") && n.len() > 1);
        match word.to_str() {
            Some(flag) if takes_value(flag) && next_is_negative => {
                let mut joined = OsString::from(flag);
                joined.push("=");
                joined.push(words.next().unwrap_or_default());
                out.push(joined);
            }
            _ => out.push(word),
        }
    }
    out
}

/// `Ok` if `dir` is (or can be made) a folder in which a file can be written.
fn writable(dir: &Path) -> std::result::Result<(), String> {
    if dir.as_os_str().is_empty() {
        return Err("must name a folder".to_string());
    }
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create the folder ({e})"))?;
    if !dir.is_dir() {
        return Err("is not a folder".to_string());
    }
    tempfile::Builder::new()
        .prefix(".write-test")
        .tempfile_in(dir)
        .map(drop)
        .map_err(|e| format!("cannot write in it ({e})"))
}

/// For `map_err`: an error reading the file given after `flag` (`--mesh`) names the
/// flag too: "--mesh torus.obj, line 3: ...".
pub fn flag(flag: &'static str) -> impl Fn(crate::error::Error) -> crate::error::Error {
    use crate::error::Error;
    move |e| match e {
        Error::Obj {
            path,
            line,
            message,
        } => Error::Obj {
            path: format!("{flag} {path}"),
            line,
            message,
        },
        Error::Io { path, message } => Error::Io {
            path: format!("{flag} {path}"),
            message,
        },
        Error::Invalid { reason, .. } => Error::Invalid {
            param: flag,
            reason,
        },
        other => other,
    }
}

/// `value` if it lies in 1..=`max` pixels; otherwise an error naming the flag
/// (e.g. `--view-width`) that asked for it.
pub fn pixels(flag: &'static str, value: u32, max: u32) -> Result<u32> {
    if (1..=max).contains(&value) {
        Ok(value)
    } else {
        Err(crate::error::Error::Resolution {
            param: flag,
            value,
            max,
        })
    }
}

/// `(min, max)` if `min < max` and twice the span between them is a finite number; the
/// error names `flags`, the two flags that set them (`"--x-min/--x-max"`).
pub fn extent(flags: &'static str, min: f32, max: f32) -> Result<(f32, f32)> {
    if min.partial_cmp(&max) != Some(std::cmp::Ordering::Less) {
        return Err(crate::error::Error::EmptyRange {
            param: flags,
            min,
            max,
        });
    }
    // Twice the span must be finite too: the figures leave a margin around it.
    if !(2.0 * (max - min)).is_finite() {
        return Err(crate::error::Error::Invalid {
            param: flags,
            reason: "span more than f32 can draw (1.7e38)",
        });
    }
    Ok((min, max))
}

/// Prints where a file was written.
pub fn wrote(path: &Path) {
    print(&format!("wrote {}\n", path.display()));
}
