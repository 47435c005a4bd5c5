#!/usr/bin/env python3
"""Compares a merged sharded run with one whole run (issue 25): `play` outputs (frames byte for
byte, each frame's image and state hash and counts) or `bench` outputs (every error figure,
every per-frame record but the times, every transition). Exits 1 naming what differs."""
import glob
import json
import os
import sys

TIMING = {"frame_ms", "cpu_ms", "gpu_ms", "systems", "passes", "submit_record_ms", "submit_issue_ms"}


def differences_play(whole, merged):
    out = []
    a = json.load(open(os.path.join(whole, "metrics.json")))
    b = json.load(open(os.path.join(merged, "metrics.json")))
    if len(a["frames"]) != len(b["frames"]):
        return [f"{len(a['frames'])} frames against {len(b['frames'])}"]
    for fa, fb in zip(a["frames"], b["frames"]):
        for key in fa:
            if key not in TIMING and fa[key] != fb.get(key):
                out.append(f"frame {fa['frame']}: {key} {fa[key]} against {fb.get(key)}")
    names = sorted(os.path.basename(p) for p in glob.glob(os.path.join(whole, "frame_*")))
    if names != sorted(os.path.basename(p) for p in glob.glob(os.path.join(merged, "frame_*"))):
        out.append("different frame files")
    for name in names:
        if open(os.path.join(whole, name), "rb").read() != open(os.path.join(merged, name), "rb").read():
            out.append(f"{name} differs")
    return out


def differences_bench(whole, merged):
    out = []
    a = json.load(open(os.path.join(whole, "bench.json")))
    b = json.load(open(os.path.join(merged, "bench.json")))
    names_a = [c["name"] for c in a["configurations"]]
    if names_a != [c["name"] for c in b["configurations"]]:
        return ["different configurations"]
    for ca, cb in zip(a["configurations"], b["configurations"]):
        for key in ("error", "primitives", "upload_bytes", "frames"):
            if ca[key] != cb[key]:
                out.append(f"{ca['name']}: {key} {ca[key]} against {cb[key]}")
        ra, rb = ca["records"], cb["records"]
        for fa, fb in zip(ra["frames"], rb["frames"]):
            for key in fa:
                if key not in TIMING and fa[key] != fb[key]:
                    out.append(f"{ca['name']} frame {fa['frame']}: {key} {fa[key]} against {fb[key]}")
        if ra["transitions"] != rb["transitions"] or ra["transitions_cut_off"] != rb["transitions_cut_off"]:
            out.append(f"{ca['name']}: transitions differ")
    return out


def main():
    kind, whole, merged = sys.argv[1:4]
    found = differences_play(whole, merged) if kind == "play" else differences_bench(whole, merged)
    for line in found[:20]:
        print(line)
    if found:
        print(f"{kind}: the merged shards differ from the whole run in {len(found)} places")
        return 1
    print(f"{kind}: the merged shards equal the whole run")
    return 0


if __name__ == "__main__":
    sys.exit(main())
