#!/usr/bin/env python3
"""Where a path sample's instructions go (issue 33), from two callgrind runs.

Reads two callgrind output files of `cross-check render` (one and two samples per
pixel, built with line tables), takes every instruction's source line (for code
inlined from another function, the line of the function it came from: DWARF's line
table), subtracts the first run from the second (start-up, set-up and the image's
writing cancel out) and divides by the pixels: instructions per path sample. Each
line of the crate's own source is given to the function it lies in (the last `fn`
above it); lines of glam, core or libm, which the crate's functions inline, are
given to the crate's function the instruction was compiled into (callgrind's
function, the symbol). Then each function is put in a group: see GROUPS. Also
counts the rays a path sample traces (calls of the scene's closest-hit and
shadow-ray functions).

    scripts/instructions-per-sample   (runs the renders, then this)
    scripts/instructions_per_sample.py ONE TWO PIXELS [--functions]
"""

import argparse
import os
import re
import sys
from collections import defaultdict

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The groups, in the order the table prints them, each with the crate's functions
# (source file, function name) it holds. A function listed nowhere lands in
# "the rest", which the table breaks down too.
GROUPS = [
    (
        "intersection (closest hit and shadow rays: the scene's loop, the shapes' tests)",
        [
            ("src/scene/", "*"),
            ("src/bvh/", "*"),
            ("src/shapes/", "*"),
            ("src/ray.rs", "*"),
            ("src/quadratic.rs", "*"),
        ],
    ),
    (
        "sampling (directions, light points and their densities)",
        [
            ("src/sampling.rs", "*"),
            ("src/pathtrace/light.rs", "*"),
            ("src/basis.rs", "*"),
            ("src/pathtrace/estimator.rs", "diffuse_bounce"),
            ("src/pathtrace/estimator.rs", "to_unit"),
            ("src/pathtrace/next_event.rs", "*"),
            ("(outside the crate)", "__sincosf_fma"),
        ],
    ),
    ("random numbers (PCG32)", [("src/rng.rs", "*")]),
    (
        "MIS weights (power heuristic, the BRDF density at a light hit)",
        [
            ("src/pathtrace/mis.rs", "*"),
            ("src/pathtrace/estimator.rs", "emission_weight"),
            ("src/pathtrace/estimator.rs", "after_diffuse"),
        ],
    ),
    ("Fresnel and specular bounces", [("src/material.rs", "*")]),
    (
        "new rays (origins moved off the surface, shadow rays' unit directions)",
        [("src/spawn.rs", "*"), ("src/float.rs", "*"), ("src/error.rs", "unit")],
    ),
    (
        "the path's loop (throughput, emission, next ray)",
        [
            ("src/pathtrace/estimator.rs", "*"),
            ("src/pathtrace/roulette.rs", "*"),
            ("src/scene/mod.rs", "emission_seen"),
        ],
    ),
    (
        "camera rays and accumulation (pixel loop, sums)",
        [
            ("src/pathtrace/progressive.rs", "*"),
            ("src/camera/", "*"),
            ("(outside the crate)", "core::ops::function::impls::<impl core::ops::function::FnMut<A> for &F>::call_mut"),
        ],
    ),
]

# The rays a path traces, by the function each kind calls once per ray.
RAYS = [
    ("closest-hit rays (Scene::closest)", "render_lessons::scene::Scene::closest"),
    ("shadow rays (Scene::occluded)", "Intersect>::occluded"),
]

FN_RE = re.compile(r"^\s*(?:pub(?:\([^)]*\))?\s+)?(?:const\s+)?(?:unsafe\s+)?fn\s+(\w+)")


class Sources:
    """The crate's source files, read once: the function each line lies in."""

    def __init__(self):
        self.cache = {}

    def relative(self, path):
        """`path` relative to the repository if it is one of the crate's files."""
        i = path.find("/src/")
        if i < 0:
            return None
        rel = path[i + 1:]
        return rel if os.path.exists(os.path.join(ROOT, rel)) and "/.cargo/" not in path else None

    def function(self, rel, line):
        if rel not in self.cache:
            names = []
            current = "(no function)"
            with open(os.path.join(ROOT, rel), encoding="utf-8") as f:
                for text in f:
                    m = FN_RE.match(text)
                    if m:
                        current = m.group(1)
                    names.append(current)
            self.cache[rel] = names
        names = self.cache[rel]
        # Line 0: code the compiler made with no line of its own (in this file).
        return names[line - 1] if 0 < line <= len(names) else "(no line)"


def read_callgrind(path):
    """Self cost (Ir) by (function symbol, source file, line), and calls by callee."""
    cost = defaultdict(int)
    calls = defaultdict(int)
    callee = None
    names = {"fl": {}, "fn": {}, "cfn": {}}
    fl = fi = fn = None
    line = 0
    skip_next = False

    def name(kind, text):
        m = re.match(r"\((\d+)\)(?: (.*))?", text)
        if not m:
            return text
        table = names["fn" if kind in ("fn", "cfn") else "fl"]
        if m.group(2) is not None:
            table[m.group(1)] = m.group(2)
        return table.get(m.group(1), "?")

    with open(path, encoding="utf-8", errors="replace") as f:
        for raw in f:
            s = raw.rstrip("\n")
            if not s:
                continue
            if s[0].isdigit() or s[0] in "+-*":
                parts = s.split()
                pos = parts[0]
                if pos == "*":
                    pass
                elif pos[0] in "+-":
                    line += int(pos)
                else:
                    line = int(pos)
                if skip_next:
                    skip_next = False
                    continue
                if len(parts) > 1:
                    cost[(fn, fi, line)] += int(parts[1])
                continue
            key, _, value = s.partition("=")
            if key == "fl":
                fl = fi = name("fl", value)
            elif key in ("fi", "fe"):
                fi = name("fl", value)
            elif key == "fn":
                fn = name("fn", value)
                fi = fl
            elif key in ("cfl", "cfi"):
                name("fl", value)
            elif key == "cfn":
                callee = name("cfn", value)
            elif key == "calls":
                calls[callee] += int(value.split()[0])
                skip_next = True
    return cost, calls


def symbol_home(symbol):
    """The crate's (file, function) a symbol names, e.g.
    'render_lessons::scene::Scene::closest' -> ('src/scene/mod.rs', 'closest'), or
    None for a symbol outside the crate (libm's sincosf)."""
    m = re.search(r"render_lessons::([\w:]+)", symbol or "")
    if not m:
        return None
    parts = m.group(1).split("::")
    func = (symbol or "").split("::")[-1]
    # The longest module path that is a file: src/a/b.rs or src/a/b/mod.rs.
    for n in range(len(parts), 0, -1):
        base = os.path.join("src", *parts[:n])
        for rel in (base + ".rs", os.path.join(base, "mod.rs")):
            if os.path.exists(os.path.join(ROOT, rel)):
                return rel, func
    return None


def group_of(rel, func):
    """The group of the crate's function `func` in file `rel`: one that names it,
    else one that takes its whole file; None for neither."""
    for wanted in (func, "*"):
        for label, members in GROUPS:
            if any(rel.startswith(prefix) and name == wanted for prefix, name in members):
                return label
    return None


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("one")
    p.add_argument("two")
    p.add_argument("pixels", type=int)
    p.add_argument("--functions", action="store_true")
    args = p.parse_args()
    (one, calls_one), (two, calls_two) = read_callgrind(args.one), read_callgrind(args.two)
    sources = Sources()
    # The crate's own lines by the function they lie in; library lines (glam, core,
    # libm) by the symbol they were compiled into, which names a crate function.
    totals = defaultdict(int)
    inlined = defaultdict(int)
    for key in set(one) | set(two):
        n = two.get(key, 0) - one.get(key, 0)
        symbol, path, line = key
        rel = sources.relative(path or "")
        if rel is not None:
            totals[(rel, sources.function(rel, line))] += n
            continue
        home = symbol_home(symbol)
        if home is None:
            home = ("(outside the crate)", (symbol or "?").split("[")[0].strip())
        totals[home] += n
        inlined[home] += n
    total = sum(totals.values())
    per = args.pixels
    groups = defaultdict(int)
    for (rel, func), n in totals.items():
        groups[group_of(rel, func) or "the rest"] += n
    print("| where (callgrind, per path sample) | instructions | share |")
    print("|---|---:|---:|")
    for label, _ in GROUPS + [("the rest", None)]:
        n = groups.get(label, 0)
        print(f"| {label} | {n / per:,.0f} | {100 * n / total:.1f}% |")
    print(f"| **in all** | **{total / per:,.0f}** | 100% |")
    rays = {}
    for label, symbol in RAYS:
        rays[label] = sum(calls_two[k] - calls_one.get(k, 0) for k in calls_two if symbol in k)
    print("\nRays per path sample: " + ", ".join(
        f"{n / per:.2f} {label}" for label, n in rays.items()))
    if args.functions:
        print("\nBy function (its own lines and the library code inlined into it):")
        for (rel, func), n in sorted(totals.items(), key=lambda kv: -kv[1]):
            if abs(n) / per < 20:
                continue
            g = group_of(rel, func) or "the rest"
            lib = inlined.get((rel, func), 0) / per
            note = f" (library code inlined into it: {lib:,.0f})" if lib >= 1 else ""
            print(f"  {n / per:8,.0f}  {rel}::{func}  [{g.split(' (')[0]}]{note}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
