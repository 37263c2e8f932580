//! Compiles the plain C anchor (`anchors/plain_caster.c`) with the system's C
//! compiler, at -O2 without -march=native, and sets `cfg(c_anchor)` when it could.
//! Without a C compiler the benches build all the same and skip the anchor (but
//! criterion itself needs one: its dependency alloca compiles C, and rustc links
//! through `cc` on Linux; `RENDER_BENCHES_NO_C_ANCHOR=1` shows the skipped path).

/// The flags the anchor is compiled with (besides cc's own, e.g. -fPIC), printed by
/// the bench next to its figures.
const FLAGS: &str = "-O2 -ffp-contract=off";

/// Set (to anything) to build without the anchor, as a machine without a C compiler
/// does: the benches then print a note in its place.
const OPT_OUT: &str = "RENDER_BENCHES_NO_C_ANCHOR";

fn main() {
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
