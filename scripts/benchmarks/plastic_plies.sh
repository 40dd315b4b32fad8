#!/bin/bash
# Hoffman plasticity of the plies (Materials/Plasticity = hoffman):
# 1. Run time against error of the plastic beam (prm/plastic_beam_2d.prm):
#    uniform meshes of 48 x 1 ... 384 x 8 cells per ply and the scene's
#    own adaptive run, final force and plastic work against the
#    Richardson extrapolation of the uniform sequence.
# 2. What plasticity costs where it is not reached: the 2D DCB
#    (prm/dcb_2d.prm to an opening of 2.6 mm) with strengths ten times the
#    defaults, elastic against Plasticity = hoffman (the same history bit
#    for bit), and the DCB with only the lower arm plastic.
# One rank, REPEAT runs each, the median wall time of the whole run.
# usage: plastic_plies.sh AMFRAC OUT.csv [REPEAT]
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2") repeat=${3:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# median_run NAME PRM: REPEAT runs, prints the median wall time.
median_run() {
  local walls=()
  for r in $(seq "$repeat"); do
    rm -rf "$work/out"
    /usr/bin/time -f "%e" -o "$work/time" "$amfrac" "$2" > "$work/$1.log"
    walls+=("$(cat "$work/time")")
  done
  printf '%s\n' "${walls[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}

last() { # last COLUMN FILE: the value of COLUMN in the last row of a CSV
  /usr/bin/python3 -c "import csv,sys; print(list(csv.DictReader(open(sys.argv[2])))[-1][sys.argv[1]])" "$1" "$2"
}

echo "case,setting,cells,wall_s,newton_iterations,force,plastic_work" > "$out"
beam_run() {
  local setting=$1 extra=$2
  { cat "$here/prm/plastic_beam_2d.prm"; printf '%s\n' "$extra"; cat <<PRM
subsection Output
  set Directory = $work/out
  set Field format = none
end
PRM
  } > "$work/beam.prm"
  local wall cells iterations
  wall=$(median_run beam "$work/beam.prm")
  iterations=$(grep -o "[0-9]* Newton iterations" "$work/beam.log" | cut -d' ' -f1)
  cells=$(grep -o "[0-9]* cells" "$work/beam.log" | tail -1 | cut -d' ' -f1)
  echo "beam,$setting,$cells,$wall,$iterations,$(last force_y+ "$work/out/history.csv"),$(last plastic_work "$work/out/history.csv")" >> "$out"
}
for m in "48 1" "96 2" "192 4" "384 8"; do
  set -- $m
  beam_run "uniform $1x$2" "subsection Geometry
  set Elements along length = $1
  set Elements per ply = $2
end
subsection Adaptivity
  set Refine every = 0
end"
done
beam_run adaptive ""

strengths='subsection Materials
  set Xt = 20000
  set Xc = 12000
  set Yt = 500
  set Yc = 2000
  set Zt = 500
  set Zc = 2000
  set S12 = 800
  set S13 = 800
  set S23 = 600
end'
dcb_run() {
  local setting=$1 extra=$2
  { cat "$here/prm/dcb_2d.prm" "$here/tests/app/dcb_2d_short.prm"
    printf '%s\n%s\n' "$strengths" "$extra"; cat <<PRM
subsection Output
  set Directory = $work/out
  set Field format = none
end
PRM
  } > "$work/dcb.prm"
  local wall iterations
  wall=$(median_run dcb "$work/dcb.prm")
  iterations=$(grep -o "[0-9]* Newton iterations" "$work/dcb.log" | cut -d' ' -f1)
  cells=$(grep -o "[0-9]* cells" "$work/dcb.log" | head -1 | cut -d' ' -f1)
  echo "dcb,$setting,$cells,$wall,$iterations,$(last force_x- "$work/out/history.csv"),0" >> "$out"
}
dcb_run elastic ""
dcb_run "plastic not reached" "subsection Materials
  set Plasticity = hoffman
end"
# The lower arm's material plastic, the upper one elastic.
dcb_run "lower arm plastic" "subsection Geometry
  set Stacking sequence = [0@soft/0]
end
subsection Materials
  set Names = cfrp, soft
  set Plasticity = none, hoffman
end"
cat "$out"
