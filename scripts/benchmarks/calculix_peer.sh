#!/bin/bash
# Side by side with the CalculiX peer on the [0/90]s simply supported plate
# under uniform pressure (prm/benchmarks/calculix_plate.prm): centre
# deflection against wall time over several meshes, one core each, on
# uniform meshes and on meshes graded towards the edges (amfrac's
# Geometry/Edge grading; the peer's decks graded the same way by
# grade_calculix_deck.py).
# usage: calculix_peer.sh AMFRAC PEER_DIR OUT.csv
#   PEER_DIR: the folder with gen_plate.py (../shared/peers/calculix)
set -euo pipefail
amfrac=$(realpath "$1") peer=$(realpath "$2") out=$(realpath -m "$3")
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
cd "$work"
echo "code,element,solver,nx,grading,nz_per_ply,dofs,wall_s,max_rss_kb,w_centre" > "$out"

# CalculiX: one element per ply through the thickness (as its deck does).
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 CCX_NPROC_EQUATION_SOLVER=1 \
  CCX_NPROC_RESULTS=1 CCX_NPROC_STIFFNESS=1
calculix() { # solver nx grading
  local name=plate_$2_$3
  python3 "$peer/gen_plate.py" C3D20 "$2" 1 static "$1" 2> "$name.info" \
    | python3 "$here/scripts/benchmarks/grade_calculix_deck.py" "$2" "$3" 100 > "$name.inp"
  /usr/bin/time -f "%e %M" -o time ccx -i "$name" > "$name.log" 2>&1
  read -r wall rss < time
  dofs=$(grep -o "dofs=[0-9]*" "$name.info" | cut -d= -f2)
  # NODE PRINT of the centre node: "node ux uy uz" after the header.
  w=$(awk '/displacements/ {getline; getline; print $4; exit}' "$name.dat")
  echo "calculix,C3D20,${1// /-},$2,$3,1,$dofs,$wall,$rss,$w" | tee -a "$out"
}
for nx in 10 20 24 30 40 58; do calculix SPOOLES $nx 1; done
calculix "ITERATIVE CHOLESKY" 58 1
for cfg in 12:4 14:6 16:4 20:4 24:4; do
  IFS=: read -r nx grading <<< "$cfg"
  calculix SPOOLES "$nx" "$grading"
done

# amfrac, Q2 (27-node hexahedra) and Q1, one rank, direct and AMG.
amfrac_run() { # degree nx nz solver grading
  sed -e "s/set Elements along length = .*/set Elements along length = $2/" \
      -e "s/set Elements along width  = .*/set Elements along width  = $2/" \
      -e "s/set Elements per ply      = .*/set Elements per ply = $3\n  set Edge grading = $5/" \
      -e "s/set Finite element degree = .*/set Finite element degree = $1/" \
      -e "s/set Solver = direct/set Solver = $4\n  set Tolerance = 1e-8/" \
      -e "s|output-calculix-plate|$work/out|" \
      "$here/prm/benchmarks/calculix_plate.prm" > run.prm
  /usr/bin/time -f "%e %M" -o time "$amfrac" run.prm > amfrac.log
  read -r wall rss < time
  dofs=$(grep -o "[0-9]* unknowns" amfrac.log | cut -d' ' -f1)
  w=$(python3 -c "import csv; r=next(csv.DictReader(open('$work/out/history.csv'))); print(-float(r['p0_uz']))")
  echo "amfrac,Q$1,$4,$2,$5,$3,$dofs,$wall,$rss,$w" | tee -a "$out"
}
export OMPI_MCA_ess_singleton_isolated=1
for cfg in 2:12:1 2:16:1 2:20:1 2:28:1 2:40:1; do
  IFS=: read -r degree nx nz <<< "$cfg"
  amfrac_run "$degree" "$nx" "$nz" direct 1
done
amfrac_run 2 40 1 cg-amg 1
amfrac_run 1 120 3 cg-amg 1
for cfg in 10:4 12:4 14:6 16:4 20:4 24:4; do
  IFS=: read -r nx grading <<< "$cfg"
  amfrac_run 2 "$nx" 1 direct "$grading"
done
rm -rf "$work"
