//! Compiles the plain C anchor (`anchors/plain_caster.c`) with the system's C
//! compiler, at -O2 without -march=native, and sets `cfg(c_anchor)` when it could.
//! Without a C compiler the benches build all the same and skip the anchor (but
//! criterion itself needs one: its dependency alloca compiles C, and rustc links
//! through `cc` on Linux; `RENDER_BENCHES_NO_C_ANCHOR=1` shows the skipped path).
//!
//! Then the Embree anchor (`anchors/embree_caster.c`, a shim over Embree 3 for the
//! BVH bench), when Embree 3 is installed: found by pkg-config (`embree3`) or by its
//! header `/usr/include/embree3/rtcore.h` (Debian's `libembree-dev`, which ships no
//! pkg-config file), and linked with `-lembree3`; it sets `cfg(embree_anchor)`.
//! Without it the BVH bench skips Embree and says how to install it
//! (`RENDER_BENCHES_NO_EMBREE=1` shows that path).

/// The flags the anchor is compiled with (besides cc's own, e.g. -fPIC), printed by
/// the bench next to its figures.
const FLAGS: &str = "-O2 -ffp-contract=off";

/// Set (to anything) to build without the anchor, as a machine without a C compiler
/// does: the benches then print a note in its place.
const OPT_OUT: &str = "RENDER_BENCHES_NO_C_ANCHOR";

/// Set (to anything) to build without the Embree anchor, as a machine without
/// Embree does.
const NO_EMBREE: &str = "RENDER_BENCHES_NO_EMBREE";

/// Where Debian's `libembree-dev` puts Embree 3's header.
const EMBREE_HEADER: &str = "/usr/include/embree3/rtcore.h";

fn main() {
    c_anchor();
    embree_anchor();
}

fn c_anchor() {
    println!("cargo::rustc-check-cfg=cfg(c_anchor)");
    println!("cargo::rerun-if-changed=anchors/plain_caster.c");
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-env-changed={OPT_OUT}");
    if std::env::var_os(OPT_OUT).is_some() {
        println!(
            "cargo::warning={OPT_OUT} is set: the benches will skip the plain C anchor"
        );
        return;
    }
    let mut build = cc::Build::new();
    build
        .file("anchors/plain_caster.c")
        .opt_level(2)
        .debug(false)
        .warnings(true)
        .flag_if_supported("-ffp-contract=off");
    match build.try_compile("plain_caster") {
        Ok(()) => {
            println!("cargo::rustc-cfg=c_anchor");
            println!(
                "cargo::rustc-env=C_ANCHOR_COMPILER={} {FLAGS}",
                version(&build)
            );
        }
        Err(e) => {
            println!(
                "cargo::warning=no C compiler ({e}): the benches will skip the plain C anchor"
            )
        }
    }
}

/// The Embree shim, compiled and linked when Embree 3 is there.
fn embree_anchor() {
    println!("cargo::rustc-check-cfg=cfg(embree_anchor)");
    println!("cargo::rerun-if-changed=anchors/embree_caster.c");
    println!("cargo::rerun-if-changed={EMBREE_HEADER}");
    println!("cargo::rerun-if-env-changed={NO_EMBREE}");
    if std::env::var_os(NO_EMBREE).is_some() {
        println!("cargo::warning={NO_EMBREE} is set: the BVH bench will skip Embree");
        return;
    }
    let mut build = cc::Build::new();
    build
        .file("anchors/embree_caster.c")
        .opt_level(2)
        .debug(false)
        .warnings(true);
    // No Embree: the bench says so and how to install it; no warning here, as a
    // machine without Embree is an ordinary one.
    let Some(EmbreeFlags {
        include,
        search,
        libs,
    }) = embree_flags()
    else {
        return;
    };
    build.includes(include);
    if let Err(e) = build.try_compile("embree_caster") {
        println!(
            "cargo::warning=the Embree shim did not compile ({e}): the BVH bench will skip Embree"
        );
        return;
    }
    for dir in search {
        println!("cargo::rustc-link-search=native={dir}");
    }
    for lib in libs {
        println!("cargo::rustc-link-lib={lib}");
    }
    println!("cargo::rustc-cfg=embree_anchor");
}

/// Where Embree 3's header and library are: include directories, library
/// directories, libraries.
struct EmbreeFlags {
    include: Vec<String>,
    search: Vec<String>,
    libs: Vec<String>,
}

/// Embree 3 by pkg-config (`embree3`), else by its header in /usr/include (the
/// library then in the linker's default path), else `None`.
fn embree_flags() -> Option<EmbreeFlags> {
    let pkg_config = |flag: &str| {
        let out = std::process::Command::new("pkg-config")
            .args([flag, "embree3"])
            .output()
            .ok()
            .filter(|o| o.status.success())?;
        let text = String::from_utf8(out.stdout).ok()?;
        Some(
            text.split_whitespace()
                .map(str::to_string)
                .collect::<Vec<_>>(),
        )
    };
    if let (Some(cflags), Some(libs)) = (pkg_config("--cflags"), pkg_config("--libs")) {
        let strip = |words: &[String], prefix: &str| -> Vec<String> {
            words
                .iter()
                .filter_map(|w| w.strip_prefix(prefix).map(str::to_string))
                .collect()
        };
        return Some(EmbreeFlags {
            include: strip(&cflags, "-I"),
            search: strip(&libs, "-L"),
            libs: strip(&libs, "-l"),
        });
    }
    std::path::Path::new(EMBREE_HEADER)
        .exists()
        .then(|| EmbreeFlags {
            include: Vec::new(),
            search: Vec::new(),
            libs: vec!["embree3".to_string()],
        })
}

/// The compiler's first line of `--version`, e.g. "cc (Debian 14.2.0-19) 14.2.0",
/// or its path.
fn version(build: &cc::Build) -> String {
    let compiler = build.get_compiler();
    let path = compiler.path().display().to_string();
    compiler
        .to_command()
        .arg("--version")
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .and_then(|s| s.lines().next().map(str::to_string))
        .unwrap_or(path)
}
