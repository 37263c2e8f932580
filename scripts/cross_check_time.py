#!/usr/bin/env python3
"""Lesson 10's path tracer against Mitsuba 3 at equal time (run by scripts/cross-check --time).

The cross-check (scripts/cross_check.py) shows that the crate and Mitsuba have the same
expected image; this script asks what each pays for it. Both render lesson 10's Cornell
box (MIS, TIME_DEPTH bounces, no Russian roulette) at TIME_SPP samples per pixel on one
thread; each image's error is its root-mean-square difference from a reference, the mean
of both renderers' images at REFERENCE_SPP samples per pixel (all threads). Error
against seconds, on log-log axes, is the chart of the book's page: at equal time, the
lower line wins.

The reference is noisy too: its variance adds to every measured mean squared error. It
is estimated from the two halves of the reference (the crate's and Mitsuba's images are
independent with the same expectation, so a quarter of their mean squared difference is
the variance of their mean) and subtracted; the fragment prints it.

    scripts/cross_check_time.py sweep --out DIR
        the sweep: DIR/10_9_error_time.csv and DIR/10_9_error_time.md
    scripts/cross_check_time.py mitsuba --variant scalar_rgb --spp 16 --threads 1 ...
        one Mitsuba render of a scene the crate describes, timed; prints one JSON line
        (also `scripts/cross_check.py time ...`, the benchmarks' entry point)

Standard library and Mitsuba only (no numpy).
"""

import argparse
import datetime
import glob
import json
import math
import os
import platform
import struct
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cross_check as cc  # noqa: E402

# ANCHOR: configuration
TIME_SCENE, TIME_SAMPLING, TIME_DEPTH = "cornell", "mis", 8
TIME_WIDTH, TIME_HEIGHT = 128, 96
TIME_SPP = [1, 2, 4, 8, 16, 32, 64, 128]
REFERENCE_SPP = 2048
# ANCHOR_END: configuration
VARIANTS = ["scalar_rgb", "llvm_ad_rgb"]


# ---------------------------------------------------------------- LLVM


def find_libllvm():
    """The libLLVM that Mitsuba's LLVM variants load: DRJIT_LIBLLVM_PATH if set, else
    the newest libLLVM 16 or later in the usual places (Debian: libllvm19)."""
    if os.environ.get("DRJIT_LIBLLVM_PATH"):
        return os.environ["DRJIT_LIBLLVM_PATH"]
    found = []
    for pattern in ("/usr/lib/x86_64-linux-gnu/libLLVM-*.so", "/usr/lib/llvm-*/lib/libLLVM*.so",
                    "/usr/lib64/libLLVM-*.so", "/usr/local/lib/libLLVM*.so"):
        for path in glob.glob(pattern):
            digits = "".join(c if c.isdigit() else " " for c in os.path.basename(path)).split()
            major = int(digits[0]) if digits else 0
            if major >= 16:
                found.append((major, path))
    return max(found)[1] if found else None


LLVM_MISSING = ("Mitsuba's llvm_ad_rgb needs libLLVM 16 or later "
                "(Debian: apt-get install libllvm19, or set DRJIT_LIBLLVM_PATH)")


# ---------------------------------------------------------------- one Mitsuba render


def write_pfm(path, width, height, values):
    """`values` as read_pfm returns them: RGB rows from the top."""
    with open(path, "wb") as f:
        f.write(f"PF\n{width} {height}\n-1.0\n".encode())
        for y in reversed(range(height)):
            row = values[y * width * 3 : (y + 1) * width * 3]
            f.write(struct.pack(f"<{width * 3}f", *row))


def mitsuba_render(args):
    """One timed Mitsuba render of the crate's scene; the JSON line it prints."""
    if args.sampling != "mis":
        sys.exit("cross_check_time: Mitsuba's `path` integrator samples with MIS only: "
                 "--sampling must be mis")
    if args.variant.startswith("llvm"):
        lib = find_libllvm()
        if lib is None:
            sys.exit(f"cross_check_time: {LLVM_MISSING}")
        os.environ["DRJIT_LIBLLVM_PATH"] = lib
    import drjit as dr
    import mitsuba as mi

    mi.set_variant(args.variant)
    if args.threads:
        dr.set_thread_count(args.threads)
    desc = json.loads(cc.crate("describe", "--scene", args.scene, "--width", str(args.width),
                               "--height", str(args.height)))
    scene = mi.load_dict(cc.mitsuba_dict(desc, args.max_depth, args.spp)[0])
    if args.variant.startswith("llvm"):
        # The first render compiles the kernels; a renderer's user pays that once.
        dr.eval(mi.render(scene, seed=args.seed + 1_000_000, spp=args.spp))
        dr.sync_thread()
    start = time.perf_counter()
    cpu = time.process_time()
    image = mi.render(scene, seed=args.seed, spp=args.spp)
    dr.eval(image)
    dr.sync_thread()
    seconds = time.perf_counter() - start
    cpu = time.process_time() - cpu
    if args.out:
        write_pfm(args.out, args.width, args.height, list(image.array))
    samples = args.width * args.height * args.spp
    return {"variant": args.variant, "mitsuba": mi.__version__, "seconds": seconds,
            "cpu_seconds": cpu, "samples": samples, "spp": args.spp}


def mitsuba_main(argv):
    p = argparse.ArgumentParser(prog="cross_check_time.py mitsuba",
                                description="one timed Mitsuba render of a crate scene")
    p.add_argument("--variant", choices=VARIANTS, default="scalar_rgb")
    p.add_argument("--scene", default=TIME_SCENE)
    p.add_argument("--sampling", default=TIME_SAMPLING)
    p.add_argument("--max-depth", type=int, default=TIME_DEPTH)
    p.add_argument("--width", type=int, default=TIME_WIDTH)
    p.add_argument("--height", type=int, default=TIME_HEIGHT)
    p.add_argument("--spp", type=int, required=True)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--threads", type=int, default=1, help="0: every core")
    p.add_argument("--out", help="also write the image as a PFM")
    args = p.parse_args(argv)
    for name in ("max_depth", "width", "height", "spp", "threads", "seed"):
        if getattr(args, name) < (1 if name in ("width", "height", "spp") else 0):
            p.error(f"--{name.replace('_', '-')} is out of range: {getattr(args, name)}")
    print(json.dumps(mitsuba_render(args)))
    return 0


# ---------------------------------------------------------------- the sweep


def mitsuba(variant, spp, seed, threads, out):
    """One render through a child process (a variant's LLVM set-up is per process)."""
    cmd = [sys.executable, os.path.abspath(__file__), "mitsuba", "--variant", variant,
           "--scene", TIME_SCENE, "--max-depth", str(TIME_DEPTH), "--width", str(TIME_WIDTH),
           "--height", str(TIME_HEIGHT), "--spp", str(spp), "--seed", str(seed),
           "--threads", str(threads), "--out", out]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"cross_check_time: `{' '.join(cmd)}` failed:\n{run.stderr}")
    result = json.loads(run.stdout.strip().splitlines()[-1])
    return result["seconds"], cc.read_pfm(out)


def crate(spp, seed, threads, out):
    args = ["render", "--scene", TIME_SCENE, "--width", str(TIME_WIDTH),
            "--height", str(TIME_HEIGHT), "--sampling", TIME_SAMPLING,
            "--max-depth", str(TIME_DEPTH), "--spp", str(spp), "--seed", str(seed),
            "--out", out]
    if threads:
        args += ["--threads", str(threads)]
    line = cc.crate(*args)
    if " 0 non-finite" not in line:
        sys.exit(f"cross_check_time: the crate dropped NaN samples: {line}")
    return float(line.split(" in ")[1].split(" s")[0]), cc.read_pfm(out)


def mean_square(a, b):
    return sum((x - y) ** 2 for x, y in zip(a, b)) / len(a)


def machine():
    """The CPU's name and the load averages now."""
    name = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    name = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return name, os.getloadavg()


def sweep(out_dir):
    import mitsuba as mi

    scratch = os.path.join(cc.ROOT, "target", "cross-check", "time")
    os.makedirs(scratch, exist_ok=True)
    cpu, load_before = machine()
    started = datetime.datetime.now(datetime.timezone.utc)
    llvm = find_libllvm()
    variants = VARIANTS if llvm else VARIANTS[:1]
    if not llvm:
        print(f"cross_check_time: skipping llvm_ad_rgb: {LLVM_MISSING}", file=sys.stderr)

    print(f"reference: {REFERENCE_SPP} spp from each renderer, every core", file=sys.stderr)
    _, ref_crate = crate(REFERENCE_SPP, 1, 0, os.path.join(scratch, "ref_crate.pfm"))
    _, ref_mitsuba = mitsuba("scalar_rgb", REFERENCE_SPP, 1, 0,
                             os.path.join(scratch, "ref_mitsuba.pfm"))
    reference = [(a + b) / 2 for a, b in zip(ref_crate, ref_mitsuba)]
    floor = mean_square(ref_crate, ref_mitsuba) / 4

    rows = []
    for i, spp in enumerate(TIME_SPP):
        seed = 100 + i
        runs = [("crate", crate(spp, seed, 1, os.path.join(scratch, f"crate_{spp}.pfm")))]
        for variant in variants:
            path = os.path.join(scratch, f"{variant}_{spp}.pfm")
            runs.append((f"Mitsuba {variant}", mitsuba(variant, spp, seed, 1, path)))
        for who, (seconds, image) in runs:
            rmse = math.sqrt(max(mean_square(image, reference) - floor, 0.0))
            rows.append({"renderer": who, "spp": spp, "seconds": seconds, "rmse": rmse})
            print(f"  {who}, {spp} spp: {seconds:.3f} s, RMS error {rmse:.4f}", file=sys.stderr)
    _, load_after = machine()
    stamp = {"started": started.strftime("%Y-%m-%d %H:%M UTC"), "cpu": cpu,
             "load_before": load_before[0], "load_after": load_after[0],
             "mitsuba": mi.__version__, "floor": math.sqrt(floor)}
    write_outputs(out_dir, rows, stamp)
    return 0


# ---------------------------------------------------------------- outputs


def per_root(rows, who, key):
    """RMS error x sqrt(row[key]), its geometric mean over the renderer's points from
    4 spp on. For key "seconds": the error after one second, if the error falls as
    1/sqrt(time); for key "spp": the error of one sample per pixel."""
    logs = [math.log(r["rmse"] * math.sqrt(r[key])) for r in rows
            if r["renderer"] == who and r["spp"] >= 4]
    return math.exp(sum(logs) / len(logs))


def slope(rows, who):
    """Least-squares slope of log(RMS error) against log(seconds)."""
    pts = [(math.log(r["seconds"]), math.log(r["rmse"])) for r in rows if r["renderer"] == who]
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    return (sum((x - mx) * (y - my) for x, y in pts)
            / sum((x - mx) ** 2 for x, _ in pts))


def write_outputs(out_dir, rows, stamp):
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "10_9_error_time.csv"), "w") as f:
        f.write("# written by scripts/cross-check --time; renderer,spp,seconds,rms_error\n")
        for r in rows:
            f.write(f"{r['renderer']},{r['spp']},{r['seconds']:.5f},{r['rmse']:.6f}\n")
    renderers = list(dict.fromkeys(r["renderer"] for r in rows))
    by = {(r["renderer"], r["spp"]): r for r in rows}
    md = ["<!-- Written by scripts/cross-check --time; do not edit. -->",
          "<!-- ANCHOR: stamp -->",
          f"One run, started {stamp['started']} on one thread of an {stamp['cpu']} "
          f"(load average {stamp['load_before']:.2f} before, {stamp['load_after']:.2f} after); "
          f"Mitsuba {stamp['mitsuba']}; lesson 10's Cornell box, {TIME_WIDTH} x {TIME_HEIGHT}, "
          f"MIS, {TIME_DEPTH} bounces, no Russian roulette; reference: {REFERENCE_SPP} samples "
          f"per pixel from each renderer, its own RMS noise {stamp['floor']:.4f} (subtracted)",
          "<!-- ANCHOR_END: stamp -->", "<!-- ANCHOR: table -->",
          "| samples per pixel | " + " | ".join(f"{w}: seconds, RMS error" for w in renderers)
          + " |",
          "|---:|" + "---:|" * len(renderers)]
    for spp in TIME_SPP:
        cells = [f"{by[(w, spp)]['seconds']:.3f}, {by[(w, spp)]['rmse']:.4f}" for w in renderers]
        md.append(f"| {spp} | " + " | ".join(cells) + " |")
    md += ["<!-- ANCHOR_END: table -->", "<!-- ANCHOR: summary -->",
           "| | " + " | ".join(renderers) + " |", "|---|" + "---:|" * len(renderers),
           "| slope of log error against log time | "
           + " | ".join(f"{slope(rows, w):.2f}" for w in renderers) + " |",
           "| error x sqrt(seconds) | "
           + " | ".join(f"{per_root(rows, w, 'seconds'):.4f}" for w in renderers) + " |",
           "| error x sqrt(samples per pixel) | "
           + " | ".join(f"{per_root(rows, w, 'spp'):.4f}" for w in renderers) + " |",
           "| time to the crate's error, over the crate's | "
           + " | ".join(f"{(per_root(rows, w, 'seconds') / per_root(rows, 'crate', 'seconds')) ** 2:.2f}"
                        for w in renderers) + " |",
           "<!-- ANCHOR_END: summary -->"]
    with open(os.path.join(out_dir, "10_9_error_time.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md[2:]))


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "mitsuba":
        return mitsuba_main(sys.argv[2:])
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("command", choices=["sweep"])
    p.add_argument("--out", default=os.path.join(cc.ROOT, "target", "cross-check", "out"))
    args = p.parse_args()
    return sweep(args.out)


if __name__ == "__main__":
    sys.exit(main())
