#!/bin/bash
# Side by side with the CalculiX peer on the [0/90]s simply supported plate
# under uniform pressure (prm/benchmarks/calculix_plate.prm): centre
# deflection against wall time over several meshes, one core each.
# usage: calculix_peer.sh AMFRAC PEER_DIR OUT.csv
#   PEER_DIR: the folder with gen_plate.py (../shared/peers/calculix)
set -euo pipefail
amfrac=$(realpath "$1") peer=$(realpath "$2") out=$(realpath -m "$3")
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
cd "$work"
echo "code,element,solver,nx,nz_per_ply,dofs,wall_s,max_rss_kb,w_centre" > "$out"

# CalculiX: one element per ply through the thickness (as its deck does).
export OMP_NUM_THREADS=1 CCX_NPROC_EQUATION_SOLVER=1 CCX_NPROC_RESULTS=1 CCX_NPROC_STIFFNESS=1
for solver in SPOOLES "ITERATIVE CHOLESKY"; do
  for nx in 10 20 30 40 58; do
    name=plate_${nx}
    python3 "$peer/gen_plate.py" C3D20 "$nx" 1 static "$solver" > "$name.inp" 2> "$name.info"
    /usr/bin/time -f "%e %M" -o time ccx -i "$name" > "$name.log" 2>&1
    read -r wall rss < time
    dofs=$(grep -o "dofs=[0-9]*" "$name.info" | cut -d= -f2)
    # NODE PRINT of the centre node: "node ux uy uz" after the header.
    w=$(awk '/displacements/ {getline; getline; print $4; exit}' "$name.dat")
    echo "calculix,C3D20,${solver// /-},$nx,1,$dofs,$wall,$rss,$w" | tee -a "$out"
  done
done

# amfrac, Q2 (27-node hexahedra) and Q1, one rank, direct and AMG.
for cfg in 2:8:1 2:12:1 2:16:1 2:20:1 2:28:1 2:40:1 1:40:2 1:80:2 1:120:3; do
  IFS=: read -r degree nx nz <<< "$cfg"
  for solver in direct cg-amg; do
    sed -e "s/set Elements along length = .*/set Elements along length = $nx/" \
        -e "s/set Elements along width  = .*/set Elements along width  = $nx/" \
        -e "s/set Elements per ply      = .*/set Elements per ply      = $nz/" \
        -e "s/set Finite element degree = .*/set Finite element degree = $degree/" \
        -e "s/set Solver = direct/set Solver = $solver\n  set Tolerance = 1e-8/" \
        -e "s|output-calculix-plate|$work/out|" \
        "$here/prm/benchmarks/calculix_plate.prm" > run.prm
    /usr/bin/time -f "%e %M" -o time "$amfrac" run.prm > amfrac.log
    read -r wall rss < time
    dofs=$(grep -o "[0-9]* unknowns" amfrac.log | cut -d' ' -f1)
    w=$(python3 -c "import csv; r=next(csv.DictReader(open('$work/out/history.csv'))); print(-float(r['p0_uz']))")
    echo "amfrac,Q$degree,$solver,$nx,$nz,$dofs,$wall,$rss,$w" | tee -a "$out"
  done
done
rm -rf "$work"
