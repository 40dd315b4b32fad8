# Helpers of the benchmark scripts (sourced).
# median X...: the median of the numbers.
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
# section LOG NAME: the wall time of TimerOutput's section NAME in LOG.
section() {
  awk -F'|' -v name="$2" '{gsub(/^ +| +$/, "", $2)} $2 == name {split($4, a, "s"); print a[1] + 0; exit}' "$1"
}
