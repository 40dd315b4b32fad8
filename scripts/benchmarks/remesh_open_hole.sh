#!/bin/bash
# Run time against error of the seed's global remeshing on the open-hole
# plate of prm/open_hole_prism.prm (P1 wedges, the isotropic nu = 0
# material of tests/app/open_hole_isotropic.prm, whose 3D solution is the
# plane-stress one), from the coarse start of tests/app/remesh_open_hole.cc
# (12 elements around the hole, 3 along the width):
# - uniform: Global refinements 0..3 (every size halved per refinement);
# - remeshed: Strategy = error target down to Target error 0.03 .. 0.006.
# The true relative energy error is sqrt((W - W_h) / W) against the load
# work W of a converged adaptive Q2 run of the plate in its plane. One
# rank, the direct solver, REPEAT runs each (median wall time of the whole
# run, all cycles and the Gmsh meshing included).
# usage: remesh_open_hole.sh AMFRAC OUT.csv [REPEAT]
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2") repeat=${3:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
isotropic=$(cat "$here/tests/app/open_hole_isotropic.prm")
{ cat "$here/prm/open_hole_2d.prm"; printf '%s\n' "$isotropic"; cat <<PRM
subsection Discretization
  set Finite element degree = 2
end
subsection Adaptivity
  set Refinement cycles = 8
  set Refine fraction = 0.6
end
subsection Output
  set Directory = $work/reference
  set Field format = none
end
PRM
} > "$work/reference.prm"
"$amfrac" "$work/reference.prm" > /dev/null
reference=$(/usr/bin/python3 -c "import csv; print(list(csv.DictReader(open('$work/reference/adaptivity.csv')))[-1]['load_work'])")
echo "reference load work $reference" >&2
echo "kind,setting,meshes,cells,unknowns,wall_s,remesh_s,transfer_s,load_work,energy_error,zz_relative" > "$out"
run() {
  local kind=$1 setting=$2 extra=$3
  { cat "$here/prm/open_hole_prism.prm"; printf '%s\n' "$isotropic"; cat <<PRM
subsection Geometry
  set Elements around hole = 12
  set Elements along width = 3
end
subsection Adaptivity
  set Refinement cycles = 0
end
$extra
subsection Output
  set Directory = $work/out
  set Field format = none
end
PRM
  } > "$work/run.prm"
  walls=()
  for r in $(seq "$repeat"); do
    rm -rf "$work/out"
    /usr/bin/time -f "%e" -o "$work/time" "$amfrac" "$work/run.prm" > "$work/log"
    walls+=("$(cat "$work/time")")
  done
  median=$(printf '%s\n' "${walls[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  /usr/bin/python3 - "$work/out" "$kind" "$setting" "$median" "$reference" <<'PY' >> "$out"
import csv, math, os, sys
folder, kind, setting, wall, reference = sys.argv[1:]
reference = float(reference)
cycles = os.path.join(folder, "adaptivity.csv")
if os.path.exists(cycles):
    rows = list(csv.DictReader(open(cycles)))
    last = rows[-1]
    remesh = sum(float(r["remesh_seconds"]) for r in rows)
    transfer = sum(float(r["transfer_seconds"]) for r in rows)
    cells, unknowns, zz = last["cells"], last["unknowns"], last["zz_relative_error"]
    meshes = len(rows)
else:
    last = list(csv.DictReader(open(os.path.join(folder, "history.csv"))))[-1]
    remesh = transfer = 0
    log = open(os.path.join(os.path.dirname(folder), "log")).read().split()
    cells = log[log.index("cells,") - 1]
    unknowns = log[log.index("unknowns") - 1]
    zz, meshes = "nan", 1
w = float(last["load_work"])
error = math.sqrt(max(0.0, reference - w) / reference)
print("%s,%s,%d,%s,%s,%s,%.3f,%.3f,%.6f,%.4e,%s" % (kind, setting, meshes, cells, unknowns, wall, remesh, transfer, w, error, zz))
PY
  tail -1 "$out"
}
for r in 0 1 2 3; do
  run uniform "$r" "subsection Geometry
  set Global refinements = $r
end"
done
for target in 0.03 0.02 0.012 0.008 0.006; do
  run remeshed "$target" "subsection Adaptivity
  set Refinement cycles = 8
  set Strategy = error target
  set Target error = $target
end"
done
rm -rf "$work"
