//! The harness of the coding exercises' checks.
//!
//! Each `check_*` function takes an implementation of one exercise as a function
//! argument, runs it on a few cases, and compares every answer with the crate's own
//! reference code (the code the book includes as the worked solution). It returns
//! [`Outcome::Pass`], [`Outcome::Fail`] with the first wrong case, the expected and
//! the received answer and a hint, or [`Outcome::NotStarted`] while the function is
//! still a `todo!()`.
//!
//! This file is the harness: how an answer is compared and printed, and how a
//! student's function is run: on a thread of its own, each case within
//! [`CASE_TIME_LIMIT`], so that an endless loop fails the check instead of hanging
//! `cargo test`, and with its panics caught (a `todo!()` means "not started").
//! Each chapter's check sits next to the student's file it checks, in
//! `chNN_check.rs` beside `chNN.rs`; `check.rs` lists them all.
//!
//! A `check_*` function takes the answer as `impl Fn`, so that a function or a
//! closure both do, and hands it on boxed, as a trait object, to a private
//! `*_checked` function that holds the cases. A generic function is compiled again
//! for every closure passed to it, and the course's own tests pass over two hundred
//! (the mistakes each check must catch); boxed, the cases and the harness are
//! compiled once, in the library.
//!
//! The default test suite runs every check against the reference implementation
//! (it must pass) and against deliberately wrong ones (they must fail with a hint),
//! so a wrong check fails CI; the student's own tests (`tests/exercises.rs`) run
//! only when asked for, `cargo test --test exercises`.

use std::any::Any;
use std::cell::{Cell, RefCell};
use std::fmt;
use std::panic::{self, AssertUnwindSafe};
use std::sync::{Arc, Once, mpsc};
use std::time::Duration;

use glam::Vec3;

/// The result of checking one exercise.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// Every case gave the expected answer.
    Pass,
    /// The first case that did not.
    Fail {
        /// The case, in words.
        case: String,
        /// What the reference code answers.
        expected: String,
        /// What the implementation answered (or how it panicked, or that it did not
        /// answer in time).
        got: String,
        /// What is probably wrong.
        hint: String,
        /// A wrong answer, a panic or no answer in time.
        reason: Reason,
    },
    /// The function still panics with `todo!()`.
    NotStarted,
}

/// Why a case failed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Reason {
    /// The function answered, wrongly.
    Wrong,
    /// The function panicked with `message`, at `at` (`file:line`) when the panic
    /// happened on the thread that runs it (a panic on a thread the function started,
    /// such as a rayon worker's, reaches the check without its place).
    Panicked {
        /// Where: the file and line of the panic.
        at: Option<String>,
        /// The panic's message.
        message: String,
    },
    /// No answer within the time limit, `seconds`.
    TimedOut {
        /// The time limit in whole seconds.
        seconds: u64,
    },
}

impl Reason {
    /// What the function did instead of answering, in a few words: "panicked at
    /// src/course/exercises/ch02.rs:17: oops" (the message's first line), "no answer
    /// within 5 s"; `None` for a wrong answer.
    pub fn summary(&self) -> Option<String> {
        match self {
            Reason::Wrong => None,
            Reason::Panicked { at, message } => {
                let first = message.lines().next().unwrap_or_default();
                Some(match at {
                    Some(at) => format!("panicked at {at}: {first}"),
                    None => format!("panicked: {first}"),
                })
            }
            Reason::TimedOut { seconds } => {
                Some(format!("no answer within {seconds} s"))
            }
        }
    }
}

impl Outcome {
    /// `PASS`, `FAIL` or `NOT STARTED`.
    pub fn status(&self) -> &'static str {
        match self {
            Outcome::Pass => "PASS",
            Outcome::Fail { .. } => "FAIL",
            Outcome::NotStarted => "NOT STARTED",
        }
    }

    /// The hint of a failure; `None` for a pass or an exercise not started.
    pub fn hint(&self) -> Option<&str> {
        match self {
            Outcome::Fail { hint, .. } => Some(hint),
            _ => None,
        }
    }
}

impl fmt::Display for Outcome {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Outcome::Pass => write!(f, "PASS: every case gives the expected answer"),
            Outcome::NotStarted => {
                write!(f, "NOT STARTED: the function is still todo!()")
            }
            Outcome::Fail {
                case,
                expected,
                got,
                hint,
                ..
            } => write!(
                f,
                "FAIL\n  case:     {case}\n  expected: {expected}\n  got:      {got}\n  hint:     {hint}"
            ),
        }
    }
}

/// One coding exercise: where the student writes it and what it is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Exercise {
    /// "3.5": lesson 03's fifth exercise. Every exercise of a lesson, written or
    /// coding, is numbered N.k in book order across the lesson's pages, and the check's
    /// number is the book's (`tests/exercise_checks/harness.rs` holds them to it).
    pub number: &'static str,
    /// The chapter's number, "03".
    pub chapter: &'static str,
    /// The chapter's title.
    pub chapter_title: &'static str,
    /// The function the student writes.
    pub function: &'static str,
    /// The file it is in.
    pub file: &'static str,
}

impl Exercise {
    /// A full report of `outcome` for this exercise, several lines.
    pub fn report(&self, outcome: &Outcome) -> String {
        let head = format!(
            "Coding exercise {} `{}` (chapter {}, {}; in {})",
            self.number, self.function, self.chapter, self.chapter_title, self.file
        );
        match outcome {
            Outcome::NotStarted => format!(
                "{head}\nNOT STARTED: replace the todo!() in `{}` in {} with your code,\n  \
                 then run `cargo test --test exercises ch{}`.",
                self.function, self.file, self.chapter
            ),
            other => format!("{head}\n{other}"),
        }
    }

    /// One line of a summary table: number, chapter, function, status, and for a
    /// panic or a time-out what happened ("FAIL: panicked at src/...:17: oops").
    pub fn row(&self, outcome: &Outcome) -> String {
        let status = match outcome {
            Outcome::Fail { reason, .. } => match reason.summary() {
                Some(what) => format!("FAIL: {what}"),
                None => "FAIL".to_string(),
            },
            other => other.status().to_string(),
        };
        format!(
            "{:<5} ch{}  {:<20} {status}",
            self.number, self.chapter, self.function
        )
    }

    /// `Ok` for a pass; otherwise the full report, as the error a student's test
    /// returns. A test that returns an error prints it as it is, without the
    /// backtrace a failed assertion would print with `RUST_BACKTRACE=1` (a backtrace
    /// of the harness, not of the student's code, whose panics the report places).
    pub fn expect_pass(&self, outcome: &Outcome) -> Result<(), Report> {
        match outcome {
            Outcome::Pass => Ok(()),
            other => Err(Report(self.report(other))),
        }
    }
}

/// A check's report, as the error of a student's test: its `Debug` form, which the
/// test prints, is the report itself.
pub struct Report(pub String);

impl fmt::Debug for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "\n{}\n", self.0)
    }
}

pub use super::answer::{Answer, TOLERANCE};

// ---------------------------------------------------------------------------
// Running an implementation.

/// How long one case may run before the check gives up on it: an answer that takes
/// longer is almost certainly stuck in a loop that never ends. Every case of every
/// check takes well under a second with a right answer, even in a debug build.
pub const CASE_TIME_LIMIT: Duration = Duration::from_secs(5);

/// The environment variable that sets the time limit of every case in whole
/// seconds, instead of [`CASE_TIME_LIMIT`]: more for a machine much slower than
/// usual, or while stepping through an answer in a debugger
/// (`EXERCISE_SECONDS=600 cargo test --test exercises ch03`).
pub const TIME_LIMIT_VARIABLE: &str = "EXERCISE_SECONDS";

thread_local! {
    /// The time limit [`with_case_time_limit`] set for the checks this thread runs
    /// now, if any.
    static LIMIT_HERE: Cell<Option<Duration>> = const { Cell::new(None) };
}

/// How long one case may run: what [`with_case_time_limit`] set around the check
/// this thread runs, else `EXERCISE_SECONDS` ([`TIME_LIMIT_VARIABLE`]) if it holds a
/// whole number of seconds from 1, else [`CASE_TIME_LIMIT`].
pub fn case_time_limit() -> Duration {
    LIMIT_HERE.with(Cell::get).unwrap_or_else(|| {
        std::env::var(TIME_LIMIT_VARIABLE)
            .ok()
            .and_then(|s| s.trim().parse::<u64>().ok())
            .filter(|&seconds| seconds >= 1)
            .map_or(CASE_TIME_LIMIT, Duration::from_secs)
    })
}

/// Runs `f` (which runs checks) with each case's time limit set to `limit`, in whole
/// seconds from 1 (a shorter `limit` gives 1 s), and restores the limit afterwards,
/// even if `f` panics. The limit holds only for checks run on this thread, so that a
/// test that shortens it (the course's own test of the time-out message uses 1 s)
/// changes nothing for the tests running beside it or after it.
pub fn with_case_time_limit<T>(limit: Duration, f: impl FnOnce() -> T) -> T {
    /// Puts the limit that held before back when dropped.
    struct Restore(Option<Duration>);
    impl Drop for Restore {
        fn drop(&mut self) {
            LIMIT_HERE.with(|here| here.set(self.0));
        }
    }
    let whole = Duration::from_secs(limit.as_secs().max(1));
    let _restore = Restore(LIMIT_HERE.with(|here| here.replace(Some(whole))));
    f()
}

thread_local! {
    /// True on a thread that runs a student's function: its panics are reported in
    /// the outcome, not printed.
    static QUIET: Cell<bool> = const { Cell::new(false) };
    /// Where the last panic on this quiet thread happened (`file:line`), as the panic
    /// hook saw it: the payload that reaches `catch_unwind` carries no place.
    static PANICKED_AT: RefCell<Option<String>> = const { RefCell::new(None) };
}

static INSTALL_HOOK: Once = Once::new();

/// A panic of a student's function: its message, and its place when known.
struct Panic {
    message: String,
    at: Option<String>,
}

/// Runs `f`, catching a panic and returning its message and place.
///
/// The panic hook is replaced once by one that, on a thread that runs a student's
/// function, prints nothing but notes the place of the panic (the file and line the
/// hook receives, which the caught payload does not carry), and otherwise calls the
/// previous hook. (Swapping the hook in and out around every call would race between
/// tests running in parallel.) A panic on another thread the function started (a
/// rayon closure, say) still reaches the function, and so the outcome, but its
/// message and place are printed there, and the outcome has no place.
fn quietly(f: Job) -> Result<Box<dyn Any + Send>, Panic> {
    INSTALL_HOOK.call_once(|| {
        let previous = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            if QUIET.with(Cell::get) {
                let at = info
                    .location()
                    .map(|place| format!("{}:{}", place.file(), place.line()));
                PANICKED_AT.with(|here| *here.borrow_mut() = at);
            } else {
                previous(info);
            }
        }));
    });
    QUIET.with(|q| q.set(true));
    PANICKED_AT.with(|here| here.borrow_mut().take());
    let result = panic::catch_unwind(AssertUnwindSafe(f));
    QUIET.with(|q| q.set(false));
    result.map_err(|payload| {
        let message = if let Some(s) = payload.downcast_ref::<&str>() {
            (*s).to_string()
        } else if let Some(s) = payload.downcast_ref::<String>() {
            s.clone()
        } else {
            "a panic without a message".to_string()
        };
        let at = PANICKED_AT.with(|here| here.borrow_mut().take());
        Panic { message, at }
    })
}

/// A student's function on a thread of its own, answering one case at a time, so
/// that the check can stop waiting for an answer that never comes.
///
/// A function stuck in an endless loop cannot be stopped from outside: its thread
/// is left behind, still running, and ends with the test program. (Endless
/// recursion is another matter: it overflows the stack, which aborts the whole
/// program; no thread can catch that.)
///
/// The thread runs jobs, each one case already bound to its arguments, and sends
/// back what it made as `Box<dyn Any>`: so the worker is one piece of code for every
/// check, whatever its argument and answer types.
struct Worker {
    jobs: mpsc::Sender<Job>,
    answers: mpsc::Receiver<Result<Box<dyn Any + Send>, Panic>>,
}

/// One case of a student's function, ready to run.
type Job = Box<dyn FnOnce() -> Box<dyn Any + Send> + Send>;

impl Worker {
    fn start() -> Worker {
        let (jobs, inbox) = mpsc::channel::<Job>();
        let (outbox, answers) = mpsc::channel();
        let worker = move || {
            // Ends when the check drops its sender, or stops listening.
            for job in inbox {
                if outbox.send(quietly(job)).is_err() {
                    break;
                }
            }
        };
        // If no thread can be started, the receiver reports the closed channel.
        let _ = std::thread::Builder::new()
            .name("exercise".into())
            .spawn(worker);
        Worker { jobs, answers }
    }

    /// The answer of `job`: `Ok` with what it returned or `Err` with its panic;
    /// `None` if none came within [`case_time_limit`].
    fn answer(&self, job: Job) -> Option<Result<Box<dyn Any + Send>, Panic>> {
        let broken = |message: &str| {
            Some(Err(Panic {
                message: message.to_string(),
                at: None,
            }))
        };
        if self.jobs.send(job).is_err() {
            return broken("the check could not start a thread to run it");
        }
        match self.answers.recv_timeout(case_time_limit()) {
            Ok(answer) => Some(answer),
            Err(mpsc::RecvTimeoutError::Timeout) => None,
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                broken("the thread running it ended without an answer")
            }
        }
    }
}

/// A typical mistake: does the answer `got` for these arguments look like it?
pub(crate) struct Mistake<'a, A, R> {
    pub(crate) looks_like: &'a dyn Fn(&A, &R) -> bool,
    pub(crate) hint: &'static str,
}

/// A mistake recognised by the wrong answer it gives.
pub(crate) fn gives<'a, A, R: Answer>(
    wrong: &'a dyn Fn(&A) -> Option<R>,
) -> impl Fn(&A, &R) -> bool + 'a {
    move |a, got| wrong(a).is_some_and(|w| got.close(&w))
}

/// One case: its description and its arguments.
pub(crate) type Case<A> = (String, A);

/// Runs `student` on every case, each within [`case_time_limit`], and compares with
/// `reference`. A panic, or a case that does not finish in time, fails the check and
/// names the case; a `todo!()` means the exercise is not started.
pub(crate) fn run<A, R>(
    cases: &[Case<A>],
    reference: impl Fn(&A) -> R,
    student: impl Fn(A) -> R + Send + Sync + 'static,
    mistakes: &[Mistake<'_, A, R>],
    hint: &str,
) -> Outcome
where
    A: Clone + Send + 'static,
    R: Answer + Send + 'static,
{
    run_compared(
        cases,
        reference,
        student,
        |_, expected: &R, got: &R| got.close(expected),
        mistakes,
        hint,
    )
}

/// [`run`], with `right(args, expected, got)` deciding whether the answer `got` is
/// right where [`Answer::close`] is not the whole story (a camera basis whose roll
/// rounding leaves uncertain, but which must be orthonormal).
pub(crate) fn run_compared<A, R>(
    cases: &[Case<A>],
    reference: impl Fn(&A) -> R,
    student: impl Fn(A) -> R + Send + Sync + 'static,
    right: impl Fn(&A, &R, &R) -> bool,
    mistakes: &[Mistake<'_, A, R>],
    hint: &str,
) -> Outcome
where
    A: Clone + Send + 'static,
    R: Answer + Send + 'static,
{
    let worker = Worker::start();
    let student = Arc::new(student);
    for (n, (case, args)) in cases.iter().enumerate() {
        let expected = reference(args);
        let (student, args_moved) = (Arc::clone(&student), args.clone());
        let job: Job = Box::new(move || Box::new(student(args_moved)));
        let answer = worker.answer(job).map(|a| a.map(|got| got.downcast::<R>()));
        let got = match answer {
            Some(Ok(Ok(got))) => *got,
            Some(Ok(Err(_))) => unreachable!("a job answers with its function's type"),
            Some(Err(panic)) if panic.message.contains("not yet implemented") => {
                return Outcome::NotStarted;
            }
            Some(Err(Panic { message, at })) => {
                let reason = Reason::Panicked { at, message };
                return Outcome::Fail {
                    case: case.clone(),
                    expected: expected.show(),
                    got: reason.summary().unwrap_or_default(),
                    hint: format!("the function must not panic on this input. {hint}"),
                    reason,
                };
            }
            None => {
                let seconds = case_time_limit().as_secs();
                let reason = Reason::TimedOut { seconds };
                return Outcome::Fail {
                    case: case.clone(),
                    expected: expected.show(),
                    got: reason.summary().unwrap_or_default(),
                    hint: format!(
                        "case {} ({case}) did not finish within {seconds} s: an infinite loop? \
                         Look for a loop whose condition never changes. {hint}",
                        n + 1
                    ),
                    reason,
                };
            }
        };
        if !right(args, &expected, &got) {
            let hint = mistakes
                .iter()
                .find(|m| (m.looks_like)(args, &got))
                .map_or(hint, |m| m.hint);
            return Outcome::Fail {
                case: case.clone(),
                expected: expected.show(),
                got: got.show(),
                hint: hint.to_string(),
                reason: Reason::Wrong,
            };
        }
    }
    Outcome::Pass
}

pub(crate) fn v(x: f32, y: f32, z: f32) -> Vec3 {
    Vec3::new(x, y, z)
}
