#!/bin/bash
# Run a shipped scene in a scratch folder; it must exit 0 and write its
# history. usage: run_scene.sh AMFRAC SCENE.prm WORKDIR
set -eu
amfrac=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$amfrac" "$scene"
test -n "$(find . -name history.csv)"
