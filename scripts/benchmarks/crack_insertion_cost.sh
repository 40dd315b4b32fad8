#!/bin/bash
# Cost of crack insertion against mesh size (issue 6 benchmark): the 3D
# weakened bar of prm/cracked_bar_2d.prm with 4 x 4 elements across and 16,
# 64, 256 along its length (meshes 1x, 4x, 16x), so that the same K = 16
# faces are inserted in each. Prints the TimerOutput sections "crack
# insertion" (release, DoF layer, interface elements, Newton state) and
# "crack check" (the Hoffman check after every step) and the whole run,
# median of REPEAT runs, into doc/benchmarks/crack_insertion_cost.csv.
# Then the same bar in explicit dynamics (tests/app/explicit_cracked_bar.prm)
# with the candidates restricted to the weakened section, so that the same
# 16 faces crack on every mesh: the insertion events, their cost and one
# internal-force evaluation (a time step's main cost) for comparison, into
# doc/benchmarks/crack_insertion_cost_explicit.csv.
# usage: scripts/benchmarks/crack_insertion_cost.sh BUILD_DIR [REPEAT]
set -eu
build=$(cd "$1" && pwd) repeat=${2:-5}
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
# shellcheck source=common.sh
source "$root/scripts/benchmarks/common.sh"
# $work/bar.prm: the files $2... with the bar in 3D, N = $1 along.
bar_3d() {
  local n=$1
  shift
  weakened_bar_3d "$n" "$work/out" "$@" > "$work/bar.prm"
}
# From the TimerOutput table of $work/log: a section's wall time [s] and
# number of calls, the whole run's wall time, and the mesh's size.
seconds() { awk -F'|' -v s="$1" '$2 ~ "^ "s" " {gsub(/s/,"",$4); print $4+0}' "$work/log"; }
calls() { awk -F'|' -v s="$1" '$2 ~ "^ "s" " {print $3+0}' "$work/log"; }
wall() { awk -F'|' '/Total wallclock/ {gsub(/s/,"",$3); print $3+0}' "$work/log"; }
size() { sed -n "s/.* \([0-9]*\) cells, \([0-9]*\) unknowns.*/\\$1/p" "$work/log" | head -1; }
out=$root/doc/benchmarks/crack_insertion_cost.csv
echo "elements_along_length,cells,unknowns,faces,insertion_s,check_s,checks,run_s" > "$out"
for n in 16 64 256; do
  bar_3d "$n" "$root/prm/cracked_bar_2d.prm"
  # Odd n would not put a face at x = 2; the scene needs n a multiple of 2.
  ins=() chk=() run=()
  for r in $(seq "$repeat"); do
    "$build/amfrac" "$work/bar.prm" > "$work/log"
    ins+=("$(seconds "crack insertion")")
    chk+=("$(seconds "crack check")")
    run+=("$(wall)")
  done
  faces=$(grep -c "face(s) cracked" "$work/log")
  echo "$n,$(size 1),$(size 2),$faces,$(median "${ins[@]}"),$(median "${chk[@]}"),$(calls "crack check"),$(median "${run[@]}")" >> "$out"
done
cat "$out"

out=$root/doc/benchmarks/crack_insertion_cost_explicit.csv
echo "elements_along_length,cells,unknowns,faces,events,insertion_s,forces_per_step_ms,steps,run_s" > "$out"
for n in 16 64 256; do
  bar_3d "$n" "$root/prm/cracked_bar_2d.prm" \
    "$root/tests/app/explicit_cracked_bar.prm"
  printf 'subsection Crack insertion\n  set Region = abs(x - 2) < 1e-3\nend\n' >> "$work/bar.prm"
  ins=() frc=() run=()
  for r in $(seq "$repeat"); do
    "$build/amfrac" "$work/bar.prm" > "$work/log"
    ins+=("$(seconds "crack insertion")")
    frc+=("$(awk -v t="$(seconds "internal forces")" -v n="$(calls "internal forces")" 'BEGIN {print 1000 * t / n}')")
    run+=("$(wall)")
  done
  faces=$(tail -1 "$work/out/cracks.csv" | cut -d, -f4)
  echo "$n,$(size 1),$(size 2),$faces,$(calls "crack insertion"),$(median "${ins[@]}"),$(median "${frc[@]}"),$(calls "internal forces"),$(median "${run[@]}")" >> "$out"
done
cat "$out"
rm -rf "$work"
