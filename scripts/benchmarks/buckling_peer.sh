#!/bin/bash
# Linear buckling side by side with the CalculiX peer: the [0/90]s plate
# under 1 MPa edge compression (prm/buckling_plate.prm, CalculiX's
# "buckle" deck), four load factors each, over several meshes, one core
# each (OMP and OpenBLAS threads 1).
# usage: buckling_peer.sh AMFRAC PEER_DIR OUT.csv
#   PEER_DIR: the folder with gen_plate.py (../shared/peers/calculix)
set -euo pipefail
amfrac=$(realpath "$1") peer=$(realpath "$2") out=$(realpath -m "$3")
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
cd "$work"
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 CCX_NPROC_EQUATION_SOLVER=1 \
  CCX_NPROC_RESULTS=1 CCX_NPROC_STIFFNESS=1
echo "code,element,nx,dofs,wall_s,max_rss_kb,lambda_1,lambda_2,lambda_3,lambda_4" > "$out"

for nx in 10 20 30 40 58; do
  name=buckle_${nx}
  python3 "$peer/gen_plate.py" C3D20 "$nx" 1 buckle "" 4 > "$name.inp" 2> "$name.info"
  /usr/bin/time -f "%e %M" -o time ccx -i "$name" > "$name.log" 2>&1
  read -r wall rss < time
  dofs=$(grep -o "dofs=[0-9]*" "$name.info" | cut -d= -f2)
  # The factor table: "MODE NO / FACTOR" header, then "k value" lines.
  factors=$(awk '/FACTOR/ {on = 1; next} on && NF == 2 {printf ",%s", $2 + 0}' "$name.dat")
  echo "calculix,C3D20,$nx,$dofs,$wall,$rss$factors" | tee -a "$out"
done

for nx in 10 16 20 30 40; do
  sed -e "s/set Elements along length = .*/set Elements along length = $nx/" \
      -e "s/set Elements along width  = .*/set Elements along width  = $nx/" \
      -e "s|output-buckling-plate|$work/out|" \
      "$here/prm/buckling_plate.prm" > run.prm
  printf 'subsection Output\n  set Field format = none\nend\n' >> run.prm
  /usr/bin/time -f "%e %M" -o time "$amfrac" run.prm > amfrac.log
  read -r wall rss < time
  dofs=$(grep -o "[0-9]* unknowns" amfrac.log | cut -d' ' -f1)
  factors=$(python3 -c "import csv; print(''.join(',' + r['load_factor'] for r in csv.DictReader(open('$work/out/buckling.csv'))))")
  echo "amfrac,Q2,$nx,$dofs,$wall,$rss$factors" | tee -a "$out"
done
rm -rf "$work"
