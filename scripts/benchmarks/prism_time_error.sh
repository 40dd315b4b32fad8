#!/bin/bash
# Run time against error for Pagano's [0/90/0] plate at S = 10 on
# hexahedra and on the same vertices split into wedges (prisms): degree 1
# and 2 over three meshes each, one rank, the direct solver and CG + AMG
# (tolerance 1e-10); REPEAT runs each, the median wall time is kept.
# usage: prism_time_error.sh AMFRAC OUT.csv [REPEAT]
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2") repeat=${3:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
echo "shape,degree,n,nz,cells,dofs,solver,wall_s,assemble_s,solver_setup_s,solve_s,iterations,w_bar,w_error,sigma_bar,sigma_error" > "$out"
# (degree in-plane-elements elements-per-ply)
meshes="1:8:1 1:16:2 1:32:3 2:4:1 2:8:1 2:16:2"
for shape in hexahedron prism; do
  for mesh in $meshes; do
    IFS=: read -r degree n nz <<< "$mesh"
    for solver in direct cg-amg; do
      prm=$work/run.prm
      sed -e "s/@A@/10/g; s/@C@/5/g; s/@N@/$n/g; s/@NZ@/$nz/g; s/@SHAPE@/$shape/g" \
        "$here/tests/app/pagano.prm" > "$prm"
      cat >> "$prm" <<PRM
subsection Discretization
  set Finite element degree = $degree
end
subsection Linear solver
  set Solver = $solver
  set Tolerance = 1e-10
end
subsection Output
  set Directory = $work/out
end
PRM
      walls=()
      for r in $(seq "$repeat"); do
        /usr/bin/time -f "%e" -o "$work/time" "$amfrac" "$prm" > "$work/log"
        walls+=("$(cat "$work/time")")
      done
      median=$(printf '%s\n' "${walls[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
      cells=$(grep -o "[0-9]* cells" "$work/log" | cut -d' ' -f1)
      dofs=$(grep -o "[0-9]* unknowns" "$work/log" | cut -d' ' -f1)
      section() { grep "^| $1 " "$work/log" | awk -F'|' '{print $4}' | sed 's/s//; s/ //g'; }
      iterations=$(grep -o "step 1 t=1: [0-9]*" "$work/log" | awk '{print $4}')
      /usr/bin/python3 - "$work/out/history.csv" <<PY >> "$out"
import csv, sys
row = next(csv.DictReader(open(sys.argv[1])))
w = 100 * 1e6 * float(row["p0_uz"]) / 1e4
s = float(row["p1_stress_xx"]) / 100
print("$shape,$degree,$n,$nz,$cells,$dofs,$solver,$median,$(section "assemble matrix"),$(section "solver setup"),$(section solve),$iterations,%.6f,%.3e,%.6f,%.3e" % (w, abs(w - 0.7530) / 0.7530, s, abs(s - 0.590) / 0.590))
PY
      tail -1 "$out"
    done
  done
done
rm -rf "$work"
