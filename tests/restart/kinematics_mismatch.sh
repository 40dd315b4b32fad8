#!/bin/bash
# A checkpoint resumed with the other kinematics is refused (the plastic
# strain and the interface history mean other things in the two): exit
# status 1, one error line naming Kinematics, and every file of the run
# that wrote it (the checkpoint, history.csv) unchanged.
# usage: kinematics_mismatch.sh AMFRAC WORKDIR SCENE.prm
set -u
amfrac=$1 work=$2 scene=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failures=0

{
  cat "$scene"
  printf 'subsection Output\n  set Directory = out\n  set Field format = none\nend\n'
  printf 'subsection Time\n  set End time = 2\n  set Number of steps = 8\nend\n'
  printf 'subsection Checkpoint\n  set Every n steps = 1\n  set Stop after step = 3\nend\n'
} > first.prm
"$amfrac" first.prm > first.log 2>&1
status=$?
if [ $status -ne 75 ]; then
  echo "FAIL: the first part ended with exit status $status, expected 75"
  cat first.log
  exit 1
fi
fingerprint() { (cd out && find . -type f -exec md5sum {} + | sort); }
before=$(fingerprint)

# resume NAME KINEMATICS: the first part resumed with KINEMATICS.
resume() {
  { cat first.prm; printf 'set Kinematics = %s\nsubsection Checkpoint\n  set Resume = true\nend\n' "$2"; } > "$1.prm"
  "$amfrac" "$1.prm" > "$1.log" 2> "$1.err"
}

resume other "small strain"
status=$?
problem=""
[ $status -eq 1 ] || problem="exit status $status"
[ "$(wc -l < other.err)" -eq 1 ] || problem="$problem; $(wc -l < other.err) stderr lines"
grep -qF "Kinematics" other.err || problem="$problem; Kinematics not named"
grep -qF "total Lagrangian" other.err || problem="$problem; the checkpoint's kinematics not named"
[ "$(fingerprint)" = "$before" ] || problem="$problem; the files of the first part changed"
if [ -n "$problem" ]; then
  echo "FAIL other kinematics: $problem"
  cat other.err
  failures=$((failures + 1))
else
  echo "ok   other kinematics: $(cat other.err)"
fi

# The same kinematics resumes and finishes.
resume same "total Lagrangian"
status=$?
if [ $status -ne 0 ] || ! grep -q "resumed from" same.log; then
  echo "FAIL same kinematics: exit status $status"
  cat same.err
  failures=$((failures + 1))
else
  echo "ok   same kinematics resumed"
fi
exit $failures
