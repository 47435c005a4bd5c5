#!/usr/bin/env python3
"""Measures the shell rung (Behrendt 2005 §3; issue 24) and writes docs/results/shells.md.

- Far field: `valley`'s Wang-tiled oaks, spruces and hazels on a flat-ish 800 m terrain, all of
  them 280 m or more from the camera, seen from 5°, 10° and 20° above the canopy. One bench per
  angle (`sylva bench`, its own reference): the shells (Eq. 2's f = 1, the paper's; 0.25; 0 =
  flat slices) against the same plants drawn one by one as crossed billboards (the ladder without
  its shell rung, and every plant as one), billboard clouds, and points and lines with eco-tile
  point sets. Frame times are compared only within one bench (timing rounds side by side).
- Far field of `landscape`: its trees and shrubs at its densities, Wang-tiled on an area 350 m and
  more from its camera, on its own hilly terrain: from its camera (about 7° down) and from 20°
  above, the same configurations; `ladder_shells_full_resolution` shows what the half-size shell
  layer costs in error and saves in time (also in the far field above).
- Plant count: the 10° view with four times the plants (spacings halved) against the base, shells
  and crossed billboards, the two played in alternation, `--rounds` times each.
- Slice merging (§3.3): the 10° view on a 150 m dolly away from the plants, where the slices of
  more and more triangles are replaced by their pyramid's merged levels: popping with the
  premultiplied pyramid and blending against the same pyramid built and blended with the
  standard equation (`ladder_shells_standard_blending`).
- SH lighting (§4 on the shells): the 10° view with every plant lit by SH transfer, under the
  valley's sun (32°) and a low one (12°): shells lit by the transfer baked into their slices
  (`ladder`) against the same shells lit by their normals (`ladder_shells_normal_lit`) and the
  ladder without shells (crossed billboards, SH-lit from their transfer pages); and under a sun
  that moves every frame (the shells then sum the transfer per fragment).
- Implicit lighting (Luft 2007 on the shells): the far field with every plant lit by the implicit
  surface: shells reading their normals' length as the plants' k_a (`ladder`) against the same
  shells reading them as plain normals (`ladder_shells_normal_lit`), the ladder without shells
  (implicit-lit crossed billboards) and billboard clouds; and the two shells on `valley`'s own walk.
- Memory: `valley` itself, with its shells and without (the ladder without the shell rung), and
  with every plant SH-lit (the shells then carry transfer pages): the shells' bytes, everything
  uploaded at start, the process's peak resident memory, frame time.

Usage: docs/measure_shells.py [--frames 3] [--timing-rounds 3] [--rounds 3] [--dolly-frames 8]
                              [--width 480 --height 270]
"""
import argparse
import copy
import datetime
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

import measure_meta

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SYLVA = os.path.join(ROOT, "build", "bin", "sylva")
ANGLES = [5, 10, 20]
SUN_ELEVATIONS = [32, 12, "moving"]
SH_CONFIGURATIONS = ["ladder", "ladder_shells_normal_lit", "ladder_no_shells"]
IMPLICIT_CONFIGURATIONS = ["ladder", "ladder_shells_normal_lit", "ladder_no_shells", "billboard_cloud_only"]
FAR_CONFIGURATIONS = ["ladder", "ladder_shells_f0.25", "ladder_shells_f0", "ladder_shells_full_resolution",
                      "ladder_no_shells", "crossed_billboard_only", "billboard_cloud_only", "points_lines",
                      "points_lines_d2"]
# Where `landscape`'s Wang-tiled far field grows: 350 m and more from its camera's first position.
LANDSCAPE_AREA = [-950, -200, 250, 950]
LANDSCAPE_VIEWS = ["own", 20]


def run(cmd):
    print("[shells] " + " ".join(cmd), file=sys.stderr)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def valley():
    with open(os.path.join(ROOT, "scenarios", "valley.json")) as f:
        return json.load(f)


def far_field(angle_deg, density=1.0):
    """`valley`'s plants at its densities on [-400, -400, 400, 100] of a flat-ish 800 m terrain,
    the camera 280 m beyond the area's edge looking at 8 m above the ground 630 m away from
    `angle_deg` above, dollying 10 m; `density` multiplies the plant counts (spacings / √density)."""
    s = valley()
    s["name"] = f"shell_far_{angle_deg}deg" + (f"_x{density:g}" if density != 1.0 else "")
    s["terrain"] = {"size_m": 800, "resolution": 129, "height_m": 4, "octaves": 3, "frequency": 0.004,
                    "seed": 5, "tiles_per_side": 4}
    area = [-400, -400, 400, 100]
    share = (area[2] - area[0]) * (area[3] - area[1]) / (1400.0 * 1400.0)
    for p in s["populations"]:
        p["area"] = area
        p["count"] = int(round(p["count"] * share * density))
        p["min_spacing_m"] = p["min_spacing_m"] / math.sqrt(density)
    y = 8 + 630 * math.tan(math.radians(angle_deg))
    s["camera"] = {"far_m": 3000, "keyframes": [
        {"t": 0.0, "position": [0, y, 380], "target": [0, 8, -250]},
        {"t": 0.5, "position": [0, y, 370], "target": [0, 8, -260]}]}
    return s


def landscape():
    with open(os.path.join(ROOT, "scenarios", "landscape.json")) as f:
        return json.load(f)


def landscape_far_field(view):
    """`landscape`'s oaks, spruces and hazels at its densities (counts scaled to the area), placed by
    Wang tiles on LANDSCAPE_AREA of its own hilly terrain (the grass dropped; a tiled population's
    plants are its tiles', so its slope, altitude and density rules go), with `valley`'s ladder ending
    in the shell rung. `view` "own": landscape's camera over the first half second of its path (about
    7° down onto the area, 350 m and more away); a number: the same target seen from that many
    degrees above, dollying 14 m."""
    s = landscape()
    s["name"] = f"shell_far_landscape_{view}" + ("deg" if view != "own" else "")
    area = LANDSCAPE_AREA
    share = (area[2] - area[0]) * (area[3] - area[1]) / float(s["terrain"]["size_m"] ** 2)
    tiled = []
    for p in s["populations"]:
        if p["species"] == "grass":
            continue
        p = {k: v for k, v in p.items() if k not in ("max_slope_deg", "min_altitude_m", "max_altitude_m", "density")}
        p.update(area=area, count=int(round(p["count"] * share)), placement="wang_tiles")
        tiled.append(p)
    s["populations"] = tiled
    s["species"] = [x for x in s["species"] if x["name"] != "grass"]
    v = valley()
    s["lod"] = v["lod"]
    s["wang_tiles"] = v["wang_tiles"]
    if view == "own":
        s["camera"]["keyframes"] = s["camera"]["keyframes"][:2]
    else:
        target = [-600, 20, 600]
        y = target[1] + math.hypot(600, 600) * math.tan(math.radians(view))
        s["camera"] = {"far_m": 6000, "keyframes": [
            {"t": 0.0, "position": [-1200, y, 1200], "target": target},
            {"t": 0.5, "position": [-1190, y, 1190], "target": [-590, 20, 590]}]}
    return s


def implicit_lit(s):
    """`s` with every plant lit by Luft 2007's implicit surface (`lod.lighting` "implicit")."""
    s = copy.deepcopy(s)
    s["name"] += "_implicit"
    s["lod"]["lighting"] = "implicit"
    return s


def sh_lit(s, elevation_deg):
    """`s` with every plant lit by SH transfer and the sun `elevation_deg` above the horizon, or,
    for "moving", sinking from 32° to 12° and swinging 40° in azimuth over the clip."""
    s = copy.deepcopy(s)
    s["name"] += f"_sh_sun{elevation_deg}"
    s["lod"]["lighting"] = "sh"
    if elevation_deg == "moving":
        end = s["camera"]["keyframes"][-1]["t"]
        s["sun"] = {"keyframes": [{"t": 0, "elevation_deg": 32, "azimuth_deg": 140},
                                  {"t": end, "elevation_deg": 12, "azimuth_deg": 180}]}
    else:
        s["sun"] = {"keyframes": [{"t": 0, "elevation_deg": elevation_deg, "azimuth_deg": 140}]}
    return s


def dolly_away(s, frames, fps=24):
    """`s` with its camera backing away 150 m over `frames` frames."""
    s = copy.deepcopy(s)
    s["name"] += "_dolly"
    end = (frames - 1) / fps
    y = s["camera"]["keyframes"][0]["position"][1]
    s["camera"]["keyframes"] = [{"t": 0.0, "position": [0, y, 380], "target": [0, 8, -250]},
                                {"t": end, "position": [0, y, 530], "target": [0, 8, -100]}]
    return s


def without_shells(s):
    s = copy.deepcopy(s)
    s["name"] += "_no_shells"
    s["lod"]["ladder"] = [r for r in s["lod"]["ladder"] if r["rung"] != "shell"]
    return s


def write(folder, s):
    path = os.path.join(folder, s["name"] + ".json")
    with open(path, "w") as f:
        json.dump(s, f, indent=1)
    return path


def bench(folder, path, args, configurations=FAR_CONFIGURATIONS, frames=None):
    out = os.path.join(folder, os.path.basename(path)[:-5])
    run([SYLVA, "bench", path, "--only", ",".join(configurations), "--frames", str(frames or args.frames),
         "--timing-rounds", str(args.timing_rounds), "--width", str(args.width), "--height", str(args.height),
         "--out", out])
    with open(os.path.join(out, "bench.json")) as f:
        return json.load(f)


def play(folder, path, args, frames):
    out = os.path.join(folder, "play_" + os.path.basename(path)[:-5])
    run([SYLVA, "play", path, "--frames", str(frames), "--width", str(args.width), "--height", str(args.height),
         "--out", out])
    with open(os.path.join(out, "metrics.json")) as f:
        return json.load(f)


def fmt(v, digits=3):
    return "n/a" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{v:.{digits}f}"


def far_field_table(report, configurations=FAR_CONFIGURATIONS, base="ladder_no_shells"):
    rows = {c["name"]: c for c in report["configurations"]}
    ladder_ms = rows[base]["frame_ms"]["median"]
    lines = [f"| configuration | frame ms (median) | time vs {base} | SSIM | FLIP | coverage IoU | popping |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    for name in configurations:
        c = rows.get(name)
        if not c:
            continue
        e = c["error"]
        ms = c["frame_ms"]["median"]
        lines.append(f"| `{name}` | {ms:.1f} | {ms / ladder_ms:.2f} | {fmt(e.get('ssim'))} | {fmt(e.get('perceptual'))} | "
                     f"{fmt(e.get('coverage_iou'))} | {fmt(e.get('popping'), 2)} |")
    return lines, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--timing-rounds", type=int, default=3)
    parser.add_argument("--rounds", type=int, default=3, help="alternating plays for the plant-count comparison")
    parser.add_argument("--dolly-frames", type=int, default=8, help="frames of the slice-merging dolly")
    parser.add_argument("--sh-frames", type=int, default=9,
                        help="frames of the SH-lit views (a light that holds still is summed once, at the "
                             "second frame; enough frames that the median is the steady state)")
    parser.add_argument("--walk-frames", type=int, default=12, help="frames of `valley`'s own walk, implicit-lit")
    parser.add_argument("--width", type=int, default=480)
    parser.add_argument("--height", type=int, default=270)
    args = parser.parse_args()
    page = []
    with tempfile.TemporaryDirectory() as tmp:
        far = {}
        for angle in ANGLES:
            far[angle] = bench(tmp, write(tmp, far_field(angle)), args)
        far_landscape = {view: bench(tmp, write(tmp, landscape_far_field(view)), args) for view in LANDSCAPE_VIEWS}
        sh = {e: bench(tmp, write(tmp, sh_lit(far_field(10), e)), args, SH_CONFIGURATIONS, args.sh_frames)
              for e in SUN_ELEVATIONS}
        implicit = {angle: bench(tmp, write(tmp, implicit_lit(far_field(angle))), args, IMPLICIT_CONFIGURATIONS)
                    for angle in ANGLES}
        implicit_walk = bench(tmp, write(tmp, implicit_lit(valley())), args, ["ladder", "ladder_shells_normal_lit"],
                              args.walk_frames)
        merging = bench(tmp, write(tmp, dolly_away(far_field(10), args.dolly_frames)), args,
                        ["ladder", "ladder_shells_standard_blending"], args.dolly_frames)
        # Plant count: base and four times the plants, in alternation.
        # The figure is the shell pass's own time; the frame's is beside it. The crossed
        # billboards are drawn in the opaque pass (with the terrain).
        pairs = {"shells": (far_field(10), far_field(10, 4.0), "shells"),
                 "crossed billboards": (without_shells(far_field(10)), without_shells(far_field(10, 4.0)), "opaque")}
        density = {}
        for label, (base, dense, pass_name) in pairs.items():
            paths = (write(tmp, base), write(tmp, dense))
            times = ([], [])
            pass_times = ([], [])
            plants = [0, 0]
            for _ in range(args.rounds):
                for k in (0, 1):
                    m = play(tmp, paths[k], args, args.frames)
                    times[k].append(m["summary"]["median_gpu_ms"])
                    pass_times[k].append(statistics.median(f["passes"][pass_name] for f in m["frames"]))
                    plants[k] = m["summary"]["plants"]
            # The change is the median of the round-by-round ratios (each pair played back to back), so
            # the machine's drift over the run cancels; the medians of each side are shown beside it.
            pass_ratios = sorted(d / b for b, d in zip(*pass_times))
            frame_ratios = sorted(d / b for b, d in zip(*times))
            density[label] = (statistics.median(times[0]), statistics.median(times[1]), plants, pass_name,
                              statistics.median(pass_times[0]), statistics.median(pass_times[1]),
                              pass_ratios, frame_ratios)
        # Memory: valley with and without its shells.
        memory = {}
        for label, s in (("shells", valley()), ("no shells", without_shells(valley())),
                         ("shells, SH-lit plants", sh_lit(valley(), 32))):
            memory[label] = play(tmp, write(tmp, s), args, args.frames)["summary"]

    page += [f"# Shells (Behrendt 2005 §3)", "",
             f"Generated by `docs/measure_shells.py --frames {args.frames} --timing-rounds {args.timing_rounds} "
             f"--rounds {args.rounds} --dolly-frames {args.dolly_frames} --sh-frames {args.sh_frames} "
             f"--walk-frames {args.walk_frames} --width {args.width} --height {args.height}` on "
             f"{datetime.date.today().isoformat()}, {measure_meta.machine()}, commit {measure_meta.commit()}. "
             "What the shells are and how they are drawn: [representations/shells.md](../representations/shells.md).", ""]
    page += ["## Far field", "",
             f"`valley`'s Wang-tiled plants on [-400, -400, 400, 100] of a flat-ish 800 m terrain, every one 280 m "
             f"or more from the camera, {args.width}x{args.height}, {args.frames} frames of a 10 m dolly. Errors "
             "against each angle's own reference (every plant at full geometry, 3x3 samples); times only within "
             "one angle's bench, as ratios to the ladder without its shell rung (crossed billboards beyond the "
             "band, the engine's own far rung).", ""]
    for angle in ANGLES:
        lines, _ = far_field_table(far[angle])
        page += [f"### {angle}° above the canopy", ""] + lines + [""]
    counts = ", ".join(f"{p['count']:,} {p['species']}" for p in landscape_far_field("own")["populations"])
    page += ["## Far field of `landscape`", "",
             f"`landscape`'s own hilly terrain with its trees and shrubs at its densities ({counts}), Wang-tiled "
             f"on {LANDSCAPE_AREA}, every one 350 m or more from the camera; `valley`'s ladder (shells beyond "
             f"24 px). {args.width}x{args.height}, {args.frames} frames. Sparser than `valley`'s forest: between "
             "its crowns the ground shows. `ladder_shells_full_resolution` blends the shells straight into the "
             "frame instead of the half-size layer (its plants then write no IDs: coverage n/a).", ""]
    for view in LANDSCAPE_VIEWS:
        lines, _ = far_field_table(far_landscape[view])
        title = ("`landscape`'s own camera, about 7° down onto the area" if view == "own"
                 else f"The same area from {view}° above")
        page += [f"### {title}", ""] + lines + [""]
    page += ["## SH lighting", "",
             "The 10° view with every plant lit by SH transfer (Behrendt 2005 §4; `lod.lighting` \"sh\"), "
             "against its own reference (every plant at full geometry, SH-lit). `ladder`: the shells lit by the "
             "transfer baked into their slices; `ladder_shells_normal_lit`: the same shells lit by their normals, "
             "as they were before; `ladder_no_shells`: crossed billboards, lit from their transfer pages. "
             f"{args.sh_frames} frames: under a sun that holds still the slices' sums are made once, at the "
             "second frame, and the median is the frames after.", ""]
    for elevation in SUN_ELEVATIONS:
        lines, _ = far_field_table(sh[elevation], SH_CONFIGURATIONS)
        title = ("Sun sinking from 32° to 12° over the clip (the sums per fragment)" if elevation == "moving"
                 else f"Sun {elevation}° above the horizon")
        page += [f"### {title}", ""] + lines + [""]
    page += ["## Implicit lighting (Luft 2007)", "",
             "The far field with every plant lit by the implicit surface (`lod.lighting` \"implicit\"), against "
             "its own reference (every plant at full geometry, implicit-lit). `ladder`: the shells reading their "
             "normals' length as the plants' k_a (the slices' normals are the mean of the plants' baked ones); "
             "`ladder_shells_normal_lit`: the same shells reading them as plain normals, as they were before; "
             "`ladder_no_shells`: implicit-lit crossed billboards; `billboard_cloud_only`: every plant a billboard "
             f"cloud. {args.frames} frames.", ""]
    for angle in ANGLES:
        lines, _ = far_field_table(implicit[angle], IMPLICIT_CONFIGURATIONS)
        page += [f"### {angle}° above the canopy", ""] + lines + [""]
    lines, _ = far_field_table(implicit_walk, ["ladder", "ladder_shells_normal_lit"], base="ladder")
    page += [f"### `valley`'s own walk, {args.walk_frames} frames", "",
             "The shells seen as the scenario sees them, nearer and over hills.", ""] + lines + [""]
    rows = {c["name"]: c for c in merging["configurations"]}
    page += ["## Slice merging", "",
             f"The 10° view backing away 150 m over {args.dolly_frames} frames, so the slices of more and more "
             "triangles are replaced by merged pyramid levels. Popping: frame-to-frame change beyond the "
             "reference's (lower is steadier).", "",
             "| pyramid and blending | popping | SSIM | FLIP | frame ms (median) |", "|---|---:|---:|---:|---:|"]
    for name, label in (("ladder", "premultiplied, c + F(1 - α) (§3.3)"),
                        ("ladder_shells_standard_blending", "standard, c·α + F(1 - α)")):
        c = rows[name]
        e = c["error"]
        page.append(f"| {label} | {fmt(e.get('popping'), 3)} | {fmt(e.get('ssim'))} | {fmt(e.get('perceptual'))} | "
                    f"{c['frame_ms']['median']:.1f} |")
    page += [""]
    page += ["## Plant count", "",
             f"The 10° view with four times the plants (spacings halved), {args.rounds} rounds of the two played "
             f"back to back, {args.frames} frames each (GPU ms per frame, and the GPU ms of the pass that draws them: "
             f"the shells' own, the opaque pass for the crossed billboards): the medians of each side, and the "
             f"change as the median of the round-by-round ratios with their range. Target: the shell pass within ±10 %.", "",
             "| drawn as | plants | 4x plants | pass | pass ms | 4x plants | change | rounds' range | frame ms | 4x plants | change |",
             "|---|---:|---:|---|---:|---:|---:|---|---:|---:|---:|"]
    for label, (base, dense, plants, pass_name, pass_base, pass_dense, pass_ratios, frame_ratios) in density.items():
        page.append(f"| {label} | {plants[0]:,} | {plants[1]:,} | {pass_name} | {pass_base:.1f} | {pass_dense:.1f} | "
                    f"{100 * (statistics.median(pass_ratios) - 1):+.0f} % | "
                    f"{100 * (pass_ratios[0] - 1):+.0f} to {100 * (pass_ratios[-1] - 1):+.0f} % | {base:.1f} | {dense:.1f} | "
                    f"{100 * (statistics.median(frame_ratios) - 1):+.0f} % |")
    page += ["", "## Memory (`valley`)", "",
             "| | shell bytes | uploaded at start | peak resident | median frame ms |", "|---|---:|---:|---:|---:|"]
    for label, m in memory.items():
        page.append(f"| {label} | {m['shell_bytes'] / 2**20:.1f} MiB | {m['static_upload_bytes'] / 2**20:.1f} MiB | "
                    f"{m['peak_memory_mb']:.0f} MB | {m['median_frame_ms']:.1f} |")
    out = os.path.join(ROOT, "docs", "results", "shells.md")
    with open(out, "w") as f:
        f.write("\n".join(page) + "\n")
    print(f"[shells] wrote {out}", file=sys.stderr)


if __name__ == "__main__":
    main()
