# Helpers of the benchmark scripts (sourced).
# median X...: the median of the numbers.
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
# section LOG NAME: the wall time of TimerOutput's section NAME in LOG.
section() {
  awk -F'|' -v name="$2" '{gsub(/^ +| +$/, "", $2)} $2 == name {split($4, a, "s"); print a[1] + 0; exit}' "$1"
}
# weakened_bar_3d N OUTPUT_DIR FILE...: the files (prm/cracked_bar_2d.prm
# and what is appended to it) with the bar in 3D, 4 x 4 elements across and
# N along, its z- face held in z, history only in OUTPUT_DIR.
weakened_bar_3d() {
  local n=$1 dir=$2
  shift 2
  cat "$@"
  cat <<PRM
set Dimension = 3
subsection Geometry
  set Width = 1
  set Elements along width = 4
  set Elements per ply = 4
  set Elements along length = $n
end
subsection Boundary conditions
  subsection z-
    set Type = displacement
    set Components = z
    set Displacement = 0
  end
end
subsection Output
  set Field format = none
  set Directory = $dir
end
PRM
}
