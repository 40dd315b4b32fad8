#!/bin/bash
# What the impactor's friction costs (issue 10). Two parts, one rank,
# median wall time of REPEAT runs each, friction on and off in turn:
# - static: prm/sliding_cylinder_2d.prm (pressed, then dragged) against
#   the same path without friction: wall time, Newton iterations, the
#   "impactor" section of TimerOutput;
# - explicit: prm/impact_plate_sphere.prm (60 x 60 cells, the quarter
#   plate) for its first 30 us, mu = 0.3 against mu = 0: wall time, the
#   "contact" section (the sphere's evaluation), the balance error.
# Rows: static (the cylinder) and explicit (the plate), mu 0.3 and 0.
# usage: impactor_friction.sh AMFRAC OUT.csv [REPEAT]
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2") repeat=${3:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
# shellcheck source=common.sh
source "$here/scripts/benchmarks/common.sh"
column() { # CSV NAME -> the last row's value of NAME
  awk -F, -v name="$2" 'NR == 1 {for (i = 1; i <= NF; ++i) if ($i == name) c = i}
    END {print $c}' "$1"
}
echo "scene,friction,wall_s,section_s,newton_iterations,balance_error" > "$out"
bench() { # NAME SECTION: the runs of $work/NAME_MU.prm, friction on and off in turn
  local name=$1 r mu start
  declare -A times parts
  for r in $(seq "$repeat"); do
    for mu in 0.3 0; do
      start=$(date +%s.%N)
      (cd "$work" && "$amfrac" "${name}_$mu.prm" > "log_$mu")
      times[$mu]+=" $(echo "$(date +%s.%N) $start" | awk '{print $1 - $2}')"
      parts[$mu]+=" $(section "$work/log_$mu" "$2")"
      cp "$work/output/history.csv" "$work/history_$mu.csv"
    done
  done
  for mu in 0.3 0; do
    local its
    its=$(grep -oE '[0-9]+ Newton iterations' "$work/log_$mu" | awk '{print $1}' || true)
    # shellcheck disable=SC2086
    echo "$name,$mu,$(median ${times[$mu]}),$(median ${parts[$mu]}),${its:-0},$(column "$work/history_$mu.csv" balance_error)" >> "$out"
  done
}
for mu in 0.3 0; do
  { cat "$here/prm/sliding_cylinder_2d.prm"
    printf 'subsection Impactor\n  set Friction coefficient = %s\nend\n' "$mu"
    printf 'subsection Output\n  set Directory = output\n  set Field format = none\nend\n'
  } > "$work/static_$mu.prm"
  { cat "$here/prm/impact_plate_sphere.prm"
    printf 'subsection Impactor\n  set Friction coefficient = %s\nend\n' "$mu"
    printf 'subsection Time\n  set End time = 3e-5\n  set Number of steps = 30\nend\n'
    printf 'subsection Output\n  set Directory = output\n  set Field format = none\nend\n'
  } > "$work/explicit_$mu.prm"
done
bench static impactor
bench explicit contact
rm -rf "$work"
cat "$out"
