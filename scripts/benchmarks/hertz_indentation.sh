#!/bin/bash
# Run time against error for the Hertz indentation (issue 10,
# prm/hertz_indentation.prm): the contact zone refined 5 to 8 times
# (Q1), the grading 2 h or 4 h outside it, and Q2 on 5 and 6 refinements.
# Per run: cells, unknowns, the median wall time of REPEAT runs, and from
# history.csv (scripts/benchmarks/hertz_errors.py) the largest
# |F / F_Hertz - 1| over the steps, that of the first step, alpha / alpha_H
# of the fit d = alpha F^(2/3) + C F, and the error of the peak pressure
# (Penalty times the deepest penetration) against Hertz's p0 at the end.
# One rank, the direct solver.
# usage: hertz_indentation.sh AMFRAC OUT.csv [REPEAT]
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2") repeat=${3:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
echo "degree,refinements,grading,cells,dofs,wall_s,max_force_error,first_force_error,alpha_ratio,C,peak_pressure_error" > "$out"
for run in 1:5:2 1:6:2 1:7:2 1:8:2 1:7:4 2:5:2 2:6:2; do
  IFS=: read -r degree refinements grading <<< "$run"
  { cat "$here/prm/hertz_indentation.prm"; cat <<PRM
subsection Geometry
  set Refinement region  = sqrt(x^2 + y^2 + (z - 20)^2) < 0.45 + $grading*h
  set Region refinements = $refinements
end
subsection Discretization
  set Finite element degree = $degree
end
subsection Output
  set Directory    = $work/out
  set Field format = none
end
PRM
  } > "$work/run.prm"
  times=()
  for r in $(seq "$repeat"); do
    start=$(date +%s.%N)
    "$amfrac" "$work/run.prm" > "$work/log"
    times+=("$(echo "$(date +%s.%N) $start" | awk '{print $1 - $2}')")
  done
  cells=$(sed -n 's/.*plies, \([0-9]*\) cells, \([0-9]*\) unknowns.*/\1/p' "$work/log")
  dofs=$(sed -n 's/.*plies, \([0-9]*\) cells, \([0-9]*\) unknowns.*/\2/p' "$work/log")
  errors=$(/usr/bin/python3 "$here/scripts/benchmarks/hertz_errors.py" "$work/out/history.csv")
  echo "$degree,$refinements,$grading,$cells,$dofs,$(median "${times[@]}"),$errors" | tee -a "$out"
done
rm -rf "$work"
