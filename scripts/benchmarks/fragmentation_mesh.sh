#!/bin/bash
# The fragmenting plate (prm/fragmenting_plate.prm) on three meshes,
# h = 0.5, 0.25 and 0.125 mm in the plane (one element through the ply),
# for the issue 6 note and doc/benchmarks/README.md section 12: crack
# faces, insertion events, fragments at the end, the largest energy change
# of an event, the balance error, and the TimerOutput sections (crack
# check, crack insertion, internal forces) and the run time, one run each
# (Release, one rank), into doc/benchmarks/fragmentation_mesh.csv.
# usage: scripts/benchmarks/fragmentation_mesh.sh BUILD_DIR
set -eu
build=$(cd "$1" && pwd)
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
out=$root/doc/benchmarks/fragmentation_mesh.csv
echo "elements_along,h_mm,cells,crack_faces,events,fragments,max_energy_jump,balance_over_initial,check_s,insertion_s,internal_forces_s,run_s" > "$out"
section() { # the wall time of TimerOutput section $1 in log $2
  grep "^| $1 " "$2" | head -1 | awk -F'|' '{print $4}' | sed 's/s//' | awk '{print $1}'
}
for n in 40 80 160; do
  cat "$root/prm/fragmenting_plate.prm" > "$work/plate.prm"
  cat >> "$work/plate.prm" <<PRM
subsection Geometry
  set Elements along length = $n
  set Elements along width  = $n
end
subsection Output
  set Field format = none
  set Directory    = $work/out$n
end
PRM
  start=$(date +%s.%N)
  "$build/amfrac" "$work/plate.prm" > "$work/log$n" 2>&1
  end=$(date +%s.%N)
  /usr/bin/python3 - "$work/out$n" "$n" "$start" "$end" \
    "$(section 'crack check' "$work/log$n")" \
    "$(section 'crack insertion' "$work/log$n")" \
    "$(section 'internal forces' "$work/log$n")" >> "$out" <<'PY'
import csv, sys
d, n, start, end, check, insertion, forces = sys.argv[1:8]
run = float(end) - float(start)
h = list(csv.DictReader(open(d + "/history.csv")))
e = list(csv.DictReader(open(d + "/cracks.csv")))
initial = float(h[0]["kinetic_energy"])
balance = max(abs(float(r["balance_error"])) for r in h) / initial
jump = max(abs(float(r["energy_jump"])) for r in e)
n = int(n)
print(f"{n},{20 / n:g},{n * n},{h[-1]['crack_faces']},{len(e)},"
      f"{h[-1]['fragments']},{jump:.3g},{balance:.3g},{check},{insertion},"
      f"{forces},{run:.3g}")
PY
done
cat "$out"
rm -rf "$work"
