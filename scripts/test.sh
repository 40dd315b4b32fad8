#!/bin/bash
# Set up and build (scripts/setup.sh), then run the default test suite.
# Benchmarks (label "benchmark") are not part of it: ctest -L benchmark.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# A one-rank run without mpirun starts no Open MPI daemon (0.3 s of the
# 1 s a short run takes; the bad-input test: 157 s -> 120 s).
export OMPI_MCA_ess_singleton_isolated=1
# Open MPI's shared-memory messaging without probing network transports:
# mpirun -np 2 amfrac --help 0.93 s -> 0.63 s (amfrac itself asks for this
# when run without mpirun, see source/main.cc).
export OMPI_MCA_pml=ob1
cd "${BUILD_DIR:-build}"
ctest -j 2 --output-on-failure -LE benchmark
