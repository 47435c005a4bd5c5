#!/usr/bin/env python3
"""Turns `sylva bench` outputs into the results pages of docs/results/.

Usage: docs/generate_results.py RUN_DIR [RUN_DIR ...]
       docs/generate_results.py --kept

Each RUN_DIR holds one scenario's bench.json and bench.svg (as `sylva bench --out RUN_DIR`
writes them) and the meta.json that docs/measure_results.sh writes beside them (date, commit,
command). For each it keeps docs/results/<scenario>.json (bench.json and meta.json together)
and docs/results/<scenario>.svg, and writes docs/results/<scenario>.md and the plot as
docs/results/<scenario>.png. `--kept` takes no run: it writes every page again from the kept
<scenario>.json and .svg files (after a change to this script, with the same figures).

Then, from every kept scenario, it writes docs/results/README.md (the index) and one page per
representation (mesh_levels.md, points_lines.md, billboard_clouds.md, sh_lighting.md: that
representation's rows of every scenario beside the engine baseline's), which the pages of
docs/representations/ link to. Nothing here is edited by hand: a figure changes when a bench is
run again. Every page names the date, machine and commit its figures were measured on.

The PNG plot needs rsvg-convert (Debian package librsvg2-bin); pngquant (package pngquant), when
installed, makes it a third of the size.
"""
import json
import math
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")


def fmt(v, digits):
    if v is None:
        return "n/a"
    if isinstance(v, str):
        return "∞" if v == "inf" else v
    if isinstance(v, float) and (math.isnan(v) or math.isinf(v)):
        return "n/a"
    return f"{v:.{digits}f}"


def ms(v):
    if v is None:
        return "n/a"
    return f"{v:.2f}" if v < 10 else f"{v:.1f}" if v < 100 else f"{v:.0f}"


def family_table(report, lighting):
    rows = [c for c in report["configurations"] if c["lighting"] == lighting]
    rows.sort(key=lambda c: c["frame_ms"]["median"])
    out = [
        "| configuration | median ms | × baseline | SSIM | FLIP | PSNR dB | coverage IoU | popping | "
        "lighting jump | transitions | Pareto (FLIP) |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|",
    ]
    for c in rows:
        e = c["error"]
        ratio = c["frame_ms"]["vs_baseline"]
        out.append(
            f"| `{c['name']}` | {ms(c['frame_ms']['median'])} | {fmt(ratio, 2)} | {fmt(e['ssim'], 4)} | "
            f"{fmt(e['perceptual'], 4)} | {fmt(e['psnr'], 1)} | {fmt(e['coverage_iou'], 4)} | "
            f"{fmt(e['popping'], 2)} | {fmt(e['lighting_jump'], 2)} | {e['transitions']['measured']} | "
            f"{'★' if c['on_pareto_front'] else ''} |"
        )
    return "\n".join(out)


def verdict_table(report, lighting):
    verdicts = [v for v in report.get("verdicts", []) if v["lighting"] == lighting]
    if not verdicts:
        return ""
    points = [p["baseline"] for p in verdicts[0]["points"]]
    out = ["| sweep | " + " | ".join(f"`{p}`" for p in points) + " | beats every point? |",
           "|---|" + "---|" * len(points) + "---|"]
    for v in verdicts:
        cells = []
        for p in v["points"]:
            if p["beaten_by"]:
                cells.append(f"✓ `{p['beaten_by']}` ({p['time_ratio']:.2f}×)")
            else:
                cells.append("✗ " + p["why_not"])
        out.append(f"| {v['family']} ({len(v['configurations'])}) | " + " | ".join(cells) +
                   f" | {'yes' if v['beats_every_baseline_point'] else 'no'} |")
    return "\n".join(out)


def page(report, meta):
    name = report["scenario"]
    lines = [
        f"# Results: {name}",
        "",
        f"Measured {meta['date']} at commit `{meta['commit']}`{' (with uncommitted changes)' if meta.get('dirty') else ''} "
        f"on {report['machine']}, {report['gl_renderer']}, {report['threads']} threads. "
        f"{report['frames']} frames of `{name}` at {report['width']}×{report['height']}; each configuration against "
        f"the {report['reference']['samples_per_pixel']} spp full-geometry reference lit as it is; "
        f"{report['timing_rounds']} timing rounds (frame times are medians over every round's frames, ratios "
        "the median of the round-by-round ratios).",
        "",
        "Reproduce:",
        "",
        "```",
        meta["command"],
        "```",
        "",
        "How to read these tables: [measuring](../measuring.md). Errors never cross a lighting family: each "
        "is measured against its own reference.",
        "",
    ]
    for family in report["lighting_families"]:
        lighting = family["name"]
        lines += [
            f"## Lighting: {lighting}",
            "",
            f"Reference: full geometry, {family['reference_lit']} "
            f"({ms(family['reference_frame_ms_median'])} ms a frame).",
            "",
            family_table(report, lighting),
            "",
        ]
        verdict = verdict_table(report, lighting)
        if verdict:
            lines += ["Does each sweep beat the engine baseline's sweep (time ratio ≤ 1, SSIM ≥, FLIP ≤)?", "",
                      verdict, ""]
    lines += [f"![frame time against error, {name}]({name}.png)", "",
              f"The same plot as [SVG]({name}.svg).", ""]
    return "\n".join(lines)


def measured_on(report, meta):
    """Date, machine and commit of one scenario's figures, as every page states them."""
    dirty = " (with uncommitted changes)" if meta.get("dirty") else ""
    return (f"{meta['date']}, {report['machine']}, {report['gl_renderer']}, commit "
            f"`{meta['commit'][:9]}`{dirty}")


def index(pages):
    lines = ["# Results", "",
             "One page per scenario, generated by `docs/generate_results.py` from `sylva bench` runs "
             "(`docs/measure_results.sh` makes them). Do not edit them by hand.", "",
             "| scenario | measured | machine | commit | verdicts (normal lighting / SH) |",
             "|---|---|---|---|---|"]
    for name, report, meta in sorted(pages, key=lambda p: p[0]):
        summary = []
        for lighting in ("normal", "sh"):
            vs = [v for v in report.get("verdicts", []) if v["lighting"] == lighting]
            if vs:
                won = [v["family"] for v in vs if v["beats_every_baseline_point"]]
                summary.append(f"{lighting}: " + (", ".join(won) + " beat the baseline" if won else "none beats the baseline"))
        lines.append(f"| [{name}]({name}.md) | {meta['date']} | {report['machine']}, {report['gl_renderer']} | "
                     f"`{meta['commit'][:9]}` | {'; '.join(summary)} |")
    lines += ["", "Per representation, every scenario's rows beside the engine baseline's:"]
    for file, (title, _, _) in REPRESENTATION_PAGES.items():
        lines.append(f"- [{title}]({file}.md)")
    for file, text, script in MEASURED_PAGES:
        if os.path.exists(os.path.join(RESULTS, file)):
            lines += ["", f"{text}: [{file}]({file}) (`{script}`)."]
    return "\n".join(lines) + "\n"


# Pages other scripts write, linked from the index when present: file, what it shows, script.
MEASURED_PAGES = [
    ("calibration.md", "The device calibration's run-to-run spread", "docs/measure_calibration.py"),
    ("budget_holding.md", "How closely the auto ladder holds a frame time", "docs/measure_budget_holding.sh"),
    ("ladder_verdict.md", "The auto ladder against each point of the engine baseline's sweep on `default`, `forest` "
     "and `landscape` (5 timing rounds)", "docs/ladder_verdict.py"),
    ("lodf.md", "LoDF (Rebollo 2006): bytes and time per change, storage, quality at equal leaf count",
     "docs/measure_lodf.py"),
    ("lodf_popping.md", "LoDF's popping along `single_tree`'s and `forest`'s paths against the mesh levels at equal "
     "time", "docs/measure_lodf_popping.py"),
    ("implicit_lighting.md", "Implicit-surface illumination (Luft 2007): occlusion ranks, crown noise, run time, "
     "the bake", "docs/measure_implicit.py"),
    ("shells.md", "Shells (Behrendt 2005 §3): the far field against crossed billboards, clouds and points at 5°, 10° "
     "and 20° above the canopy, plant-count independence, memory", "docs/measure_shells.py"),
    ("shards.md", "Sharded runs (issue 25): shards of `play` and `bench` against whole runs, and what a shard of the "
     "landscape reference costs beyond its frames", "docs/measure_shards.py"),
]

# One page per representation: its title, the bench families it shows and the lightings.
REPRESENTATION_PAGES = {
    "mesh_levels": ("Mesh levels", ("mesh_lod",), ("normal", "sh")),
    "points_lines": ("Points and lines (Deussen 2002)", ("points_lines",), ("normal", "sh")),
    "billboard_clouds": ("Billboard clouds (Behrendt 2005 §2)", ("billboard_clouds",), ("normal", "sh")),
    "sh_lighting": ("SH radiance transfer lighting (Behrendt 2005 §4)",
                    ("mesh_lod", "billboard_clouds", "points_lines"), ("sh",)),
}


def representation_rows(report, families, lighting):
    """The rows of `families` lit by `lighting`, after the engine baseline's sweep."""
    rows = [c for c in report["configurations"] if c["lighting"] == lighting and c["family"] == "baseline"]
    rows.sort(key=lambda c: c["frame_ms"]["median"])
    for family in families:
        mine = [c for c in report["configurations"] if c["lighting"] == lighting and c["family"] == family]
        rows += sorted(mine, key=lambda c: c["frame_ms"]["median"])
    return rows


def normal_twin(report, config):
    """The normal-lit configuration an SH configuration is the twin of (same name without _sh)."""
    name = config["name"][:-3] if config["name"].endswith("_sh") else None
    return next((c for c in report["configurations"] if c["name"] == name and c["lighting"] == "normal"), None)


def representation_page(file, pages):
    title, families, lightings = REPRESENTATION_PAGES[file]
    lines = [f"# Results: {title}", "",
             "Generated by `docs/generate_results.py` from the scenario pages' bench runs; do not edit by "
             "hand. Each table is one scenario and one lighting family: the engine baseline's sweep "
             "first (`crossed_billboard_only`, `baseline_25m`, `baseline`, `baseline_100m`), then this "
             "representation's configurations. Errors are against that family's own reference and "
             "never compare across tables; how to read them: [measuring](../measuring.md).", ""]
    if file == "sh_lighting":
        lines += ["`× normal` is the SH configuration's median frame time over its normal-lit twin's "
                  "(the same configuration without `_sh`) in the same run: what the transfer costs. "
                  "Times compare across lighting families; errors do not.", ""]
    for name, report, meta in sorted(pages, key=lambda p: p[0]):
        for lighting in lightings:
            rows = representation_rows(report, families, lighting)
            if not any(c["family"] in families for c in rows):
                continue
            lines += [f"## {name}, {lighting} lighting", "",
                      f"Measured {measured_on(report, meta)}; {report['frames']} frames at "
                      f"{report['width']}×{report['height']}, {report['timing_rounds']} timing rounds. "
                      f"All of this scenario's figures: [{name}.md]({name}.md).", ""]
            twin = file == "sh_lighting"
            lines += ["| configuration | median ms | × baseline | " + ("× normal | " if twin else "") +
                      "SSIM | FLIP | PSNR dB | coverage IoU | popping | lighting jump | triangles | points | lines |",
                      "|---|---:|---:|" + ("---:|" if twin else "") + "---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
            for c in rows:
                e, prim = c["error"], c["primitives"]
                cell = ""
                if twin:
                    normal = normal_twin(report, c)
                    cell = (fmt(c["frame_ms"]["median"] / normal["frame_ms"]["median"], 2) if normal else "n/a") + " | "
                lines.append(
                    f"| `{c['name']}` | {ms(c['frame_ms']['median'])} | {fmt(c['frame_ms']['vs_baseline'], 2)} | "
                    f"{cell}{fmt(e['ssim'], 4)} | {fmt(e['perceptual'], 4)} | {fmt(e['psnr'], 1)} | "
                    f"{fmt(e['coverage_iou'], 4)} | {fmt(e['popping'], 2)} | {fmt(e['lighting_jump'], 2)} | "
                    f"{count(prim.get('triangles'))} | {count(prim.get('points'))} | {count(prim.get('lines'))} |")
            lines.append("")
    return "\n".join(lines)


def count(v):
    """A primitive count per frame (a median over frames) in thousands or millions."""
    if v is None:
        return "n/a"
    if v >= 1e6:
        return f"{v / 1e6:.2f} M"
    if v >= 1e3:
        return f"{v / 1e3:.0f} k"
    return f"{v:.0f}"


def svg_to_png(svg, png):
    """The plot as PNG beside the SVG, for viewers that do not show SVG."""
    if shutil.which("rsvg-convert") is None:
        sys.exit("generate_results: rsvg-convert not found; install the Debian package librsvg2-bin")
    subprocess.run(["rsvg-convert", "--format", "png", "--width", "1200", "--background-color", "white",
                    "--output", png, svg], check=True)
    # Line art on white: a 256-colour palette loses nothing visible and a third of the bytes.
    if shutil.which("pngquant"):
        subprocess.run(["pngquant", "--quality", "80-100", "--speed", "1", "--strip", "--force",
                        "--output", png, png], check=True)


def write_scenario(report, meta):
    name = report["scenario"]
    with open(os.path.join(RESULTS, name + ".md"), "w") as f:
        f.write(page(report, meta))
    svg_to_png(os.path.join(RESULTS, name + ".svg"), os.path.join(RESULTS, name + ".png"))
    print(f"wrote docs/results/{name}.md and {name}.png")


def kept_pages():
    pages = []
    for entry in sorted(os.listdir(RESULTS)):
        if entry.endswith(".json"):
            with open(os.path.join(RESULTS, entry)) as f:
                kept = json.load(f)
            pages.append((kept["bench"]["scenario"], kept["bench"], kept["meta"]))
    return pages


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    os.makedirs(RESULTS, exist_ok=True)
    if argv[1:] == ["--kept"]:
        for _, report, meta in kept_pages():
            write_scenario(report, meta)
    else:
        for run in argv[1:]:
            with open(os.path.join(run, "bench.json")) as f:
                report = json.load(f)
            with open(os.path.join(run, "meta.json")) as f:
                meta = json.load(f)
            name = report["scenario"]
            shutil.copyfile(os.path.join(run, "bench.svg"), os.path.join(RESULTS, name + ".svg"))
            # The per-frame records (megabytes) stay in RUN_DIR/bench.json; the pages need the
            # configurations' summaries only.
            for c in report.get("configurations", []):
                c.pop("records", None)
            with open(os.path.join(RESULTS, name + ".json"), "w") as f:
                json.dump({"meta": meta, "bench": report}, f, indent=1)
            write_scenario(report, meta)
    pages = kept_pages()
    with open(os.path.join(RESULTS, "README.md"), "w") as f:
        f.write(index(pages))
    for file in REPRESENTATION_PAGES:
        with open(os.path.join(RESULTS, file + ".md"), "w") as f:
            f.write(representation_page(file, pages))
        print(f"wrote docs/results/{file}.md")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
