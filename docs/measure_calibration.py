#!/usr/bin/env python3
"""Calibrates this device's primitive costs several times in a row, each in its own process, and
writes how far the costs spread to docs/results/calibration.md (issue 18: every cost within
±15 % of the median of five runs).

Usage: docs/measure_calibration.py [--runs 5] [--width 480] [--height 270]

Each run is `sylva calibrate --force` (it measures again and replaces the cached model), so the
last run's model is what later plays use.
"""
import argparse
import datetime
import json
import os
import statistics
import subprocess
import sys
import tempfile

import measure_meta

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SYLVA = os.path.join(ROOT, "build", "bin", "sylva")


def median_and_spread(values):
    """The median and the largest distance of a value from it, in percent of it."""
    median = statistics.median(values)
    return median, max(abs(v / median - 1.0) for v in values) * 100.0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--width", type=int, default=480)
    parser.add_argument("--height", type=int, default=270)
    args = parser.parse_args()
    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(args.runs):
            out = os.path.join(tmp, f"run_{i}.json")
            cmd = [SYLVA, "calibrate", "--force", "--width", str(args.width), "--height", str(args.height),
                   "--json", out]
            print(f"[calibration] run {i + 1}/{args.runs}", file=sys.stderr)
            subprocess.run(cmd, check=False, stdout=subprocess.DEVNULL)
            with open(out) as f:
                runs.append(json.load(f))
    refused = [r.get("refused") for r in runs if "refused" in r]
    rows = []
    keys = [(c["sample_distance_px"], c["splats"]) for c in runs[0].get("costs_per_triangle", [])]
    worst = 0.0
    for d, splats in keys:
        for what in ("point", "line"):
            if what == "line" and splats == "opaque":
                continue  # lines do not depend on the splat style
            values = [next(c[what] for c in r["costs_per_triangle"] if c["sample_distance_px"] == d and c["splats"] == splats)
                      for r in runs if "costs_per_triangle" in r]
            median, spread = median_and_spread(values)
            worst = max(worst, spread)
            label = f"{splats} splat" if what == "point" else "line"
            rows.append(f"| {d:g} | {label} | {median:.3f} | {min(values):.3f} – {max(values):.3f} | ±{spread:.1f} % |")
    # The auto ladder's cost coefficients (lod/shader_work_costs.h): what its rung tables' shader
    # work is priced at, so how far they spread is how far a budget's choices can move between
    # calibrations of one device.
    work_rows = []
    for key, label in (("vertex_us", "c_v, µs per vertex"), ("fragment_us", "c_f, µs per view fragment"),
                       ("shadow_fragment_us", "c_s, µs per shadow fragment")):
        values = [r["shader_work"]["costs"][key] for r in runs if "costs" in r.get("shader_work", {})]
        if not values:
            continue
        median, spread = median_and_spread(values)
        work_rows.append(f"| {label} | {median:.5f} | {min(values):.5f} – {max(values):.5f} | ±{spread:.1f} % |")
    work_refused = [r["shader_work"]["refused"] for r in runs if "refused" in r.get("shader_work", {})]
    commit = measure_meta.commit()
    seconds = [r["seconds"] for r in runs if "seconds" in r]
    page = [
        "# Results: the device calibration of primitive costs",
        "",
        f"Measured {datetime.date.today().isoformat()} at commit `{commit}` on {runs[0]['device']}.",
        f"{args.runs} runs of `sylva calibrate --force --width {args.width} --height {args.height}`, each in its own "
        f"process, one after the other ({min(seconds):.0f}–{max(seconds):.0f} s each). Reproduce: "
        f"`docs/measure_calibration.py --runs {args.runs} --width {args.width} --height {args.height}`.",
        "",
        f"Refused runs: {len(refused)}" + ("" if not refused else " (" + "; ".join(refused) + ")") + ".",
        "",
        "Costs relative to a triangle at each d' (c_p 1.3); the spread is the largest distance of a run from "
        f"the median. Worst: ±{worst:.1f} % (target ±15 %).",
        "",
        "| d' px | primitive | median | range | spread |",
        "|---:|---|---:|---|---:|",
        *rows,
        "",
        "## Shader work (the auto ladder's rung costs)",
        "",
        "What `sylva calibrate` fits from frames of tiny, small and large triangles and a shadow map "
        "(lod/shader_work_costs.h); the auto ladder prices its rung tables' vertex and fragment invocations "
        "with them, so their spread is how far a plant budget's choices can move between calibrations of one "
        f"device. Refused runs: {len(work_refused)}.",
        "",
        "| coefficient | median | range | spread |",
        "|---|---:|---|---:|",
        *work_rows,
        "",
    ]
    os.makedirs(os.path.join(ROOT, "docs", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "docs", "results", "calibration.md"), "w") as f:
        f.write("\n".join(page))
    print("\n".join(page))
    return 0 if not refused else 1


if __name__ == "__main__":
    sys.exit(main())
