#!/bin/bash
# Linear buckling of pre-buckled total Lagrangian states (Buckling/Number
# of modes with Kinematics = total Lagrangian), three tables:
#   OUT_arch.csv: the shallow arch (prm/shallow_arch_2d.prm, load steps)
#     analysed at fractions of its one-mode limit point t_l = 0.60447:
#     the state's t, the predicted t_c and (t + t_c) / 2; plus the
#     continuum's limit point from an arc-length run of the scene with 60
#     nominal steps (the first local maximum of t), in OUT_arch_path.csv.
#   OUT_panel.csv: the delaminated panel (prm/delaminated_panel.prm,
#     imperfect, displacement steps of 0.5) analysed at several t: the
#     force of the state and the predicted critical force.
#   OUT_strip.csv: the clamped strip (prm/buckling_strip_2d.prm, total
#     Lagrangian, 6 steps to t = 3) against the mesh: unknowns, t_c, the
#     analysis's wall time and share of the run (median of 3 runs).
# One rank, Release build.
# usage: prebuckling.sh AMFRAC OUT
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2")
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
cd "$work"

# run NAME SCENE APPENDED: runs, echoes "wall_s analysis_s".
run() {
  { cat "$2"; printf '%s\nsubsection Output\n set Field format = none\n set Directory = %s\nend\n' "$3" "$1"; } > "$1.prm"
  local start end
  start=$(date +%s.%N)
  "$amfrac" "$1.prm" > "$1.log"
  end=$(date +%s.%N)
  echo "$(echo "$end - $start" | bc) $(grep -o 'critical t from [0-9]* solves, [0-9.e-]* s' "$1.log" | awk '{print $6}')"
}
first_mode() { # FILE COLUMN: the column of buckling.csv's first mode
  /usr/bin/python3 -c "import csv,sys; print(next(csv.DictReader(open(sys.argv[1])))[sys.argv[2]])" "$1" "$2"
}
last_row() { # FILE COLUMN
  /usr/bin/python3 -c "import csv,sys; print(list(csv.DictReader(open(sys.argv[1])))[-1][sys.argv[2]])" "$1" "$2"
}

echo "fraction,t,t_c,mean,wall_s,analysis_s" > "${out}_arch.csv"
for f in 0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9 0.95 0.98; do
  t=$(echo "$f * 0.604472" | bc -l)
  read -r wall analysis < <(run arch$f "$here/prm/shallow_arch_2d.prm" "subsection Nonlinear solver
 set Control = displacement
end
subsection Time
 set End time = $t
 set Number of steps = 20
end
subsection Buckling
 set Number of modes = 1
end")
  tc=$(first_mode arch$f/buckling.csv critical_time)
  echo "$f,$t,$tc,$(echo "($t + $tc) / 2" | bc -l),$wall,$analysis" >> "${out}_arch.csv"
done
run path "$here/prm/shallow_arch_2d.prm" "subsection Time
 set End time = 0.7
 set Number of steps = 60
end" > /dev/null
cp path/history.csv "${out}_arch_path.csv"

echo "t,N,N_c,t_c,wall_s,analysis_s" > "${out}_panel.csv"
for t in 0.5 1 2 3 3.5 3.8 4 4.2; do
  n=$(echo "2 * $t / 1" | bc)
  read -r wall analysis < <(run panel$t "$here/prm/delaminated_panel.prm" "subsection Nonlinear solver
 set Control = displacement
end
subsection Time
 set End time = $t
 set Number of steps = $n
end
subsection Buckling
 set Number of modes = 1
 set Analysis times =
end")
  N=$(last_row panel$t/history.csv reaction_x+_x)
  Nc=$(first_mode panel$t/buckling.csv critical_reaction_x+_x)
  tc=$(first_mode panel$t/buckling.csv critical_time)
  echo "$t,${N#-},${Nc#-},$tc,$wall,$analysis" >> "${out}_panel.csv"
done

echo "elements,unknowns,t_c,N_c,wall_s_median,analysis_s_median" > "${out}_strip.csv"
for e in 50 100 200 400; do
  walls=() analyses=()
  for r in 1 2 3; do
    read -r wall analysis < <(run strip$e "$here/prm/buckling_strip_2d.prm" "set Kinematics = total Lagrangian
subsection Geometry
 set Elements along length = $e
end
subsection Time
 set End time = 3
 set Number of steps = 6
end")
    walls+=("$wall") analyses+=("$analysis")
  done
  unknowns=$(grep -o "[0-9]* unknowns" strip$e.log | head -1 | cut -d' ' -f1)
  echo "$e,$unknowns,$(first_mode strip$e/buckling.csv critical_time),$(first_mode strip$e/buckling.csv critical_reaction_x+_x | tr -d -),$(printf '%s\n' "${walls[@]}" | sort -g | sed -n 2p),$(printf '%s\n' "${analyses[@]}" | sort -g | sed -n 2p)" >> "${out}_strip.csv"
done
rm -rf "$work"
