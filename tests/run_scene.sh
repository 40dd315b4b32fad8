#!/bin/bash
# Run a shipped scene in a scratch folder; it must exit 0 and write its
# history (and, with interfaces and VTU output, the interface points).
# usage: run_scene.sh AMFRAC SCENE.prm WORKDIR
set -eu
amfrac=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$amfrac" "$scene"
test -n "$(find . -name history.csv)"
# A scene with cohesive interfaces and VTU output writes the interface
# points too.
if grep -q "^ *set Interfaces *= *[^ ]" "$scene" && [ -n "$(find . -name 'solution.pvd')" ]; then
  test -n "$(find . -name 'solution-interfaces.pvd')"
  test -n "$(find . -name 'solution-interfaces-*.0000.vtu')"
fi
