#!/bin/bash
# Run time against error for the open-hole plate on Gmsh prisms
# (prm/open_hole_prism.prm) with the isotropic nu = 0 material of
# tests/app/open_hole_isotropic.prm, whose 3D solution is the plane-stress one:
# P1 and P2 wedges, Elements around hole 24..96 and Global refinements
# 0..2, and the hexahedra of deal.II's plate with a hole (Elements along
# width 8..64, refined in the plane only), against the load work of a
# converged adaptive Q2 run of the plate in its plane. One rank, the
# direct solver, REPEAT runs each (median wall time; the Gmsh meshing is
# part of it). SHAPES (default "prism hexahedron") picks the families.
# usage: open_hole_prism.sh AMFRAC OUT.csv [REPEAT] [SHAPES]
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2") repeat=${3:-3}
shapes=${4:-prism hexahedron}
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
echo "shape,degree,around_hole,refinements,along_width,cells,dofs,wall_s,setup_s,solve_s,load_work,work_error,K" > "$out"
# shape:degree:around hole:global refinements:elements along width
runs=""
for degree in 1 2; do
  for mesh in 24:0 48:0 48:1 48:2 96:1; do
    [ "$degree" = 2 ] && [ "$mesh" = 96:1 ] && continue
    runs="$runs prism:$degree:$mesh:8"
  done
  for width in 8 16 32 64; do
    [ "$degree" = 2 ] && [ "$width" = 64 ] && continue
    runs="$runs hexahedron:$degree:32:0:$width"
  done
done
for run in $runs; do
    IFS=: read -r shape degree around refinements width <<< "$run"
    [[ " $shapes " == *" $shape "* ]] || continue
    { cat "$here/prm/open_hole_prism.prm"; printf '%s\n' "$isotropic"; cat <<PRM
subsection Geometry
  set Element shape = $shape
  set Elements around hole = $around
  set Elements along width = $width
  set Global refinements = $refinements
end
subsection Discretization
  set Finite element degree = $degree
end
# One mesh per run: the scene's remeshing cycles are section 18's.
subsection Adaptivity
  set Refinement cycles = 0
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
print("$shape,$degree,$around,$refinements,$width,$cells,$dofs,$median,$(section setup),$(section solve),%.6f,%.3e,%.4f" % (w, abs(w / $reference - 1), float(row["p0_stress_xx"]) / 100))
PY
    tail -1 "$out"
done
rm -rf "$work"
