#!/usr/bin/env python3
"""Measures sharded runs (issue 25) and writes docs/results/shards.md:

1. Shards equal the whole: `sylva play` of `default` (its ladder) and of `forest` with points and
   lines, whole and in 1, 2 and 4 shards (`--shard K/N`, every other shard on one thread),
   merged by `sylva merge` and compared with the whole run (frames byte for byte, every
   per-frame record but the times: tests/slurm/compare_runs.py); and `sylva bench` of `default`
   in 2 and 4 shards against the whole bench (every error figure, record and transition).
2. What a shard costs beyond its frames, on the landscape reference (3x3 samples of full
   geometry): start-up (process start to the first frame: GL, assets from the bake cache,
   renderer upload), state reconstruction (for the reference, one rendered frame: the frame
   before the shard's first), against the shard's own frames, for 2 to 16 shards of a 100-frame
   path; and, from those measured costs, the shard count beyond which the path stops getting
   faster on a cluster of N nodes. Also the reconstruction of a LOD run (the ladder), whose
   replay runs the frames' systems alone.

Usage: docs/measure_shards.py [--width 480 --height 270] [--bench-width 240 --bench-height 135]
       [--landscape-frames 100]
"""
import argparse
import datetime
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import measure_meta

ROOT = measure_meta.ROOT
SYLVA = measure_meta.SYLVA
sys.path.insert(0, os.path.join(ROOT, "tests", "slurm"))
import compare_runs  # noqa: E402


def run(cmd):
    print("[shards] " + " ".join(cmd), file=sys.stderr)
    start = time.monotonic()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.monotonic() - start


def play_equality(tmp, name, options, shard_counts):
    """Rows: shards, identical?, differences, the slowest shard's replay (ms, CPU frames, rendered)."""
    whole = os.path.join(tmp, f"{name}_whole")
    run([SYLVA, "play", *options, "--headless", "--out", whole])
    rows = []
    for n in shard_counts:
        dirs = []
        for k in range(n):
            out = os.path.join(tmp, f"{name}_{n}_{k}")
            run([SYLVA, "play", *options, "--headless", "--shard", f"{k}/{n}", "--out", out]
                + (["--threads", "1"] if k % 2 else []))
            dirs.append(out)
        merged = os.path.join(tmp, f"{name}_{n}_merged")
        run([SYLVA, "merge", *dirs, "--out", merged])
        differences = compare_runs.differences_play(whole, merged)
        summaries = [json.load(open(os.path.join(d, "metrics.json")))["summary"] for d in dirs]
        last = summaries[-1]
        frames = len(json.load(open(os.path.join(whole, "metrics.json")))["frames"])
        rows.append({"shards": n, "frames": frames, "differences": len(differences), "first": differences[:3],
                     "replay_ms": last["replay_ms"], "cpu_frames": last["replay_cpu_frames"],
                     "rendered_frames": last["replay_rendered_frames"],
                     "frame_ms": last["median_frame_ms"], "setup_ms": last["setup_ms"]})
    return rows


def bench_equality(tmp, options, shard_counts):
    whole = os.path.join(tmp, "bench_whole")
    seconds_whole = run([SYLVA, "bench", *options, "--out", whole])
    rows = []
    for n in shard_counts:
        dirs, seconds = [], []
        for k in range(n):
            out = os.path.join(tmp, f"bench_{n}_{k}")
            seconds.append(run([SYLVA, "bench", *options, "--shard", f"{k}/{n}", "--out", out]
                               + (["--threads", "1"] if k % 2 else [])))
            dirs.append(out)
        merged = os.path.join(tmp, f"bench_{n}_merged")
        run([SYLVA, "merge", *dirs, "--out", merged])
        differences = compare_runs.differences_bench(whole, merged)
        report = json.load(open(os.path.join(merged, "bench.json")))
        transitions = sum(c["error"]["transitions"]["measured"] for c in report["configurations"])
        rows.append({"shards": n, "differences": len(differences), "first": differences[:3],
                     "seconds": seconds, "seconds_whole": seconds_whole, "transitions": transitions,
                     "configurations": [c["name"] for c in report["configurations"]]})
    return rows


def shard_costs(tmp, options, frames, shard_counts, label):
    """Start-up and reconstruction of the last shard of each count, and the frame time."""
    rows = []
    for n in shard_counts:
        first = (n - 1) * (frames // n) + min(n - 1, frames % n)
        out = os.path.join(tmp, f"{label}_cost_{n}")
        wall = run([SYLVA, "play", *options, "--frames", str(frames), "--headless",
                    "--frame-range", f"{first}:{first + 1}", "--out", out])
        m = json.load(open(os.path.join(out, "metrics.json")))
        s = m["summary"]
        frame_ms = m["frames"][0]["frame_ms"]
        rows.append({"shards": n, "first": first, "wall_s": wall, "setup_ms": s["setup_ms"],
                     "replay_ms": s["replay_ms"], "cpu_frames": s["replay_cpu_frames"],
                     "rendered_frames": s["replay_rendered_frames"], "frame_ms": frame_ms})
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--width", type=int, default=480)
    parser.add_argument("--height", type=int, default=270)
    parser.add_argument("--bench-width", type=int, default=240)
    parser.add_argument("--bench-height", type=int, default=135)
    parser.add_argument("--bench-frames", type=int, default=12)
    parser.add_argument("--landscape-frames", type=int, default=100)
    args = parser.parse_args()
    size = ["--width", str(args.width), "--height", str(args.height)]
    with tempfile.TemporaryDirectory() as tmp:
        default_rows = play_equality(tmp, "default", ["default", *size], [1, 2, 4])
        forest_rows = play_equality(tmp, "forest", ["forest", "--representation", "points_lines", *size], [1, 2, 4])
        bench_options = ["default", "--frames", str(args.bench_frames), "--width", str(args.bench_width),
                         "--height", str(args.bench_height), "--only", "baseline,ladder,points_lines,auto_30"]
        bench_rows = bench_equality(tmp, bench_options, [2, 4])
        reference = shard_costs(tmp, ["landscape", "--reference", *size], args.landscape_frames, [1, 2, 4, 8, 16],
                                "reference")
        ladder = shard_costs(tmp, ["landscape", *size], args.landscape_frames, [2, 16], "ladder")
    write(args, default_rows, forest_rows, bench_rows, bench_options, reference, ladder)


def write(args, default_rows, forest_rows, bench_rows, bench_options, reference, ladder):
    frames = args.landscape_frames
    lines = [
        "# Sharded runs (issue 25)",
        "",
        f"Generated by `docs/measure_shards.py` on {datetime.date.today()} · {measure_meta.machine()} · "
        f"commit {measure_meta.commit()} · Mesa llvmpipe through OSMesa.",
        "",
        "A shard (`--frame-range A:B` or `--shard K/N`) replays the frames before its first with the",
        "frame's systems alone, renders the frame before it, and then plays its own frames;",
        "`sylva merge` joins shards and recomputes every summary from the per-frame records.",
        "",
        "## Shards equal the whole",
        "",
        f"`sylva play` at {args.width}x{args.height}, every other shard on one thread (the whole run on "
        "two); compared by `tests/slurm/compare_runs.py`: frames byte for byte and every per-frame "
        "record but the times (image and state hashes, triangles, points, lines, instances, uploads, "
        "draw calls, shadow cascades).",
        "",
        "| run | shards | frames | differences | last shard's replay | replayed frames (systems only / rendered) |",
        "|---|---:|---:|---:|---:|---:|",
    ]
    for name, rows in (("`default` (its ladder)", default_rows), ("`forest`, points and lines", forest_rows)):
        for r in rows:
            lines.append(f"| {name} | {r['shards']} | {r['frames']} | {r['differences']} | {r['replay_ms']:.0f} ms | "
                         f"{r['cpu_frames']} / {r['rendered_frames']} |")
    lines += [
        "",
        f"`sylva bench {' '.join(bench_options)}` in shards against the whole bench (every error "
        "figure, per-frame record and transition; `auto_30` replays rendering every frame, since its "
        "selection reads the last frame's ID buffer):",
        "",
        "| shards | differences | transitions measured | whole bench | slowest shard |",
        "|---:|---:|---:|---:|---:|",
    ]
    for r in bench_rows:
        lines.append(f"| {r['shards']} | {r['differences']} | {r['transitions']} | {r['seconds_whole']:.0f} s | "
                     f"{max(r['seconds']):.0f} s |")
    if any(r["differences"] for r in default_rows + forest_rows + bench_rows):
        lines += ["", "First differences: " + "; ".join(
            str(r["first"]) for r in default_rows + forest_rows + bench_rows if r["differences"])]
    f = sorted(r["frame_ms"] for r in reference)[len(reference) // 2] / 1000.0
    startup = sorted(r["wall_s"] - r["frame_ms"] / 1000.0 - r["replay_ms"] / 1000.0 for r in reference)
    o_start = startup[len(startup) // 2]
    o_replay = sorted(r["replay_ms"] for r in reference if r["shards"] > 1)
    o_replay = o_replay[len(o_replay) // 2] / 1000.0
    lines += [
        "",
        f"## What a shard costs: the landscape reference, {frames} frames",
        "",
        f"Each row is the last shard of N over a {frames}-frame path, played for its first frame alone: "
        "start-up is the process's wall time less its frames (GL, the scenario's assets from the bake "
        "cache, the renderer's upload), reconstruction is `replay_ms` (for full geometry one rendered "
        "frame, the one before the shard's first; nothing else carries over).",
        "",
        "| shards N | shard's first frame | start-up | reconstruction | one frame | shard's frames | overhead / shard's work |",
        "|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in reference:
        n = r["shards"]
        work = math.ceil(frames / n) * f
        over = r["wall_s"] - r["frame_ms"] / 1000.0
        lines.append(f"| {n} | {r['first']} | {r['wall_s'] - r['frame_ms'] / 1000.0 - r['replay_ms'] / 1000.0:.1f} s | "
                     f"{r['replay_ms'] / 1000.0:.1f} s | {r['frame_ms'] / 1000.0:.1f} s | {math.ceil(frames / n)} "
                     f"({work:.0f} s) | {over / work:.1%} |")
    lines += [
        "",
        f"On paper, from these medians (start-up s = {o_start:.1f} s, reconstruction r = {o_replay:.1f} s, "
        f"frame f = {f:.1f} s): S shards on N nodes take ⌈S/N⌉ · (s + r + ⌈{frames}/S⌉ · f), plus the "
        "merge (seconds: frames are hard-linked). Up to S = N every added shard shortens the longest "
        "task; beyond N a second wave adds a whole task's start-up and reconstruction, so the path "
        f"stops getting faster at S = N (S = {frames} when N ≥ {frames}: a shard is at least a frame).",
        "",
        "| nodes N | best S | time | speed-up over one node's whole run |",
        "|---:|---:|---:|---:|",
    ]
    one = o_start + frames * f
    for nodes in (1, 2, 4, 8, 16, 32, 64, 128):
        best = min(range(1, frames + 1), key=lambda s: math.ceil(s / nodes) * (o_start + (o_replay if s > 1 else 0)
                                                                              + math.ceil(frames / s) * f))
        t = math.ceil(best / nodes) * (o_start + (o_replay if best > 1 else 0) + math.ceil(frames / best) * f)
        lines.append(f"| {nodes} | {best} | {t / 60:.1f} min | {one / t:.1f}x |")
    lines += [
        "",
        "A LOD run reconstructs by replaying the frames' systems without rendering; the ladder on "
        "`landscape`, last shard of N:",
        "",
        "| shards N | shard's first frame | replayed frames (systems only / rendered) | reconstruction | one frame |",
        "|---:|---:|---:|---:|---:|",
    ]
    for r in ladder:
        lines.append(f"| {r['shards']} | {r['first']} | {r['cpu_frames']} / {r['rendered_frames']} | "
                     f"{r['replay_ms'] / 1000.0:.1f} s | {r['frame_ms']:.0f} ms |")
    lines += [
        "",
        "Reproduce: `docs/measure_shards.py` (the build in build/, the bake cache warm for the "
        "landscape: the first run bakes it). The Slurm path itself is tested by `./sylva test --slurm`.",
        "",
    ]
    measure_meta.write_page("shards.md", lines)


if __name__ == "__main__":
    main()
