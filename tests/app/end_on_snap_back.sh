#!/bin/bash
# A dissipation-controlled run whose End time lies on a snap-back of the
# path (the 3D DCB of prm/dcb_3d.prm to 2.4 mm): a displacement step to End
# time cannot follow it, so the run must end with the dissipation step that
# crosses End time: exit 0, the message, and a last row at t >= End time
# whose energy balance is closed.
# usage: end_on_snap_back.sh AMFRAC SCENE.prm WORKDIR
set -eu
amfrac=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
{ cat "$scene"
  printf 'subsection Time\n  set End time = 2.4\n  set Number of steps = 80\nend\n'
  printf 'subsection Output\n  set Field format = none\n  set Directory = out\nend\n'; } > run.prm
"$amfrac" run.prm > log.txt
grep -q "End time lies on a snap-back" log.txt
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  { t = $col["time"]; b = $col["balance_error"]; w = $col["external_work"] }
  END { print "last t", t, "balance", b, "of", w
        exit !(t >= 2.4 && t < 2.5 && b * b < 1e-16 * w * w) }' out/history.csv
