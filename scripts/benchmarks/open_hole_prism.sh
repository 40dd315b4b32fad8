#!/bin/bash
# Run time against error for the open-hole plate on Gmsh prisms
# (prm/open_hole_prism.prm) with the isotropic nu = 0 material of
# tests/app/open_hole_isotropic.prm, whose 3D solution is the plane-stress one:
# P1 and P2 wedges, Elements around hole 24..96 and Global refinements
# 0..2, against the load work of a converged adaptive Q2 run of the plate
# in its plane. One rank, the direct solver, REPEAT runs each (median wall
# time; the Gmsh meshing is part of it).
# usage: open_hole_prism.sh AMFRAC OUT.csv [REPEAT]
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2") repeat=${3:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
isotropic=$(cat "$here/tests/app/open_hole_isotropic.prm")
# The reference: the plate in its plane, adaptive Q2, 8 cycles.
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
echo "degree,around_hole,refinements,cells,dofs,wall_s,setup_s,solve_s,load_work,work_error,K" > "$out"
for degree in 1 2; do
  for mesh in 24:0 48:0 48:1 48:2 96:1; do
    IFS=: read -r around refinements <<< "$mesh"
    [ "$degree" = 2 ] && [ "$mesh" = 96:1 ] && continue
    { cat "$here/prm/open_hole_prism.prm"; printf '%s\n' "$isotropic"; cat <<PRM
subsection Geometry
  set Elements around hole = $around
  set Global refinements = $refinements
end
subsection Discretization
  set Finite element degree = $degree
end
subsection Output
  set Directory = $work/out
  set Field format = none
  set Point values = 36, 21, 0.5
end
PRM
    } > "$work/run.prm"
    walls=()
    for r in $(seq "$repeat"); do
      /usr/bin/time -f "%e" -o "$work/time" "$amfrac" "$work/run.prm" > "$work/log"
      walls+=("$(cat "$work/time")")
    done
    median=$(printf '%s\n' "${walls[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
    cells=$(grep -o "[0-9]* cells" "$work/log" | head -1 | cut -d' ' -f1)
    dofs=$(grep -o "[0-9]* unknowns" "$work/log" | head -1 | cut -d' ' -f1)
    section() { grep "^| $1 " "$work/log" | awk -F'|' '{print $4}' | sed 's/s//; s/ //g'; }
    /usr/bin/python3 - "$work/out/history.csv" <<PY >> "$out"
import csv, sys
row = next(csv.DictReader(open(sys.argv[1])))
w = float(row["load_work"])
print("$degree,$around,$refinements,$cells,$dofs,$median,$(section setup),$(section solve),%.6f,%.3e,%.4f" % (w, abs(w / $reference - 1), float(row["p0_stress_xx"]) / 100))
PY
    tail -1 "$out"
  done
done
rm -rf "$work"
