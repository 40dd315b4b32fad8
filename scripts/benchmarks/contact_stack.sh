#!/bin/bash
# Run time against error of static contact between bodies (issue 10,
# prm/contact_stack_2d.prm): two unbonded plies as a cantilever under a
# pressure q, meshed with N elements along the length and N / 20 per ply
# (square cells), against a single ply of the same mesh under q / 2
# (the reference the contact must reproduce) and Timoshenko's deflection
# of one ply under q / 2 (the continuum). Per mesh: unknowns, the median
# wall time of REPEAT runs of the stack and of the single ply, Newton
# iterations and the contact's share of the stack's time (TimerOutput's
# "body contact" section), |w_stack / w_single - 1| and
# w_stack / w_Timoshenko - 1. One rank, the direct solver.
# usage: contact_stack.sh AMFRAC OUT.csv [REPEAT]
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2") repeat=${3:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
# Timoshenko, one ply (h = 1, unit width) under q / 2 = 0.005 MPa, L = 20,
# E = 70000, G = 35000, shear factor 5/6.
timoshenko=$(awk 'BEGIN {q = 0.005; L = 20; E = 70000; G = 35000;
  print q * L^4 / (8 * E / 12) + q * L^2 / (2 * 5 / 6 * G)}')
echo "elements_along_length,elements_per_ply,unknowns,stack_wall_s,single_wall_s,newton_iterations,contact_share,stack_vs_single,stack_vs_timoshenko" > "$out"
run() { # PRM -> median wall time; leaves the last log in $work/log
  local times=() r start
  for r in $(seq "$repeat"); do
    start=$(date +%s.%N)
    "$amfrac" "$1" > "$work/log"
    times+=("$(echo "$(date +%s.%N) $start" | awk '{print $1 - $2}')")
  done
  median "${times[@]}"
}
tip() { # history.csv -> the last row's p0_uy
  awk -F, 'NR == 1 {for (i = 1; i <= NF; ++i) if ($i == "p0_uy") c = i}
           END {print $c}' "$1"
}
for n in 40 80 160 320; do
  per_ply=$((n / 20))
  mesh="subsection Geometry
  set Elements along length = $n
  set Elements per ply      = $per_ply
end"
  { cat "$here/prm/contact_stack_2d.prm"; echo "$mesh"; cat <<PRM
subsection Output
  set Directory    = $work/stack
  set Field format = none
end
PRM
  } > "$work/stack.prm"
  stack_time=$(run "$work/stack.prm")
  unknowns=$(sed -n 's/.* cells, \([0-9]*\) unknowns.*/\1/p' "$work/log")
  iterations=$(sed -n 's/.* steps, \([0-9]*\) Newton iterations.*/\1/p' "$work/log")
  total=$(sed -n 's/^| Total wallclock time elapsed *| *\([0-9.e+-]*\)s.*/\1/p' "$work/log")
  contact=$(sed -n 's/^| body contact *| *[0-9]* | *\([0-9.e+-]*\)s.*/\1/p' "$work/log")
  { cat "$here/prm/contact_stack_2d.prm"; echo "$mesh"; cat <<PRM
subsection Geometry
  set Stacking sequence = [0]
end
subsection Boundary conditions
  set Function constants = q=0.005
end
subsection Contact
  set Enable              = false
  set Unbonded interfaces =
end
subsection Output
  set Point values = 20, 1
  set Directory    = $work/single
  set Field format = none
end
PRM
  } > "$work/single.prm"
  single_time=$(run "$work/single.prm")
  ws=$(tip "$work/stack/history.csv") w1=$(tip "$work/single/history.csv")
  awk -v n="$n" -v p="$per_ply" -v u="$unknowns" -v ts="$stack_time" \
      -v t1="$single_time" -v it="$iterations" -v c="$contact" -v T="$total" \
      -v ws="$ws" -v w1="$w1" -v wt="$timoshenko" 'BEGIN {
    d = ws / w1 - 1; if (d < 0) d = -d;
    printf "%d,%d,%d,%.3f,%.3f,%d,%.3f,%.2e,%.4f\n", n, p, u, ts, t1, it,
      c / T, d, -ws / wt - 1}' >> "$out"
done
rm -rf "$work"
cat "$out"
