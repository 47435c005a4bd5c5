#!/usr/bin/env python3
"""Measures Luft 2007's implicit-surface illumination (issue 22) and writes
docs/results/implicit_lighting.md:

  - how well Eq. 4's k_a ranks ray-cast ambient occlusion (`sylva implicit-ao`), on the generated
    trees and on trees imported from glTF, with every foliage triangle a generator (the default)
    and with a quarter of them (the paper's shortcut);
  - the crowns' high-frequency luma energy and mean luma, implicit-lit against normal-lit
    (`sylva implicit-look`) on single_tree, forest and default;
  - what it costs at run time: frame time of each representation lit both ways in one bench run
    with timing rounds (ratios round by round), and the lighting jump and popping across the
    ladder's transitions (`sylva bench`);
  - the bake: its time cold (broadleaf_hd, the 180k-vertex oak) and warm (a cache read), and its
    bytes on disk per species against the same species lit by its normals.

Usage: docs/measure_implicit.py [--rounds 5] [--frames 12] [--bench-scenarios single_tree,default]
                                [--model FILE.glb ...]

Imported trees: two written by `sylva plant` (broadleaf_hd seed 2, conifer seed 5) and read back,
and two made by others (tests/data/trees: Quaternius's CommonTree_1, Cesium's sample tree);
--model adds more.
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
GENERATED = ["broadleaf", "broadleaf_hd", "conifer", "shrub"]
# Trees made by other makers and tools (tests/data/trees/README.md).
OTHERS = ["tests/data/trees/quaternius_common_tree_1/CommonTree_1.gltf", "tests/data/trees/cesium_tree.glb"]
LOOK_SCENARIOS = ["single_tree", "forest", "default"]
PAIRS = ["baseline", "mesh_lod", "ladder", "points_lines"]
DEFAULT_GENERATORS = "every foliage triangle, d_v = the depth below the iso-surface (the defaults)"


def run(cmd, env=None):
    print("[implicit] " + " ".join(cmd), file=sys.stderr)
    return subprocess.run(cmd, check=True, stdout=subprocess.PIPE, text=True, env=env).stdout


def folder_bytes(path):
    total = 0
    for base, _, files in os.walk(path):
        total += sum(os.path.getsize(os.path.join(base, f)) for f in files)
    return total


def bake_costs(tmp):
    """single_tree's oak baked into fresh caches lit by its normals and lit implicitly: bytes per
    cache kind, and the implicit bake's warm (cached) time."""
    with open(os.path.join(ROOT, "scenarios", "single_tree.json")) as f:
        base = json.load(f)
    out = {}
    for lighting in ["normal_mapped", "implicit"]:
        s = json.loads(json.dumps(base))
        s.setdefault("lod", {})["lighting"] = lighting
        path = os.path.join(tmp, f"oak_{lighting}.json")
        with open(path, "w") as f:
            json.dump(s, f)
        cache = os.path.join(tmp, "cache_" + lighting)
        env = dict(os.environ, SYLVA_CACHE_DIR=cache)
        # `play` bakes what the scenario's ladder reaches; one frame is enough.
        run([SYLVA, "play", path, "--frames", "1", "--width", "160", "--height", "90", "--out",
             os.path.join(tmp, "play_" + lighting)], env)
        kinds = {k: folder_bytes(os.path.join(cache, k)) for k in sorted(os.listdir(cache))
                 if os.path.isdir(os.path.join(cache, k))}
        out[lighting] = kinds
    return out


def ratio_by_rounds(a, b):
    """Median over timing rounds of a's round median over b's."""
    ra, rb = a["frame_ms"]["round_medians"], b["frame_ms"]["round_medians"]
    return statistics.median(x / y for x, y in zip(ra, rb))


def fmt(x, digits=3):
    return "n/a" if x is None else f"{x:.{digits}f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--frames", type=int, default=12)
    parser.add_argument("--rays", type=int, default=256)
    parser.add_argument("--bench-scenarios", default="single_tree,default")
    parser.add_argument("--model", action="append", default=[], help="an imported tree (.glb/.gltf)")
    args = parser.parse_args()
    bench_scenarios = [s for s in args.bench_scenarios.split(",") if s]
    only = ",".join(p + suffix for p in PAIRS for suffix in ["", "_implicit"])
    with tempfile.TemporaryDirectory() as tmp:
        models = GENERATED + measure_meta.export_imported(tmp, run)
        models += [os.path.join(ROOT, m) for m in OTHERS] + [os.path.abspath(m) for m in args.model]
        ao = {}
        for label, extra in [(DEFAULT_GENERATORS, []),
                             ("every foliage triangle, d_v = F(v) (the paper's input to Eq. 4)", ["--ambient-from", "density"]),
                             ("a quarter of the foliage triangles (§3.1's shortcut), d_v = depth", ["--generator-fraction", "0.25"])]:
            out = os.path.join(tmp, "ao.json")
            run([SYLVA, "implicit-ao", *models, "--rays", str(args.rays), "--json", out, *extra])
            with open(out) as f:
                ao[label] = json.load(f)
        look_json = os.path.join(tmp, "look.json")
        run([SYLVA, "implicit-look", *LOOK_SCENARIOS, "--frames", str(args.frames), "--json", look_json])
        with open(look_json) as f:
            look = json.load(f)
        benches = {}
        for s in bench_scenarios:
            folder = os.path.join(tmp, "bench_" + s)
            run([SYLVA, "bench", s, "--frames", str(args.frames), "--width", "480", "--height", "270",
                 "--timing-rounds", str(args.rounds), "--only", only, "--out", folder])
            with open(os.path.join(folder, "bench.json")) as f:
                benches[s] = json.load(f)
        # The pair whose shading differs most (every fragment through shade_implicit), timed again
        # with three times the rounds: how much of a ratio's distance from 1 is the machine.
        tight = os.path.join(tmp, "tight")
        run([SYLVA, "bench", "single_tree", "--frames", str(args.frames), "--width", "480", "--height", "270",
             "--timing-rounds", str(3 * args.rounds), "--only", "mesh_lod,mesh_lod_implicit", "--out", tight])
        with open(os.path.join(tight, "bench.json")) as f:
            tight_bench = json.load(f)
        # The ladder's transitions over a longer walk: 12 frames of default cross only a few.
        walk = os.path.join(tmp, "walk")
        run([SYLVA, "bench", "default", "--frames", str(4 * args.frames), "--width", "480", "--height", "270",
             "--only", "ladder,ladder_implicit", "--out", walk])
        with open(os.path.join(walk, "bench.json")) as f:
            walk_bench = json.load(f)
        costs = bake_costs(tmp)

    page = [
        "# Results: implicit-surface foliage illumination (Luft 2007)",
        "",
        f"Measured {datetime.date.today().isoformat()} at commit `{measure_meta.commit()}` on {measure_meta.machine()}. "
        f"Reproduce: `docs/measure_implicit.py --rounds {args.rounds} --frames {args.frames} --rays {args.rays} "
        f"--bench-scenarios {','.join(bench_scenarios)}"
        + "".join(f" --model {os.path.basename(m)}" for m in args.model) + "`. "
        "oak_hd and spruce are broadleaf_hd (seed 2) and conifer (seed 5) written as glTF by `sylva plant` and "
        "imported back; CommonTree_1 (Quaternius, Blender) and cesium_tree (Cesium, COLLADA2GLTF) are other "
        "makers' trees ([tests/data/trees](../../tests/data/trees/README.md)). How it works: [representations/implicit_lighting.md](../representations/implicit_lighting.md).",
        "",
        "## Ambient against ray-cast occlusion",
        "",
        f"Per vertex of the full mesh, the Spearman rank correlation of Eq. 4's k_a with ambient occlusion "
        f"ray-cast with Embree ({args.rays} cosine-weighted rays, a leaf's two sides averaged; `sylva implicit-ao`), "
        "beside the naive method the paper rejects (depth in the foliage's bounding ellipsoid). Eq. 4 maps d_v "
        "to k_a: by default d_v is the vertex's depth below the iso-surface; the paper's d_v = F(v) is measured "
        "beside it. −d_v is d_v itself, unclamped: what any Eq. 4 mapping (k_a,min, d_min, n) could reach for "
        "that ρ and τ. Neighbours ranks each leaf vertex by the mean occlusion of the other leaves' vertices "
        "within ρ/4: how far a smooth function of position could go. Bark is the share of the vertices that are "
        "trunk and branches, whose occlusion depends on which way their normal faces (one hemisphere, not a "
        "leaf's two): no field of position ranks it well. Target: ≥ 0.7 on each model, and above the ellipsoid.",
        "",
    ]
    for label, rows in ao.items():
        page += [f"Generators: {label}.", "",
                 "| model | vertices | bark | k_a | ellipsoid | −d_v (bound) | leaves only | neighbours | at k_a,min | ρ m | bake s | ≥ 0.7 |",
                 "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|"]
        for r in rows:
            page.append(f"| {r['model']} | {r['vertices']} | {100 * r['bark_share']:.0f} % | {r['spearman_implicit']:.3f} | "
                        f"{r['spearman_ellipsoid']:.3f} | {r['spearman_unclamped']:.3f} | {r['spearman_foliage']:.3f} | {r['spearman_neighbours']:.3f} | "
                        f"{100 * r['ka_min_share']:.1f} % | {r['rho_m']:.2f} | {r['bake_s']:.2f} | "
                        f"{'yes' if r['spearman_implicit'] >= 0.7 else 'no'} |")
        page.append("")
    page += [
        "## Less noise, same shape",
        "",
        f"{args.frames} frames of each scenario's walk at 480×270, lit by the species' normals and by the implicit "
        "surface with the same camera and ladder (`sylva implicit-look`). Crown pixels: plant in both frames (ID "
        "buffer) with a 5×5 neighbourhood all plant, so silhouettes never count. Targets: the variance of a luma "
        "Laplacian at least 40 % lower, mean luma within 10 %.",
        "",
        "| scenario | crown pixels | Laplacian variance, normal | implicit | change | mean luma, normal | implicit | change |",
        "|---|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in look:
        if r["crown_pixels"] == 0:
            page.append(f"| {r['scenario']} | 0 | n/a | n/a | n/a | n/a | n/a | n/a |")
            continue
        page.append(f"| {r['scenario']} | {r['crown_pixels']} | {r['laplacian_variance_normal']:.1f} | "
                    f"{r['laplacian_variance_implicit']:.1f} | {r['laplacian_variance_change_percent']:+.1f} % | "
                    f"{r['mean_luma_normal']:.1f} | {r['mean_luma_implicit']:.1f} | "
                    f"{r['mean_luma_change_percent']:+.1f} % |")
    page += [
        "",
        "## Free at run time",
        "",
        "The vertex format does not grow (k_a is the normal's length; `static_assert(sizeof(vertex) == 32)` in "
        "`models/mesh.h`). Each representation lit both ways in one `sylva bench` run at 480×270 "
        f"({args.frames} frames, {args.rounds} timing rounds): the implicit-lit time over the normal-lit one, the "
        "median of the round-by-round ratios. Errors are each against its own family's reference (so they are "
        "not compared here); the lighting jump and popping are measured over the path's transitions (n/a: no "
        "transition measured on that path). Target: no more than 3 % slower. The rounds' spread (slowest over "
        "fastest round median of the normal-lit row) says how noisy the shared machine was.",
        "",
    ]
    for s, b in benches.items():
        bench = b["bench"] if "bench" in b else b
        by_name = {c["name"]: c for c in bench["configurations"]}
        page += [f"`{s}` (`sylva bench {s} --frames {args.frames} --width 480 --height 270 --timing-rounds "
                 f"{args.rounds} --only {only}`):", "",
                 "| representation | normal ms | implicit ms | time ratio | ≤ 1.03 | normal's rounds spread | lighting jump normal | implicit | popping normal | implicit |",
                 "|---|---:|---:|---:|:---:|---:|---:|---:|---:|---:|"]
        for p in PAIRS:
            a, b2 = by_name.get(p + "_implicit"), by_name.get(p)
            if not a or not b2:
                continue
            ratio = ratio_by_rounds(a, b2)
            rounds = b2["frame_ms"]["round_medians"]
            page.append(f"| {p} | {b2['frame_ms']['median']:.1f} | {a['frame_ms']['median']:.1f} | {ratio:.3f} | "
                        f"{'yes' if ratio <= 1.03 else 'no'} | {max(rounds) / min(rounds):.2f}× | "
                        f"{fmt(b2['error']['lighting_jump'], 2)} | "
                        f"{fmt(a['error']['lighting_jump'], 2)} | {fmt(b2['error']['popping'], 2)} | "
                        f"{fmt(a['error']['popping'], 2)} |")
        page.append("")
    tb = tight_bench.get("bench", tight_bench)
    by_name = {c["name"]: c for c in tb["configurations"]}
    ratio = ratio_by_rounds(by_name["mesh_lod_implicit"], by_name["mesh_lod"])
    rounds = sorted(x / y for x, y in zip(by_name["mesh_lod_implicit"]["frame_ms"]["round_medians"],
                                          by_name["mesh_lod"]["frame_ms"]["round_medians"]))
    page += [f"Timed again with {3 * args.rounds} rounds (`sylva bench single_tree --frames {args.frames} --width 480 "
             f"--height 270 --timing-rounds {3 * args.rounds} --only mesh_lod,mesh_lod_implicit`): mesh_lod lit "
             f"implicitly takes {ratio:.3f}× the normal-lit time (round by round {rounds[0]:.3f}–{rounds[-1]:.3f}).",
             ""]
    wb = walk_bench.get("bench", walk_bench)
    by_name = {c["name"]: c for c in wb["configurations"]}
    page += [f"The ladder over a longer walk (`sylva bench default --frames {4 * args.frames} --width 480 --height 270 "
             "--only ladder,ladder_implicit`; 12 frames cross only a few transitions):", "",
             "| lighting | transitions measured | lighting jump | popping |", "|---|---:|---:|---:|"]
    for n, label in [("ladder", "normal"), ("ladder_implicit", "implicit")]:
        e = by_name[n]["error"]
        page.append(f"| {label} | {e['transitions']['measured']} | {fmt(e['lighting_jump'], 2)} | "
                    f"{fmt(e['popping'], 2)} |")
    page.append("")
    hd = [r for r in ao[DEFAULT_GENERATORS] if r["model"] == "broadleaf_hd"]
    page += [
        "## The bake",
        "",
        (f"broadleaf_hd (the 180k-vertex oak), cold: {hd[0]['bake_s']:.2f} s for the whole implicit bake on every "
         "mesh level (`sylva implicit-ao`'s bake column; target ≤ 2 s). " if hd else "")
        + "Warm, the species' model is read from the bake cache with the rest of its entry: the bake adds no "
        "file. Bytes on disk, `single_tree`'s oak baked into fresh caches by a one-frame `sylva play` lit each "
        "way (everything its ladder reaches):",
        "",
        "| cache kind | lit by its normals | lit implicitly |",
        "|---|---:|---:|",
    ]
    kinds = sorted(set(costs["normal_mapped"]) | set(costs["implicit"]))
    for k in kinds:
        page.append(f"| {k} | {costs['normal_mapped'].get(k, 0):,} | {costs['implicit'].get(k, 0):,} |")
    page.append(f"| total | {sum(costs['normal_mapped'].values()):,} | {sum(costs['implicit'].values()):,} |")
    page.append("")
    measure_meta.write_page("implicit_lighting.md", page)


if __name__ == "__main__":
    main()
