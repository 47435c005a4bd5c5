#!/usr/bin/env bash
# Measures how well the auto ladder holds a frame time (issue 21, `--target-frame-ms` with
# representation "ladder"): `landscape` played at 480x270 for each target, the median GPU frame
# from frame 5 on against the target, and the plants' predicted cost beside it. Writes
# docs/results/budget_holding.md with the date, machine and commit.
#
#   docs/measure_budget_holding.sh [TARGET_MS ...]      default: 150 250 450
#
# Environment: OUT (play outputs, default out/budget_holding), SCENARIO (default landscape).
# Frame times are the machine's: run it on a quiet one.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
out="${OUT:-out/budget_holding}"
scenario="${SCENARIO:-landscape}"
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(150 250 450)
sylva="${SYLVA:-build/bin/sylva}"
[ -x "$sylva" ] || { echo "measure_budget_holding: $sylva not built (./sylva test builds it)" >&2; exit 1; }
for t in "${targets[@]}"; do
  echo "measure_budget_holding: $scenario at --target-frame-ms $t" >&2
  "$sylva" play "$scenario" --headless --width 480 --height 270 --representation ladder \
    --target-frame-ms "$t" --out "$out/t$t" >/dev/null
done
python3 - "$out" "$scenario" "$(git rev-parse --short HEAD)" "${targets[@]}" > docs/results/budget_holding.md <<'PY'
import json, statistics, sys, datetime
out, scenario, commit, targets = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
rows, machine = [], ""
for t in targets:
    m = json.load(open(f"{out}/t{t}/metrics.json"))
    machine = m["summary"]["machine"]
    frames = m["frames"][5:]
    gpu = statistics.median(f["gpu_ms"] for f in frames)
    predicted = statistics.median(f["predicted_plant_ms"] for f in frames)
    rows.append((float(t), gpu, predicted, min(f["gpu_ms"] for f in frames), max(f["gpu_ms"] for f in frames)))
print(f"# Holding a frame time: `{scenario}`, auto ladder under `--target-frame-ms`\n")
print(f"Measured {datetime.date.today()} on {machine}, commit {commit}, by "
      "`docs/measure_budget_holding.sh`. 480x270, the scenario's camera path; frames 5 on.\n")
print("| target ms | median GPU ms | median / target | min–max GPU ms | median predicted plant ms |")
print("|---:|---:|---:|---:|---:|")
for t, gpu, predicted, lo, hi in rows:
    print(f"| {t:g} | {gpu:.1f} | {gpu / t:.3f} | {lo:.0f}–{hi:.0f} | {predicted:.1f} |")
print("\nThe predicted plant cost is the shader work the rung tables counted for each plant's rung, "
      "at the device calibration's cost per vertex and fragment (lod/shader_work_costs.h; process CPU "
      "time); the controller uses only the ratio of measured frames to the target, so the two need "
      "not agree (systems/adapt_plant_budget_system.h).")
PY
echo "measure_budget_holding: wrote docs/results/budget_holding.md" >&2
