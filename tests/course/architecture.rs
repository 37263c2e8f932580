//! The core's shape, as `src/lib.rs` states it: dependencies flow one way, from
//! the maths up to the renderers, and the course's tools (`src/course/`) sit on
//! top, imported by nothing in the renderer. Read from the sources: every
//! `crate::...` path outside comments and test modules is an import.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

/// The layers of `src/lib.rs`, lowest first. A module may only use modules of
/// lower layers (and its own submodules).
const LAYERS: &[&[&str]] = &[
    &["error", "float"],
    &[
        "limits",
        "transform",
        "ray",
        "basis",
        "rng",
        "sampling",
        "material",
        "files",
        "progress",
    ],
    &["quadratic", "spawn", "bvh", "texture"],
    &["camera", "shapes"],
    &["scene", "framebuffer"],
    &["lighting", "render", "mesh"],
    &["raycast", "raster", "pathtrace"],
    &["scenes"],
    &["prelude"],
    &["course"],
];

/// Every `.rs` file under `dir` as (module path, source without comments and
/// without its `#[cfg(test)]` tail).
fn modules(dir: &Path, prefix: &[String], out: &mut BTreeMap<String, String>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        let mut module = prefix.to_vec();
        if path.is_dir() {
            module.push(name);
            modules(&path, &module, out);
            continue;
        }
        if path.extension().is_none_or(|e| e != "rs") {
            continue;
        }
        if name != "mod" && name != "lib" {
            module.push(name);
        }
        let text = fs::read_to_string(&path).unwrap();
        let text = text.split("#[cfg(test)]").next().unwrap_or("");
        let code: Vec<&str> = text
            .lines()
            .map(|l| l.split("//").next().unwrap_or(""))
            .collect();
        out.insert(module.join("::"), code.join("\n"));
    }
}

/// The modules `source` (of module `me`) refers to through `crate::` or `super::`,
/// resolved to the longest known module path.
fn imports(me: &str, source: &str, known: &BTreeSet<String>) -> BTreeSet<String> {
    let mut found = BTreeSet::new();
    let words: Vec<&str> = source
        .split(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':' || c == '{'))
        .collect();
    for word in words {
        let word = word.split('{').next().unwrap_or("");
        let path = if let Some(rest) = word.strip_prefix("crate::") {
            rest.to_string()
        } else if let Some(rest) = word.strip_prefix("super::") {
            let mut parent: Vec<&str> = me.split("::").collect();
            parent.pop();
            parent.push(rest);
            parent.join("::")
        } else {
            continue;
        };
        let segments: Vec<&str> = path.split("::").filter(|s| !s.is_empty()).collect();
        let target = (1..=segments.len())
            .rev()
            .map(|n| segments[..n].join("::"))
            .find(|m| known.contains(m));
        if let Some(t) = target
            && t != me
            && !me.starts_with(&format!("{t}::"))
        {
            found.insert(t);
        }
    }
    found
}

fn graph() -> BTreeMap<String, BTreeSet<String>> {
    let mut sources = BTreeMap::new();
    modules(Path::new("src"), &[], &mut sources);
    let known: BTreeSet<String> = sources.keys().cloned().collect();
    sources
        .iter()
        .map(|(m, s)| (m.clone(), imports(m, s, &known)))
        .collect()
}

fn top(module: &str) -> &str {
    module.split("::").next().unwrap_or(module)
}

fn layer(top: &str) -> Option<usize> {
    LAYERS.iter().position(|l| l.contains(&top))
}

#[test]
fn every_top_level_module_has_a_layer() {
    for module in graph().keys().filter(|m| !m.is_empty()) {
        assert!(
            layer(top(module)).is_some(),
            "src/lib.rs and LAYERS here must place `{}`",
            top(module)
        );
    }
}

#[test]
fn dependencies_flow_one_way_and_the_renderer_never_imports_the_course() {
    let mut wrong = Vec::new();
    for (module, deps) in graph() {
        let Some(mine) = layer(top(&module)) else {
            continue;
        };
        for dep in deps {
            if top(&dep) == top(&module) {
                continue;
            }
            let theirs = layer(top(&dep)).unwrap_or(usize::MAX);
            if theirs >= mine {
                wrong.push(format!("{module} -> {dep}"));
            }
        }
    }
    assert!(wrong.is_empty(), "imports against the flow: {wrong:?}");
}

#[test]
fn the_renderer_knows_nothing_of_command_lines() {
    let mut sources = BTreeMap::new();
    modules(Path::new("src"), &[], &mut sources);
    for (module, code) in sources {
        if top(&module) != "course" {
            assert!(
                !code.contains("clap"),
                "{module} uses clap: flags belong in course/"
            );
        }
    }
}

#[test]
fn no_two_public_types_share_a_name() {
    let mut sources = BTreeMap::new();
    modules(Path::new("src"), &[], &mut sources);
    let mut seen: BTreeMap<String, String> = BTreeMap::new();
    for (module, code) in sources {
        let words: Vec<&str> = code.split_whitespace().collect();
        for w in words.windows(3) {
            if w[0] == "pub" && ["struct", "enum", "type", "trait"].contains(&w[1]) {
                let name: String =
                    w[2].chars().take_while(|c| c.is_alphanumeric()).collect();
                if let Some(other) = seen.insert(name.clone(), module.clone()) {
                    panic!("two public types called {name}: in {other} and {module}");
                }
            }
        }
    }
    assert!(seen.contains_key("Scene") && seen.contains_key("Model"));
}

#[test]
fn no_import_cycle_between_files() {
    let graph = graph();
    // Depth-first search; a back edge closes a cycle.
    fn visit(
        m: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        state: &mut BTreeMap<String, u8>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        state.insert(m.to_string(), 1);
        stack.push(m.to_string());
        for d in graph.get(m).into_iter().flatten() {
            match state.get(d.as_str()) {
                Some(1) => {
                    let start = stack.iter().position(|s| s == d).unwrap_or(0);
                    return Some(stack[start..].to_vec());
                }
                Some(_) => {}
                None => {
                    if let Some(c) = visit(d, graph, state, stack) {
                        return Some(c);
                    }
                }
            }
        }
        stack.pop();
        state.insert(m.to_string(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for m in graph.keys() {
        if !state.contains_key(m.as_str()) {
            let cycle = visit(m, &graph, &mut state, &mut Vec::new());
            assert!(cycle.is_none(), "import cycle: {cycle:?}");
        }
    }
}

#[test]
fn the_checker_sees_a_known_import() {
    // If the parsing broke, every test above would pass vacuously.
    let graph = graph();
    assert!(graph["scene"].contains("shapes"), "{:?}", graph["scene"]);
    assert!(graph["raycast"].contains("scene"));
    assert!(graph["pathtrace::estimator"].contains("pathtrace::next_event"));
}

/// The front door (issue 32): `examples/library.rs`, a whole program, is at most 40
/// lines and needs one `use` of the crate, the prelude.
#[test]
fn the_library_example_is_short_and_needs_one_use() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("examples/library.rs")).unwrap();
    assert!(text.lines().count() <= 40, "{} lines", text.lines().count());
    let uses: Vec<&str> = text.lines().filter(|l| l.starts_with("use ")).collect();
    assert_eq!(uses, ["use render_lessons::prelude::*;"]);
}
