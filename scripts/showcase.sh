#!/bin/bash
# Set up and build (scripts/setup.sh), then run the showcase scene: a
# quasi-isotropic [0/45/-45/90]s cantilever plate under a tip load, on two
# MPI ranks. Output: output-cantilever/ (open solution.pvd in ParaView).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun -np 2 "${BUILD_DIR:-build}/amfrac" prm/cantilever.prm
echo "amfrac showcase: fields in output-cantilever/solution.pvd, history in output-cantilever/history.csv"
