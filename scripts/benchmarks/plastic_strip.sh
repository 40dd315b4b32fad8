#!/bin/bash
# Elastic-plastic post-buckling of the clamped [90_4] strip
# (prm/plastic_strip_2d.prm, total Lagrangian, Hoffman plasticity) against
# the mesh: for 50 ... 400 elements along the length (Q2, one element per
# ply), the median wall time of 3 runs, the Newton iterations, the end
# shortening of the first yield, and at the end the axial force N, the
# plastic work and the balance error. One rank, Release build. Also writes
# the history of the 100-element run (the shipped scene) and of the same
# scene with elastic plies next to OUT.csv for the plot.
# usage: plastic_strip.sh AMFRAC OUT.csv
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2")
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
cd "$work"
echo "elements,unknowns,steps,newton_iterations,wall_s_median,first_yield_shortening,N_end,plastic_work,external_work,balance_error" > "$out"
for n in 50 100 200 400; do
  cat "$here/prm/plastic_strip_2d.prm" > s$n.prm
  printf 'subsection Geometry\n set Elements along length = %s\nend\nsubsection Output\n set Directory = out%s\nend\n' "$n" "$n" >> s$n.prm
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
# The scene's end shortening is 4 t^2 mm.
first = next(r for r in rows if float(r["yielding_points"]) > 0)
d_yield = 4 * float(first["time"]) ** 2
last = rows[-1]
N = -float(last["reaction_x+_x"])
s, its = steps.split()
print(f"{n},{unknowns},{s},{its},{median},{d_yield:.4f},{N:.5f},"
      f"{float(last['plastic_work']):.5f},{float(last['external_work']):.5f},"
      f"{float(last['balance_error']):.3g}")
PY
done
cp out100/history.csv "${out%.csv}_history.csv"
cat "$here/prm/plastic_strip_2d.prm" > elastic.prm
printf 'subsection Materials\n set Plasticity = none\nend\nsubsection Output\n set Directory = elastic\nend\n' >> elastic.prm
"$amfrac" elastic.prm > elastic.log
cp elastic/history.csv "${out%.csv}_elastic.csv"
cat "$out"
rm -rf "$work"
