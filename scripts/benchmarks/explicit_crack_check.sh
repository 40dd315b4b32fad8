#!/bin/bash
# The explicit crack check's cost (issue 6): the impactor scene
# prm/impact_beam_2d.prm (2D, 600 us, 93720 steps), the 3D fragmenting
# plate prm/fragmenting_plate.prm (25,600 cells) and the 3D weakened bar
# of scripts/benchmarks/crack_insertion_cost.sh (64 elements along), one
# rank. Per scene the
# median of REPEAT runs of the whole run's wall time and of the TimerOutput
# sections "crack check" (the Hoffman check of every candidate face after
# every step), "internal forces" and "time steps", the crack faces at the
# end and the last row of cracks.csv's time (the same pattern before and
# after a change). Rows are appended to OUT.csv under LABEL, so that a
# baseline build and the current one go into one table.
# usage: explicit_crack_check.sh AMFRAC OUT.csv LABEL [REPEAT]
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2") label=$3 repeat=${4:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
# shellcheck source=common.sh
source "$here/scripts/benchmarks/common.sh"
[ -s "$out" ] || echo "build,scene,steps,crack_faces,last_crack_t,wall_s,crack_check_s,internal_forces_s,time_steps_s" > "$out"
# A scene of prm/ with its output, history only, in output/.
from_prm() {
  cat "$here/prm/$1.prm"
  printf 'subsection Output\n  set Directory = output\n  set Field format = none\nend\n'
}
impact_beam_2d() { from_prm impact_beam_2d; }
fragmenting_plate() { from_prm fragmenting_plate; }
bar_3d() {
  weakened_bar_3d 64 output "$here/prm/cracked_bar_2d.prm" \
    "$here/tests/app/explicit_cracked_bar.prm"
}
for scene in impact_beam_2d fragmenting_plate bar_3d; do
  "$scene" > "$work/scene.prm"
  walls="" checks="" forces="" steps_s=""
  for r in $(seq "$repeat"); do
    (cd "$work" && "$amfrac" scene.prm > log)
    walls+=" $(awk -F'|' '/Total wallclock/ {split($3, a, "s"); print a[1] + 0}' "$work/log")"
    checks+=" $(section "$work/log" "crack check")"
    forces+=" $(section "$work/log" "internal forces")"
    steps_s+=" $(section "$work/log" "time steps")"
  done
  steps=$(awk -F'|' '{gsub(/^ +| +$/, "", $2)} $2 == "crack check" {print $3 + 0; exit}' "$work/log")
  last=$(tail -1 "$work/output/cracks.csv" 2> /dev/null || echo ",,,0")
  faces=$(echo "$last" | cut -d, -f4)
  # shellcheck disable=SC2086
  echo "$label,$scene,$steps,$faces,$(echo "$last" | cut -d, -f1),$(median $walls),$(median $checks),$(median $forces),$(median $steps_s)" >> "$out"
done
rm -rf "$work"
cat "$out"
