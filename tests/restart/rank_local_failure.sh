#!/bin/bash
# An error on one rank only (here: rank 1 cannot write its piece of the
# second field step, because a folder has taken the file's name) must end
# the whole job within the time limit with a message naming the file and a
# non-zero exit status, instead of leaving the other rank waiting (the
# failing rank used to hang in the MUMPS destructor while unwinding).
# usage: rank_local_failure.sh MPIEXEC AMFRAC WORKDIR DCB.prm DCB_SHORT.prm
set -u
mpiexec=$1 amfrac=$2 work=$3 dcb=$4 short=$5
rm -rf "$work" && mkdir -p "$work/out/solution-00002.0001.vtu" && cd "$work" || exit 1
cat "$dcb" "$short" > scene.prm
printf 'subsection Output\n  set Directory = out\n  set Field format = vtu\n  set Write every = 1\nend\nsubsection Linear solver\n  set Direct package = mumps\nend\n' >> scene.prm
timeout 120 "$mpiexec" --allow-run-as-root --oversubscribe -np 2 "$amfrac" scene.prm > run.log 2> run.err
status=$?
if [ $status -eq 124 ]; then
  echo "FAIL: the job hung (killed after 120 s)"; exit 1
fi
if [ $status -eq 0 ] || ! grep -q "amfrac: error: (rank 1).*solution-00002.0001.vtu" run.err; then
  echo "FAIL: exit status $status, stderr:"; cat run.err; exit 1
fi
echo "ok: exit status $status: $(grep 'amfrac: error' run.err)"
