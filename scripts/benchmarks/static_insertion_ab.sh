#!/bin/bash
# Static crack insertion, two builds interleaved (issue 6): the 3D weakened
# bar of crack_insertion_cost.sh (4 x 4 elements across, 16, 64 and 256
# along; the same 16 faces crack in 16 rounds) run by the build BASE and
# then by NEW, REPEAT times, one rank. One row per run: the label (BASE's
# LABEL or "new"), the elements along, the whole run's wall time, the
# TimerOutput sections "crack insertion" (which holds the Newton set-up
# after each round), "setup Newton" (all 17 set-ups) and "linear solve",
# and the number of insertion rounds. Interleaving keeps a drifting
# machine's speed out of the comparison; the medians go into the note.
# usage: static_insertion_ab.sh BASE LABEL NEW OUT.csv [REPEAT]
set -euo pipefail
base=$(realpath "$1") label=$2 new=$(realpath "$3") out=$(realpath -m "$4")
repeat=${5:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
# shellcheck source=common.sh
source "$here/scripts/benchmarks/common.sh"
echo "build,elements_along_length,run_s,insertion_s,setup_newton_s,linear_solve_s,insertion_rounds" > "$out"
for _ in $(seq "$repeat"); do
  for n in 16 64 256; do
    weakened_bar_3d "$n" "$work/out" "$here/prm/cracked_bar_2d.prm" > "$work/bar.prm"
    for build in "$label:$base" "new:$new"; do
      "${build#*:}" "$work/bar.prm" > "$work/log"
      wall=$(awk -F'|' '/Total wallclock/ {split($3, a, "s"); print a[1] + 0}' "$work/log")
      echo "${build%%:*},$n,$wall,$(section "$work/log" "crack insertion"),$(section "$work/log" "setup Newton"),$(section "$work/log" "linear solve"),$(grep -c "face(s) cracked" "$work/log")" >> "$out"
    done
  done
done
rm -rf "$work"
cat "$out"
