#!/usr/bin/env bash
# Measures the figures of docs/results/: one `sylva bench` per scenario, then
# docs/generate_results.py turns the outputs into pages. Run it on a quiet machine; it takes
# hours (the supersampled references of landscape alone take half an hour on two cores).
#
#   docs/measure_results.sh [SCENARIO ...]      default: default forest landscape meadow time_of_day
#
# Environment: ROUNDS (timing rounds, default 5), OUT (bench outputs, default out/results),
# CALIBRATION_RUNS (runs of docs/measure_calibration.py, default 5), ONLY (the configurations,
# default the lists below), FRAMES_<scenario> (its frame count, default in frames_of).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
rounds="${ROUNDS:-5}"
out="${OUT:-out/results}"
scenarios=("$@")
[ ${#scenarios[@]} -eq 0 ] && scenarios=(default forest landscape meadow time_of_day)

# What every scenario measures: each lighting family's brute force and engine baseline sweep,
# and the sweeps of each representation family against them.
normal="reference,brute_force,crossed_billboard_only,baseline_25m,baseline,baseline_100m"
normal+=",mesh_lod,mesh_lod_x0.25,mesh_lod_x0.5,mesh_lod_x2,billboard_clouds,billboard_clouds_pre_lit"
normal+=",points_lines,points_lines_d2,points_lines_d2.5,points_lines_d3,points_lines_d4"
normal+=",ladder,ladder_x0.5,ladder_x2,auto_15,auto_20,auto_30,auto_38,auto_45,auto_60,auto_75,auto_90,auto_105,auto_120,auto_150,auto_180,auto_210"
normal+=",auto_250,auto_300,auto_350,auto_420,auto_500"
normal+=",auto_gain_500,auto_gain_300,auto_gain_250,auto_gain_200,auto_gain_180,auto_gain_160,auto_gain_120,auto_gain_80,auto_gain_60,auto_gain_50"
normal+=",auto_gain_40,auto_gain_30,auto_gain_20,auto_gain_15,auto_gain_10,auto_gain_7,auto_gain_5,auto_gain_3"
sh="brute_force_sh,crossed_billboard_only_sh,baseline_25m_sh,baseline_sh,baseline_100m_sh"
sh+=",mesh_lod_sh,billboard_clouds_sh,points_lines_sh,points_lines_d2_sh"

frames_of() {  # the supersampled reference costs most where the plants are many
  local override="FRAMES_$1"
  if [ -n "${!override:-}" ]; then echo "${!override}"; return; fi
  case "$1" in
    landscape) echo 6 ;;
    forest | meadow) echo 12 ;;
    *) echo 24 ;;
  esac
}

# The pages need the plot as PNG: fail now, not after hours of benches.
command -v rsvg-convert >/dev/null ||
  { echo "measure_results: rsvg-convert not found: apt-get install librsvg2-bin" >&2; exit 1; }
./sylva build >&2
# The device's primitive costs first: the points-and-lines configurations plan with them, and
# calibration.md records how far they spread from run to run.
python3 docs/measure_calibration.py --runs "${CALIBRATION_RUNS:-5}" >&2
runs=()
for s in "${scenarios[@]}"; do
  dir="$out/$s"
  mkdir -p "$dir"
  cmd="./sylva bench $s --frames $(frames_of "$s") --timing-rounds $rounds --only ${ONLY:-$normal,$sh} --out $dir"
  echo "[measure] $cmd" >&2
  $cmd
  commit="$(git rev-parse HEAD)"
  dirty=false
  # This script's own outputs (calibration.md above, the pages of earlier scenarios) are not the code measured.
  [ -n "$(git status --porcelain --untracked-files=no -- . ':!docs/results')" ] && dirty=true
  printf '{"date": "%s", "commit": "%s", "dirty": %s, "command": "%s"}\n' \
    "$(date -u +%Y-%m-%d)" "$commit" "$dirty" "$cmd" > "$dir/meta.json"
  runs+=("$dir")
done
python3 docs/generate_results.py "${runs[@]}"
