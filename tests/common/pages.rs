//! The book's pages and the tests' insta snapshots, read as text from the root of
//! the crate.

use std::fs;
use std::path::PathBuf;

/// The root of the crate (where `Cargo.toml` is).
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The file at `relative` to the root; panics naming it if it cannot be read.
pub fn read(relative: &str) -> String {
    fs::read_to_string(root().join(relative)).unwrap_or_else(|e| panic!("{relative}: {e}"))
}

/// A page of the book (`chapters/NAME`), as written.
pub fn page(name: &str) -> String {
    read(&format!("chapters/{name}"))
}

/// Where insta keeps the snapshot `name` of a test in the module `module` (as
/// `module_path!()` gives it, e.g. `lessons::lesson_10_path_tracing`) of a test
/// crate in `tests/CRATE/`: `tests/CRATE/snapshots/CRATE__MODULE__NAME.snap`.
pub fn snapshot_path(module: &str, name: &str) -> String {
    let krate = module.split("::").next().unwrap_or(module);
    format!(
        "tests/{krate}/snapshots/{}__{name}.snap",
        module.replace("::", "__")
    )
}

/// The snapshot `name` of the module `module` (see [`snapshot_path`]), header
/// included.
pub fn snapshot(module: &str, name: &str) -> String {
    read(&snapshot_path(module, name))
}

/// A snapshot's text after its insta header (the second `---` line).
pub fn after_header(snapshot: &str) -> &str {
    let mut parts = snapshot.splitn(3, "---\n");
    parts.next();
    parts.next();
    parts.next().expect("an insta snapshot has a header")
}
