#!/usr/bin/env python3
"""Measures LoDF's popping along the `single_tree` and `forest` camera paths against the mesh
levels at equal frame time (issue 23), and writes docs/results/lodf_popping.md.

Usage: docs/measure_lodf_popping.py [--rounds 3] [--frames 12]
       docs/measure_lodf_popping.py --from SINGLE_TREE_RUN FOREST_RUN --commit SHA --date YYYY-MM-DD

Three families are run side by side in one bench per scenario, each at four scales of its
switch sizes (cheaper to dearer; the bench has the mesh levels' at x0.25 … x2): `ladder_lodf` (the scenario's ladder with LoDF
in the reduced mesh's place), `ladder` (the same ladder with the reduced mesh) and `mesh_lod`
(full, reduced and far mesh by distance). Times are the median over timing rounds of each
configuration's frame time over `ladder`'s in the same round; popping is the bench's (the
frame-to-frame change a configuration adds over the reference's own, per pixel); errors are
against the same supersampled reference. `--from` writes the page from two existing bench
outputs (`sylva bench --out DIR`) run with the configurations below, at the commit and on the
date given.
"""
import argparse
import datetime
import json
import os
import subprocess
import sys

import measure_meta

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SYLVA = os.path.join(ROOT, "build", "bin", "sylva")
SCALES = {"ladder_lodf": ["_x0.5", "", "_x2", "_x4"], "ladder": ["_x0.5", "", "_x2", "_x4"],
          "mesh_lod": ["_x0.25", "_x0.5", "", "_x2"]}
FAMILIES = list(SCALES)
CONFIGS = [f + s for f in FAMILIES for s in SCALES[f]]
RUNS = {s: ["--width", "480", "--height", "270"] for s in ("single_tree", "forest")}


def command(scenario, frames, rounds, out):
    return [SYLVA, "bench", scenario, *RUNS[scenario], "--frames", str(frames), "--timing-rounds", str(rounds),
            "--only", ",".join(CONFIGS), "--out", out]


def same_image(a, b):
    return all(a[k] == b[k] for k in ("ssim", "perceptual", "psnr", "coverage_iou", "popping"))


def ratio_to(c, ref):
    """The median over rounds of c's round median over ref's (side by side in one run)."""
    pairs = sorted(a / b for a, b in zip(c["frame_ms"]["round_medians"], ref["frame_ms"]["round_medians"]))
    n = len(pairs)
    return pairs[n // 2] if n % 2 else 0.5 * (pairs[n // 2 - 1] + pairs[n // 2])


def section(bench, cmd):
    by = {c["name"]: c for c in bench["configurations"]}
    missing = [n for n in CONFIGS if n not in by]
    if missing:
        raise SystemExit(f"measure_lodf_popping: {bench['scenario']} run lacks {', '.join(missing)}")
    ref = by["ladder"]
    rows = []
    for name in CONFIGS:
        c = by[name]
        e = c["error"]
        p = c["primitives"]
        pop = e.get("popping")
        rows.append((name, ratio_to(c, ref), pop, e["ssim"], e["perceptual"], p.get("instances_lodf", 0.0), e))
    out = [f"## `{bench['scenario']}`", "",
           f"{bench['frames']} frames at {bench['width']}×{bench['height']}, {bench['timing_rounds']} timing rounds; "
           f"{bench['machine']}; {bench['gl_renderer']}:", "", "```", " ".join(cmd), "```", "",
           "| configuration | time (× `ladder`) | popping | SSIM | FLIP | plants on LoDF (median frame) |",
           "|---|---|---|---|---|---|"]
    for name, t, pop, ssim, flip, lodf, _ in sorted(rows, key=lambda r: r[1]):
        pop_text = "n/a" if pop is None else f"{pop:.3f}"
        out.append(f"| `{name}` | {t:.2f} | {pop_text} | {ssim:.4f} | {flip:.4f} | {lodf:.0f} |")
    # At equal time: each LoDF point against the other families' point nearest it in time.
    out += ["", "At equal time (each `ladder_lodf` point against the nearest point of each other family):", ""]
    for name, t, pop, _, _, _, e in [r for r in rows if r[0].startswith("ladder_lodf")]:
        said = []
        for family in FAMILIES[1:]:
            rivals = [r for r in rows if r[0] in {family + s for s in SCALES[family]}]
            near = min(rivals, key=lambda r: abs(r[1] - t))
            if same_image(e, near[6]):
                verdict = "the same image: no plant on LoDF"
            elif pop is None or near[2] is None:
                verdict = "n/a"
            else:
                verdict = "lower" if pop < near[2] else "not lower"
            said.append(f"`{near[0]}` at {near[1]:.2f}× pops {'n/a' if near[2] is None else f'{near[2]:.3f}'} ({verdict})")
        out.append(f"- `{name}` at {t:.2f}× pops {'n/a' if pop is None else f'{pop:.3f}'}: " + "; ".join(said))
    return out + [""]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--frames", type=int, default=12)
    parser.add_argument("--from", dest="runs", nargs=2, metavar=("SINGLE_TREE_RUN", "FOREST_RUN"))
    parser.add_argument("--commit")
    parser.add_argument("--date")
    args = parser.parse_args()
    if args.runs and not (args.commit and args.date):
        parser.error("--from needs --commit and --date: the commit and day the runs were made")
    commit = args.commit or measure_meta.commit()
    date = args.date or datetime.date.today().isoformat()
    runs = args.runs or [os.path.join(ROOT, "out", "lodf_popping", s) for s in RUNS]
    lines = ["# LoDF's popping against the mesh levels", "",
             "Written by `docs/measure_lodf_popping.py`; nothing here is edited by hand. "
             "What the figures mean: [LoDF](../representations/lodf.md#where-it-stands).", "",
             f"Measured {date} at commit `{commit}` on {measure_meta.machine()}.", ""]
    for scenario, run in zip(RUNS, runs):
        if not args.runs:
            cmd = command(scenario, args.frames, args.rounds, run)
            print("[lodf_popping] " + " ".join(cmd), file=sys.stderr)
            subprocess.run(cmd, check=True)
        with open(os.path.join(run, "bench.json")) as f:
            bench = json.load(f)
        cmd = ["./sylva", *command(bench["scenario"], bench["frames"], bench["timing_rounds"], "OUT")[1:]]
        lines += section(bench, cmd)
    measure_meta.write_page("lodf_popping.md", lines)


if __name__ == "__main__":
    sys.exit(main())
