#!/bin/bash
# Linear buckling on wedges against hexahedra: the [0/90]s plate of
# prm/buckling_plate.prm (quadratic elements) on nx x nx squares, each
# square one Q2 hexahedron or two P2 wedges per ply, four load factors,
# one rank, the median wall time of REPEATS runs.
# usage: buckling_prism.sh AMFRAC OUT.csv [REPEATS]
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2") repeats=${3:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
source "$here/scripts/benchmarks/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
echo "shape,nx,cells,dofs,wall_s,lambda_1,lambda_2,lambda_3,lambda_4" > "$out"

for nx in 10 16 20 30 40; do
  for shape in hexahedron prism; do
    sed -e "s/set Elements along length = .*/set Elements along length = $nx/" \
        -e "s/set Elements along width  = .*/set Elements along width  = $nx/" \
        -e "s|output-buckling-plate|$work/out|" \
        "$here/prm/buckling_plate.prm" > run.prm
    printf 'subsection Geometry\n  set Element shape = %s\nend\n' "$shape" >> run.prm
    printf 'subsection Output\n  set Field format = none\nend\n' >> run.prm
    walls=()
    for ((r = 0; r < repeats; ++r)); do
      /usr/bin/time -f "%e" -o time "$amfrac" run.prm > amfrac.log
      walls+=("$(cat time)")
    done
    cells=$(grep -o "[0-9]* cells" amfrac.log | cut -d' ' -f1)
    dofs=$(grep -o "[0-9]* unknowns" amfrac.log | cut -d' ' -f1)
    factors=$(/usr/bin/python3 -c "import csv; print(''.join(',' + r['load_factor'] for r in csv.DictReader(open('$work/out/buckling.csv'))))")
    echo "$shape,$nx,$cells,$dofs,$(median "${walls[@]}")$factors" | tee -a "$out"
  done
done
