#!/bin/bash
# A checkpoint resumed with parameters it cannot take is refused: exit
# status 1, one error line naming the parameter and the cause, and every
# file of the run that wrote it (the checkpoint, history.csv) unchanged;
# resumed with the setting of the run that wrote it, it finishes.
# The first part runs SCENE to END_TIME in STEPS steps and stops after
# step 3 (and must print FIRST_MATCH, if given); SETTING is a printf
# format of the .prm lines that set OTHER (refused) or SAME (resumed).
# usage: resume_mismatch.sh AMFRAC WORKDIR SCENE.prm END_TIME STEPS
#          SETTING OTHER SAME NAMED CAUSE [FIRST_MATCH]
set -u
amfrac=$1 work=$2 scene=$3 end_time=$4 steps=$5 setting=$6 other=$7 same=$8
named=$9 cause=${10} first_match=${11:-}
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failures=0

{
  cat "$scene"
  printf 'subsection Output\n  set Directory = out\n  set Field format = none\nend\n'
  printf 'subsection Time\n  set End time = %s\n  set Number of steps = %s\nend\n' "$end_time" "$steps"
  printf 'subsection Checkpoint\n  set Every n steps = 1\n  set Stop after step = 3\nend\n'
} > first.prm
"$amfrac" first.prm > first.log 2>&1
status=$?
if [ $status -ne 75 ] || { [ -n "$first_match" ] && ! grep -q "$first_match" first.log; }; then
  echo "FAIL: the first part ended with exit status $status (expected 75) or did not print '$first_match'"
  cat first.log
  exit 1
fi
fingerprint() { (cd out && find . -type f -exec md5sum {} + | sort); }
before=$(fingerprint)

# resume NAME VALUE: the first part resumed with SETTING of VALUE.
resume() {
  { cat first.prm; printf "$setting" "$2"; printf 'subsection Checkpoint\n  set Resume = true\nend\n'; } > "$1.prm"
  "$amfrac" "$1.prm" > "$1.log" 2> "$1.err"
}

resume other "$other"
status=$?
problem=""
[ $status -eq 1 ] || problem="exit status $status"
[ "$(wc -l < other.err)" -eq 1 ] || problem="$problem; $(wc -l < other.err) stderr lines"
grep -qF "$named" other.err || problem="$problem; $named not named"
grep -qF "$cause" other.err || problem="$problem; the cause ('$cause') not named"
[ "$(fingerprint)" = "$before" ] || problem="$problem; the files of the first part changed"
if [ -n "$problem" ]; then
  echo "FAIL $other: $problem"
  cat other.err
  failures=$((failures + 1))
else
  echo "ok   $other: $(cat other.err)"
fi

resume same "$same"
status=$?
if [ $status -ne 0 ] || ! grep -q "resumed from" same.log; then
  echo "FAIL $same: exit status $status"
  cat same.err
  failures=$((failures + 1))
else
  echo "ok   $same resumed"
fi
exit $failures
