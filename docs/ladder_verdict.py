#!/usr/bin/env python3
"""Writes docs/results/ladder_verdict.md, the auto ladder against the engine baseline (issue 21),
from `sylva bench` outputs.

Usage: docs/ladder_verdict.py --commit SHA --date YYYY-MM-DD --command "CMD" RUN_DIR [RUN_DIR ...]
       docs/ladder_verdict.py --kept

Each RUN_DIR holds one scenario's bench.json (`sylva bench --out RUN_DIR`) run with the baseline
sweep and the auto ladder's sweeps: family `auto` (a plant budget per frame) and, where measured,
`auto_gain` (a least gain per ms); both are the same runtime with another aim, so a baseline point
is beaten when either sweep beats it. The bench.json files are kept as docs/results/ladder_verdict/<scenario>.json
with the date, commit and command beside them, and `--kept` writes the page again from those.
The verdict itself is the bench's (its `verdicts`, one per family: an auto point at most as slow,
by the median of the round-by-round time ratios, with SSIM at least and FLIP at most the baseline
point's); of the two families' the faster beating point is shown.
This adds, for each baseline point, the auto point that draws the very same image when there
is one (equal errors to the last digit: a tie, whatever the timing says), and the auto points
nearest it in time.
"""
import json
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
KEPT = os.path.join(HERE, "results", "ladder_verdict")
PAGE = os.path.join(HERE, "results", "ladder_verdict.md")
BASELINE_POINTS = ["crossed_billboard_only", "baseline_25m", "baseline", "baseline_100m"]
NOISE = 0.03  # this machine's timing noise in a time ratio
AUTO_FAMILIES = ("auto", "auto_gain")  # the auto ladder's sweeps: a budget, a gain


def same_image(a, b):
    keys = ("ssim", "perceptual", "psnr", "coverage_iou")
    return all(a["error"][k] == b["error"][k] for k in keys)


def point(c):
    e = c["error"]
    return f"{c['frame_ms']['vs_baseline']:.2f}×, SSIM {e['ssim']:.4f}, FLIP {e['perceptual']:.4f}"


def scenario_section(kept):
    bench, meta = kept["bench"], kept["meta"]
    by_name = {c["name"]: c for c in bench["configurations"]}
    autos = sorted((c for c in bench["configurations"] if c["family"] in AUTO_FAMILIES),
                   key=lambda c: c["frame_ms"]["vs_baseline"])
    verdicts = [v for v in bench["verdicts"] if v["family"] in AUTO_FAMILIES and v["lighting"] == "normal"]
    sweeps = ", ".join(f"`{v['family']}` ({len(v['configurations'])} points)" for v in verdicts)
    out = [f"## `{bench['scenario']}`", "",
           f"{bench['frames']} frames at {bench['width']}×{bench['height']}, {bench['timing_rounds']} timing "
           f"rounds; {bench['machine']}; {bench['gl_renderer']}; measured {meta['date']} at commit "
           f"`{meta['commit'][:10]}`; the auto sweeps {sweeps}:", "", "```", meta["command"], "```", "",
           "| baseline point | its time, SSIM, FLIP | verdict | the same image | auto points nearest in time |",
           "|---|---|---|---|---|"]
    every_beaten = True
    for name in BASELINE_POINTS:
        if name not in by_name:
            continue
        b = by_name[name]
        judged = [(v["family"], p) for v in verdicts for p in v["points"] if p["baseline"] == name]
        beaten = sorted((p for _, p in judged if p["beaten_by"]), key=lambda p: p["time_ratio"])
        every_beaten = every_beaten and bool(beaten)
        if not judged:
            said = "n/a"
        elif beaten:
            said = f"✓ {beaten[0]['beaten_by']} ({beaten[0]['time_ratio']:.2f}×)"
        else:
            said = "✗ " + "; ".join(f"{family}: {p['why_not']}" for family, p in judged)
        twins = [a["name"] for a in sorted(autos, key=lambda a: a["quality"]) if same_image(a, b)]
        twin = f"tie: {', '.join(twins)}" if twins else "none"
        t = b["frame_ms"]["vs_baseline"]
        near = sorted(autos, key=lambda a: abs(a["frame_ms"]["vs_baseline"] - t))[:2]
        near_text = "; ".join(f"{a['name']} {point(a)}" for a in sorted(near, key=lambda a: a["frame_ms"]["vs_baseline"]))
        out.append(f"| `{name}` | {point(b)} | {said} | {twin} | {near_text} |")
    out += ["", f"Every point beaten: {'yes' if every_beaten and verdicts else 'no'} "
            "(a ✓ or ✗ at 1.00 ± 0.03 is within this machine's timing noise; a tie draws the same image).", ""]
    return out + transitions_section(by_name, autos)


def figure(value):
    return "n/a" if value is None or value != value else f"{value:.2f}"


def transitions_section(by_name, autos):
    """Issue 21's transitions at equal frame time: for each baseline point, the slowest auto point
    at most as slow (within the timing noise, 0.03), its popping and lighting jump against the
    baseline point's. A jump is n/a when no plant finished a change of representation over the
    frames (nothing to measure, not 0)."""
    out = ["Transitions at equal frame time (the slowest auto point at most 0.03× slower than the "
           "baseline point; popping and lighting jump, lower is better):", "",
           "| baseline point | auto point | popping | lighting jump |", "|---|---|---|---|"]
    for name in BASELINE_POINTS:
        if name not in by_name:
            continue
        b = by_name[name]
        t = b["frame_ms"]["vs_baseline"]
        cheaper = [a for a in autos if a["frame_ms"]["vs_baseline"] <= t + NOISE]
        if not cheaper:
            out.append(f"| `{name}` | none at or below {t + NOISE:.2f}× | | |")
            continue
        a = max(cheaper, key=lambda c: c["frame_ms"]["vs_baseline"])
        ea, eb = a["error"], b["error"]
        pop = f"{figure(ea['popping'])} against {figure(eb['popping'])} {'✓' if ea['popping'] < eb['popping'] else '✗'}"
        ja, jb = ea.get("lighting_jump"), eb.get("lighting_jump")
        if jb is None:
            jump = f"{figure(ja)} against n/a (no whole transition in its frames)"
        elif ja is None:
            jump = f"n/a (no whole transition in its frames) against {figure(jb)}"
        else:
            jump = f"{figure(ja)} against {figure(jb)} {'✓' if ja < jb else '✗'}"
        out.append(f"| `{name}` | {a['name']} ({a['frame_ms']['vs_baseline']:.2f}×) | {pop} | {jump} |")
    return out + [""]


def write_page():
    runs = []
    for name in sorted(os.listdir(KEPT)):
        if name.endswith(".json"):
            with open(os.path.join(KEPT, name)) as f:
                runs.append(json.load(f))
    order = {"default": 0, "forest": 1, "landscape": 2, "time_of_day": 3}
    runs.sort(key=lambda k: order.get(k["bench"]["scenario"], 9))
    lines = ["# The auto ladder against the engine baseline", "",
             "Written by `docs/ladder_verdict.py` from `sylva bench` outputs; nothing here is edited by hand. "
             "Errors against each scenario's 3×3 supersampled full-geometry reference; times as ratios to "
             "`baseline` within one run. What the figures mean: "
             "[the ladder](../representations/ladder.md#against-the-engine-baseline).", ""]
    for kept in runs:
        lines += scenario_section(kept)
    with open(PAGE, "w") as f:
        f.write("\n".join(lines))


def main(argv):
    if argv[1:] == ["--kept"]:
        write_page()
        return 0
    args, runs = {}, []
    i = 1
    while i < len(argv):
        if argv[i] in ("--commit", "--date", "--command") and i + 1 < len(argv):
            args[argv[i][2:]] = argv[i + 1]
            i += 2
        else:
            runs.append(argv[i])
            i += 1
    if not runs or set(args) != {"commit", "date", "command"}:
        print(__doc__, file=sys.stderr)
        return 2
    os.makedirs(KEPT, exist_ok=True)
    for run in runs:
        path = os.path.join(run, "bench.json")
        try:
            with open(path) as f:
                bench = json.load(f)
        except (OSError, ValueError) as e:
            print(f"ladder_verdict: {path}: {e}", file=sys.stderr)
            return 2
        if bench.get("partial"):
            print(f"ladder_verdict: {path} is a partial run", file=sys.stderr)
            return 2
        for c in bench["configurations"]:
            c.pop("records", None)  # per-frame records: the page needs only the summaries
        command = args["command"].replace("SCENARIO", bench["scenario"])
        with open(os.path.join(KEPT, bench["scenario"] + ".json"), "w") as f:
            json.dump({"bench": bench, "meta": dict(args, command=command)}, f)
    write_page()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
