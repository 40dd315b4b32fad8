#!/bin/bash
# A checkpoint of a wedge run remeshed by Gmsh resumed with parameters
# that make hexahedra is refused (its mesh is the last remeshing's, which
# hexahedra cannot take): exit status 1, one error line naming
# Geometry/Element shape, and every file of the run that wrote it
# unchanged; resumed on wedges it finishes.
# usage: shape_mismatch.sh AMFRAC WORKDIR SCENE.prm (a scene that
# remeshes before its first step: prm/dcb_process_zone_prism.prm)
set -u
amfrac=$1 work=$2 scene=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failures=0

{
  cat "$scene"
  printf 'subsection Output\n  set Directory = out\n  set Field format = none\nend\n'
  printf 'subsection Time\n  set End time = 0.3\n  set Number of steps = 10\nend\n'
  printf 'subsection Checkpoint\n  set Every n steps = 1\n  set Stop after step = 3\nend\n'
} > first.prm
"$amfrac" first.prm > first.log 2>&1
status=$?
if [ $status -ne 75 ] || ! grep -q "remeshed:" first.log; then
  echo "FAIL: the first part ended with exit status $status (expected 75) or did not remesh"
  cat first.log
  exit 1
fi
fingerprint() { (cd out && find . -type f -exec md5sum {} + | sort); }
before=$(fingerprint)

# resume NAME SHAPE: the first part resumed on elements of SHAPE.
resume() {
  { cat first.prm; printf 'subsection Geometry\n  set Element shape = %s\nend\nsubsection Checkpoint\n  set Resume = true\nend\n' "$2"; } > "$1.prm"
  "$amfrac" "$1.prm" > "$1.log" 2> "$1.err"
}

resume other hexahedron
status=$?
problem=""
[ $status -eq 1 ] || problem="exit status $status"
[ "$(wc -l < other.err)" -eq 1 ] || problem="$problem; $(wc -l < other.err) stderr lines"
grep -qF "Geometry/Element shape" other.err || problem="$problem; Geometry/Element shape not named"
grep -qF "remeshed by Gmsh" other.err || problem="$problem; the cause not named"
[ "$(fingerprint)" = "$before" ] || problem="$problem; the files of the first part changed"
if [ -n "$problem" ]; then
  echo "FAIL hexahedra: $problem"
  cat other.err
  failures=$((failures + 1))
else
  echo "ok   hexahedra: $(cat other.err)"
fi

resume same prism
status=$?
if [ $status -ne 0 ] || ! grep -q "resumed from" same.log; then
  echo "FAIL wedges: exit status $status"
  cat same.err
  failures=$((failures + 1))
else
  echo "ok   wedges resumed"
fi
exit $failures
