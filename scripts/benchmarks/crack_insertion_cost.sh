#!/bin/bash
# Cost of crack insertion against mesh size (issue 6 benchmark): the 3D
# weakened bar of prm/cracked_bar_2d.prm with 4 x 4 elements across and 16,
# 64, 256 along its length (meshes 1x, 4x, 16x), so that the same K = 16
# faces are inserted in each. Prints the TimerOutput sections "crack
# insertion" (release, DoF layer, interface elements, Newton state) and
# "crack check" (the Hoffman check after every step) and the whole run,
# median of REPEAT runs, into doc/benchmarks/crack_insertion_cost.csv.
# usage: scripts/benchmarks/crack_insertion_cost.sh BUILD_DIR [REPEAT]
set -eu
build=$(cd "$1" && pwd) repeat=${2:-5}
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
out=$root/doc/benchmarks/crack_insertion_cost.csv
echo "elements_along_length,cells,unknowns,faces,insertion_s,check_s,checks,run_s" > "$out"
for n in 16 64 256; do
  cat "$root/prm/cracked_bar_2d.prm" > "$work/bar.prm"
  cat >> "$work/bar.prm" <<PRM
set Dimension = 3
subsection Geometry
  set Width = 1
  set Elements along width = 4
  set Elements per ply = 4
  set Elements along length = $n
end
subsection Boundary conditions
  subsection z-
    set Type = displacement
    set Components = z
    set Displacement = 0
  end
end
subsection Output
  set Field format = none
  set Directory = $work/out
end
PRM
  # Odd n would not put a face at x = 2; the scene needs n a multiple of 2.
  ins=() chk=() run=()
  for r in $(seq "$repeat"); do
    "$build/amfrac" "$work/bar.prm" > "$work/log"
    ins+=("$(awk -F'|' '/^\| crack insertion/ {gsub(/s/,"",$4); print $4+0}' "$work/log")")
    chk+=("$(awk -F'|' '/^\| crack check/ {gsub(/s/,"",$4); print $4+0}' "$work/log")")
    run+=("$(awk -F'|' '/Total wallclock/ {gsub(/s/,"",$3); print $3+0}' "$work/log")")
  done
  median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
  checks=$(awk -F'|' '/^\| crack check/ {print $3+0}' "$work/log")
  cells=$(sed -n 's/.* \([0-9]*\) cells, \([0-9]*\) unknowns.*/\1/p' "$work/log" | head -1)
  unknowns=$(sed -n 's/.* \([0-9]*\) cells, \([0-9]*\) unknowns.*/\2/p' "$work/log" | head -1)
  faces=$(grep -c "face(s) cracked" "$work/log")
  echo "$n,$cells,$unknowns,$faces,$(median "${ins[@]}"),$(median "${chk[@]}"),$checks,$(median "${run[@]}")" >> "$out"
done
cat "$out"
rm -rf "$work"
