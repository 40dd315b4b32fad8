#!/bin/bash
# The cylindrical loading nose (issue 10, Impactor/Shape = cylinder):
# prm/three_point_bending_3d.prm (a [0_4] coupon in three-point bending,
# Q2, a quarter model) on meshes of growing size, one rank, the median wall
# time of REPEAT runs each. Per mesh: the cells along the length, across
# the half-width and through a ply, the unknowns, the stiffness P / w at
# the last step, its difference from narrow-beam theory (42.65 N/mm, see
# the .prm), the nodes in contact, the wall time and the "impactor" section
# of TimerOutput.
# usage: three_point_bending.sh AMFRAC OUT.csv [REPEAT]
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2") repeat=${3:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
# shellcheck source=common.sh
source "$here/scripts/benchmarks/common.sh"
echo "length_cells,width_cells,ply_cells,unknowns,stiffness_N_per_mm,vs_beam_theory,contact_nodes,wall_s,impactor_s" > "$out"
for mesh in "12 1 1" "25 2 1" "50 4 1" "50 4 2"; do
  read -r nx ny nz <<< "$mesh"
  { cat "$here/prm/three_point_bending_3d.prm"
    printf 'subsection Geometry\n  set Elements along length = %s\n' "$nx"
    printf '  set Elements along width = %s\n  set Elements per ply = %s\nend\n' "$ny" "$nz"
    printf 'subsection Output\n  set Directory = output\n  set Field format = none\nend\n'
  } > "$work/scene.prm"
  times="" parts=""
  for r in $(seq "$repeat"); do
    start=$(date +%s.%N)
    (cd "$work" && "$amfrac" scene.prm > log)
    times+=" $(echo "$(date +%s.%N) $start" | awk '{print $1 - $2}')"
    parts+=" $(section "$work/log" impactor)"
  done
  unknowns=$(grep -oE '[0-9]+ unknowns' "$work/log" | head -1 | awk '{print $1}')
  row=$(awk -F, 'NR == 1 {for (i = 1; i <= NF; ++i) c[$i] = i; next}
    {k = 4 * $c["contact_force"] / -$c["p0_uz"]; n = $c["contact_nodes"]}
    END {printf "%.4f,%.5f,%d", k, k / 42.65 - 1, n}' "$work/output/history.csv")
  # shellcheck disable=SC2086
  echo "$nx,$ny,$nz,${unknowns:-0},$row,$(median $times),$(median $parts)" >> "$out"
done
rm -rf "$work"
cat "$out"
