#!/usr/bin/env python3
"""Measures LoDF's popping along the `single_tree` and `forest` camera paths against the mesh
levels at equal frame time (issue 23), and writes docs/results/lodf_popping.md.

Usage: docs/measure_lodf_popping.py [--rounds 3] [--frames 12]
       docs/measure_lodf_popping.py --from SINGLE_TREE_RUN FOREST_RUN --commit SHA --date YYYY-MM-DD

Three families are run side by side in one bench per scenario, each at several scales of its
switch sizes (cheaper to dearer; the bench has the mesh levels' at x0.25 … x2): `ladder_lodf`
(the scenario's ladder with LoDF in the reduced mesh's place, x0.5 … x4 with the steps between
x1 and x2 where a near tree is on LoDF), `ladder` (the same ladder with the reduced mesh) and
`mesh_lod` (full, reduced and far mesh by distance). Times are the median over timing rounds of
each configuration's frame time over `ladder`'s in the same round; popping is the bench's (the
frame-to-frame change a configuration adds over the reference's own, per pixel); errors are
against the same supersampled reference.

The verdict at equal frame time: for each point of the other two families, the `ladder_lodf`
points at most as slow as it (the median of their round-by-round time ratios to it <= 1) that
draw a plant on LoDF in some frame (a point with none draws what `ladder` draws: not LoDF's
doing), and among them the one that pops least: "lower" when it pops less than the rival,
"not lower" otherwise; "the same image" when no such point pops less but one of the family at
most as slow draws exactly the rival's image (the tree whole, as the mesh levels draw it). `--from` writes the page from two existing bench
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
SCALES = {"ladder_lodf": ["_x0.5", "", "_x1.125", "_x1.25", "_x1.5", "_x1.75", "_x2", "_x4"], "ladder": ["_x0.5", "", "_x2", "_x4"],
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
    # At equal time: each point of the other families against the LoDF points no slower than it.
    out += ["", "At equal time (each point of the other families against the `ladder_lodf` points at most as slow "
            "as it, time ratios to it side by side in the same rounds; the one that pops least):", ""]
    lodf_rows = [r for r in rows if r[0].startswith("ladder_lodf")]
    draws_lodf = {r[0] for r in lodf_rows
                  if any(f["primitives"].get("instances_lodf", 0) > 0 for f in by[r[0]]["records"]["frames"])}
    for family in FAMILIES[1:]:
        for name in [family + s for s in SCALES[family]]:
            rival = next(r for r in rows if r[0] == name)
            pop = rival[2]
            head = f"- `{name}` at {rival[1]:.2f}× pops {'n/a' if pop is None else f'{pop:.3f}'}: "
            no_slower = [(r, ratio_to(by[r[0]], by[name])) for r in lodf_rows]
            no_slower = [(r, t) for r, t in no_slower if t <= 1.0]
            on_lodf = [(r, t) for r, t in no_slower if r[0] in draws_lodf and r[2] is not None]
            same = [(r, t) for r, t in no_slower if same_image(r[6], rival[6])]
            if pop is None:
                out.append(head + "n/a (no popping measured)")
                continue
            best = min(on_lodf, key=lambda x: x[0][2]) if on_lodf else None
            if best and best[0][2] < pop:
                r, t = best
                out.append(head + f"`{r[0]}` at {t:.2f}× it pops {r[2]:.3f} (lower)")
            elif same:
                r, t = same[0]
                out.append(head + f"`{r[0]}` at {t:.2f}× it draws the same image (the same popping)")
            elif best:
                r, t = best
                out.append(head + f"`{r[0]}` at {t:.2f}× it pops {r[2]:.3f} (not lower)")
            else:
                drawing = [r for r in lodf_rows if r[0] in draws_lodf]
                if not drawing:
                    out.append(head + "no `ladder_lodf` point draws a plant on LoDF")
                    continue
                fastest = min(drawing, key=lambda r: ratio_to(by[r[0]], by[name]))
                out.append(head + f"no `ladder_lodf` point with a plant on LoDF as fast (fastest `{fastest[0]}` "
                           f"at {ratio_to(by[fastest[0]], by[name]):.2f}× it, pops {fastest[2]:.3f})")
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
