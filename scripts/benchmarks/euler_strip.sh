#!/bin/bash
# Total Lagrangian post-buckling of the clamped strip (prm/euler_strip_2d.prm)
# against the mesh: for 25 ... 400 elements along the length (Q2, one
# element per ply), the median wall time of 3 runs, the Newton iterations,
# and the axial force N and mid-span deflection w (imperfection included)
# at the end, and N over the imperfect Euler column N_1 (1 - w0 / w) with
# N_1 = 44.24 N/mm (Engesser, clamped). One rank, Release build. Also writes
# the history of the 100-element run (the shipped scene) and of a
# small-strain run of the same scene (linear: no bifurcation) next to
# OUT.csv for the plot.
# usage: euler_strip.sh AMFRAC OUT.csv
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2")
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
cd "$work"
echo "elements,unknowns,steps,newton_iterations,wall_s_median,N_end,w_end,imperfect_column_ratio" > "$out"
for n in 25 50 100 200 400; do
  cat "$here/prm/euler_strip_2d.prm" > s$n.prm
  printf 'subsection Geometry\n set Elements along length = %s\nend\nsubsection Output\n set Field format = none\n set Directory = out%s\nend\n' "$n" "$n" >> s$n.prm
  times=()
  for r in 1 2 3; do
    start=$(date +%s.%N)
    "$amfrac" s$n.prm > s$n.log
    end=$(date +%s.%N)
    times+=("$(echo "$end - $start" | bc)")
  done
  median=$(printf '%s\n' "${times[@]}" | sort -g | sed -n 2p)
  unknowns=$(grep -o "[0-9]* unknowns" s$n.log | head -1 | cut -d' ' -f1)
  steps=$(grep -o "^  [0-9]* steps, [0-9]* Newton" s$n.log | awk '{print $1, $3}')
  /usr/bin/python3 - "$n" "$unknowns" "$steps" "$median" "out$n/history.csv" >> "$out" <<'PY'
import csv, sys
n, unknowns, steps, median, path = sys.argv[1:]
rows = list(csv.DictReader(open(path)))
N = -float(rows[-1]["reaction_x+_x"])
w = 0.01 + float(rows[-1]["p0_uy"])
ratio = N / (44.24 * (1 - 0.01 / w))
s, its = steps.split()
print(f"{n},{unknowns},{s},{its},{median},{N:.6f},{w:.6f},{ratio:.5f}")
PY
done
cp out100/history.csv "${out%.csv}_history.csv"
cat "$here/prm/euler_strip_2d.prm" > small.prm
printf 'set Kinematics = small strain\nsubsection Output\n set Field format = none\n set Directory = small\nend\n' >> small.prm
"$amfrac" small.prm > small.log
cp small/history.csv "${out%.csv}_small_strain.csv"
cat "$out"
rm -rf "$work"
