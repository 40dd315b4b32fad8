#!/bin/bash
# Run time against error for the 2D DCB (prm/dcb_2d.prm) over meshes: the
# wall time (median of REPEAT runs, one core, Release) and, against
# corrected beam theory, the error of the peak load and of the load on the
# propagation branch at delta = 3.88 and 5.82 mm.
# A mesh on which the solver stops (an under-resolved process zone) is
# recorded with the opening where it stopped.
# usage: dcb_time_error.sh AMFRAC SCENE.prm OUT.csv [REPEAT]
set -eu
amfrac=$1 scene=$2 out=$3 repeat=${4:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "elements,unknowns,steps,seconds,peak_N,peak_error_pct,P388_error_pct,P582_error_pct,stopped_at" > "$out"
for n in 100 200 400 800; do
  { cat "$scene"; printf 'subsection Geometry\n  set Elements along length = %s\nend\n' "$n"
    printf 'subsection Time\n  set End time = 6\n  set Number of steps = 180\nend\n'
    printf 'subsection Output\n  set Field format = none\n  set Directory = %s/out\nend\n' "$work"; } > "$work/run.prm"
  times=()
  for r in $(seq "$repeat"); do
    start=$(date +%s.%N)
    status=0
    "$amfrac" "$work/run.prm" > "$work/log.txt" 2> "$work/error.txt" || status=$?
    times+=("$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')")
  done
  median=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  unknowns=$(grep -o '[0-9]* unknowns' "$work/log.txt" | cut -d' ' -f1)
  stopped=""
  if [ "$status" -ne 0 ]; then
    stopped=$(awk -F, 'END { print $2 }' "$work/out/history.csv")
  fi
  awk -F, -v n="$n" -v u="$unknowns" -v s="$median" -v stop="$stopped" '
    NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    { t[NR] = $col["time"]; P[NR] = 20 * $col["force_x-"]; last = NR }
    END {
      k = 2; for (r = 2; r <= last; ++r) if (P[r] > P[k]) k = r
      split("3.88 5.82", d, " "); split("44.5692 36.3906", env, " ")
      for (j = 1; j <= 2; ++j) {
        best = k; for (r = k; r <= last; ++r) if ((t[r]-d[j])^2 < (t[best]-d[j])^2) best = r
        err[j] = (t[last] < d[j]) ? "nan" : sprintf("%.2f", 100 * (P[best] / env[j] - 1))
      }
      printf "%d,%d,%d,%.2f,%.3f,%.2f,%s,%s,%s\n", n, u, last - 1, s, P[k], 100 * (P[k] / 63.03 - 1), err[1], err[2], stop
    }' "$work/out/history.csv" >> "$out"
done
cat "$out"
