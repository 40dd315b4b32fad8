#!/bin/bash
# Divergence: a Newton solve that cannot converge, a NaN in a prescribed
# displacement, an explicit run that blows up, a NaN in an explicit load and
# a NaN in the pressure of a linear static run
# must each stop with exit status 1, one `amfrac: error:` line saying what
# happened, history.csv with whole rows up to the last good step, and the
# fields of the last good state written (the newest entry of the field
# series exists).
# usage: divergence.sh AMFRAC WORKDIR DCB.prm DCB_SHORT.prm IMPACT.prm IMPACT_COARSE.prm BEAM.prm
set -u
amfrac=$1 work=$2 dcb=$3 dcb_short=$4 impact=$5 impact_coarse=$6 beam=$7
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failures=0

# expect NAME EXPECTED-TEXT SCENE-TEXT
expect() {
  local name=$1 expected=$2
  printf '%s\n' "$3" > "$name.prm"
  printf 'subsection Output\n  set Directory = %s\n  set Field format = vtu\nend\n' \
    "$name" >> "$name.prm"
  timeout 300 "$amfrac" "$name.prm" > "$name.log" 2> "$name.err"
  local status=$? problem=""
  local errors
  errors=$(grep -c "amfrac: error:" "$name.err")
  [ $status -eq 1 ] || problem="exit status $status"
  [ "$errors" -eq 1 ] || problem="$problem; $errors error lines"
  grep -qF -- "$expected" "$name.err" || problem="$problem; no '$expected'"
  local rows width
  rows=$(wc -l < "$name/history.csv" 2>/dev/null || echo 0)
  [ "$rows" -ge 2 ] || problem="$problem; history.csv has no rows"
  width=$(awk -F, 'NR == 1 {w = NF} NF != w {bad = 1} END {print bad + 0}' "$name/history.csv" 2>/dev/null)
  [ "$width" = 0 ] || problem="$problem; history.csv has a partial row"
  local newest
  local series
  series=$(ls "$name"/*.pvd 2>/dev/null | grep -v interfaces | head -1)
  newest=$(grep -o 'file="[^"]*"' "$series" 2>/dev/null | tail -1 | cut -d'"' -f2)
  [ -n "$newest" ] && [ -f "$name/$newest" ] || problem="$problem; no fields of the last good state"
  if [ -n "$problem" ]; then
    echo "FAIL $name: $problem"; cat "$name.err"
    failures=$((failures + 1))
  else
    echo "ok   $name: $(cat "$name.err")"
  fi
}

dcb_scene="$(cat "$dcb" "$dcb_short")"
impact_scene="$(cat "$impact" "$impact_coarse")"

expect newton_stalls "Newton did not converge" "$dcb_scene
subsection Nonlinear solver
  set Control        = displacement
  set Max iterations = 2
end"

expect newton_nan "is not finite" "$dcb_scene
subsection Boundary conditions
  subsection x-
    set Displacement = 0; y > h ? (t < 2 ? t/2 : sqrt(2 - t)) : -t/2
  end
end"

expect explicit_blows_up "explicit solution diverged" "$impact_scene
subsection Time
  set Time step      = 2e-8
  set Allow unstable time step = true
end"

expect explicit_nan "is not finite" "$impact_scene
subsection Boundary conditions
  subsection Patch load
    set Force = t < 1e-5 ? 1250*t/1e-5 : sqrt(1e-5 - t)
  end
end"

# A linear static run: the steps before the NaN are written.
expect static_nan "is not finite" "$(cat "$beam")
subsection Boundary conditions
  subsection y+
    set Pressure = t < 0.6 ? (abs(x - L/2) < 2 ? t : 0) : sqrt(0.5 - t)
  end
end
subsection Time
  set End time        = 1
  set Number of steps = 4
end"

exit $failures
