#!/bin/bash
# usage: three_point_bending_3d.sh AMFRAC prm/three_point_bending_3d.prm
#        WORKDIR — runs the 3D three-point bending scene (a cylindrical
# loading nose, Impactor/Shape = cylinder) and checks at every step that
# the coupon's stiffness P / w lies between the narrow beam's 42.65 N/mm
# and the wide plate's 42.93 (derivation in the .prm), each within 0.5 %.
# The nose must touch along a line (at least 3 nodes), and the driver's
# work must balance (1e-9 of it).
set -eu
amfrac=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$amfrac" "$scene" > log
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  { P = 4 * $col["contact_force"]; w = -$col["p0_uz"]; err = (P / w - 42.65) / 42.65;
    balance = $col["balance_error"] / $col["external_work"];
    printf "t %g: P %.4f N, w %.5f mm, P/w %.3f N/mm, narrow beam 42.65 (%+.3f %%), wide plate 42.93, %d nodes touch, balance %.1e\n",
      $col["time"], P, w, P / w, 100 * err, $col["contact_nodes"], balance;
    if (P / w < 0.995 * 42.65 || P / w > 1.005 * 42.93 || $col["contact_nodes"] < 3 || balance > 1e-9 || balance < -1e-9) bad = 1;
    ++rows }
  END { exit (rows == 4 && !bad) ? 0 : 1 }' output-three-point-bending-3d/history.csv
