#!/bin/bash
# usage: beam_2d.sh AMFRAC prm/beam_2d.prm WORKDIR — runs the 2D three-point
# bending scene and compares the mid-span deflection with beam theory
# (1.052 mm, derivation in the .prm) within 1 %.
set -eu
amfrac=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$amfrac" "$scene" > log
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  { w = -$col["p0_uy"]; err = (w - 1.052) / 1.052;
    printf "mid-span deflection %.5f mm, beam theory 1.052 mm, error %.3f %%\n", w, 100 * err;
    exit (err < 0.01 && err > -0.01) ? 0 : 1 }' output-beam-2d/history.csv
