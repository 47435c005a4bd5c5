#!/usr/bin/env bash
# Issue 25, tested for real: a single-node Slurm cluster on this machine (Debian's slurmctld,
# slurmd, slurm-client, munge; tests/slurm/single_node_cluster.sh), `sylva farm --submit` of a
# 4-shard play and a 2-shard bench of `tiny`, waited for, merged by the farm's own merge job, and
# compared with one local run of each: identical frames (bytes), per-frame image and state
# hashes, and every error figure and per-frame record of the bench.
# Usage: farm_test.sh SYLVA_BINARY. Exit 77 (CTest: skipped) when Slurm is not installed.
set -euo pipefail
sylva=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
for tool in slurmctld slurmd sbatch squeue munged python3; do
  if ! command -v "$tool" >/dev/null; then
    echo "skipped: $tool is not installed (./sylva test --slurm installs slurmctld, slurmd, slurm-client and munge)"
    exit 77
  fi
done
work=$(mktemp -d /tmp/sylva_slurm.XXXXXX)
source "$here/single_node_cluster.sh"
trap 'stop_cluster "$work/cluster"; rm -rf "$work"' EXIT
start_cluster "$work/cluster"
export SLURM_CONF="$work/cluster/slurm.conf"
export SYLVA_CACHE_DIR="$work/cache"

play_options=(--frames 8 --width 96 --height 54)
bench_options=(--frames 6 --width 64 --height 36 --only baseline,mesh_lod,points_lines)
"$sylva" farm play tiny --shards 4 --cpus-per-task 1 --out "$work/play" --submit -- "${play_options[@]}"
"$sylva" farm bench tiny --shards 2 --cpus-per-task 1 --out "$work/bench" --submit -- "${bench_options[@]}"

# The local runs while the cluster works (this machine is the cluster: they share its cores).
"$sylva" play tiny "${play_options[@]}" --headless --out "$work/local_play" >/dev/null 2>&1
"$sylva" bench tiny "${bench_options[@]}" --out "$work/local_bench" >/dev/null 2>&1

for _ in $(seq 900); do
  [ -z "$(squeue -h 2>/dev/null)" ] && break
  sleep 1
done
if [ -n "$(squeue -h)" ]; then
  echo "the farm's jobs did not finish in 15 minutes:"; squeue; exit 1
fi
for farm in play bench; do
  if [ ! -d "$work/$farm/merged" ]; then
    echo "no merged output of the $farm farm; its logs:"
    tail -n 5 "$work/$farm"/logs/*.log
    exit 1
  fi
done
python3 "$here/compare_runs.py" play "$work/local_play" "$work/play/merged"
python3 "$here/compare_runs.py" bench "$work/local_bench" "$work/bench/merged"
