#!/bin/bash
# Cost of the contact search against the number of surface faces (issue 10
# benchmark): prm/impact_plate.prm (the seed's quarter plate, three plies,
# two cohesive interfaces) with Contact/Enable = true on 10 x 10 to
# 80 x 80 cells in the plane, 5 us of the impact, one rank. From the run's
# log: the surface faces, the search time (candidate search and closest
# points) and the whole contact time per evaluation, the number of
# candidate searches, and the TimerOutput sections "body contact",
# "internal forces" and "time steps"; median of REPEAT runs, into OUT
# (default doc/benchmarks/contact_search.csv). It fails if the search time
# per evaluation grows faster than the number of faces to the power 1.3
# (the least-squares slope over the four meshes; measured 0.77 and 1.06
# in two sessions; a search over all pairs of faces would grow with its
# square). ctest -R benchmark/contact_search runs it once into the build
# folder.
# usage: scripts/benchmarks/contact_search.sh BUILD_DIR [REPEAT] [OUT]
set -eu
build=$(cd "$1" && pwd) repeat=${2:-3}
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
out=${3:-$root/doc/benchmarks/contact_search.csv}
echo "elements,faces,nodes,evaluations,candidate_searches,search_us,contact_us,internal_forces_s,contact_s,steps_s" > "$out"
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
section() { # the average time of a TimerOutput section in a log
  grep "^| $1 " "$2" | awk -F'|' '{print $5}' | sed 's/s//' | tr -d ' '
}
for n in 10 20 40 80; do
  cat "$root/prm/impact_plate.prm" > "$work/plate.prm"
  cat >> "$work/plate.prm" <<PRM
subsection Geometry
  set Elements along length = $n
  set Elements along width  = $n
end
subsection Time
  set End time        = 5e-6
  set Number of steps = 5
end
subsection Output
  set Field format = none
  set Damage maps  = false
  set Directory    = $work/out
end
subsection Contact
  set Enable = true
end
PRM
  search=() contact=() internal=() body=() steps=()
  for r in $(seq "$repeat"); do
    "$build/amfrac" "$work/plate.prm" > "$work/log" 2>&1
    line=$(grep "  body contact:" "$work/log")
    faces=$(echo "$line" | awk '{print $3}')
    evaluations=$(echo "$line" | sed 's/.* over \([0-9]*\) evaluations.*/\1/')
    rebuilds=$(echo "$line" | sed 's/.*(\([0-9]*\) candidate searches.*/\1/')
    search+=("$(echo "$line" | sed 's/.* search \([0-9.e-]*\) s,.*/\1/')")
    contact+=("$(echo "$line" | sed 's/.*all contact work \([0-9.e-]*\) s.*/\1/')")
    internal+=("$(section "internal forces" "$work/log")")
    body+=("$(section "body contact" "$work/log")")
    steps+=("$(section "time steps" "$work/log")")
  done
  nodes=$(grep "  contact: .* surface nodes" "$work/log" | awk '{print $5}')
  s=$(median "${search[@]}") c=$(median "${contact[@]}")
  echo "$n,$faces,$nodes,$evaluations,$rebuilds,$(echo "$s $evaluations" | awk '{print 1e6*$1/$2}'),$(echo "$c $evaluations" | awk '{print 1e6*$1/$2}'),$(median "${internal[@]}"),$(median "${body[@]}"),$(median "${steps[@]}")" | tee -a "$out"
done
rm -rf "$work"
# The growth exponent of the search time with the number of faces: the
# least-squares slope of log(search) against log(faces) over the four
# meshes (a missing or non-positive figure fails).
awk -F, 'NR > 1 {
  if (!($2 > 0 && $6 > 0)) bad = 1
  else {x = log($2); y = log($6); n++; sx += x; sy += y; sxx += x * x; sxy += x * y}
} END {
  if (bad || n != 4) {print "contact_search: incomplete table"; exit 1}
  exponent = (n * sxy - sx * sy) / (n * sxx - sx * sx)
  printf "search time grows as faces^%.2f over %d meshes\n", exponent, n
  exit !(exponent < 1.3)}' "$out"
