#!/bin/bash
# Checkpoint cost (issue 9): size, write time and read time against the
# mesh size, for the explicit plate impact (3D, two cohesive interfaces:
# displacement, velocity, acceleration, load, reaction, damping force and
# the interface history) and the Newton DCB (2D); then the share of run
# time spent on checkpoints for a run that writes one every 3 s of wall
# time (100 times the rate of the default interval of 30 minutes).
# One rank, Release build. Every write and read is logged by amfrac itself
# ("checkpoint ...: X MB in Y s", "resumed ... read in Z s").
# usage: checkpoint_cost.sh AMFRAC OUT.csv
set -euo pipefail
amfrac=$(realpath "$1") out=$(realpath -m "$2")
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
cd "$work"
echo "scene,cells,unknowns,checkpoints,megabytes,write_s_median,read_s,run_s" > "$out"

# Median of the write times and the size of the last checkpoint in LOG.
summarize() {
  local scene=$1 log=$2 read_log=$3 run_s=$4
  local cells unknowns
  cells=$(grep -o "[0-9]* cells" "$log" | head -1 | cut -d' ' -f1)
  unknowns=$(grep -o "[0-9]* unknowns" "$log" | head -1 | cut -d' ' -f1)
  grep -o ": [0-9.e+-]* MB in [0-9.e+-]* s" "$log" | awk '{print $2, $5}' > writes
  local n mb median read
  n=$(wc -l < writes)
  mb=$(tail -1 writes | cut -d' ' -f1)
  median=$(cut -d' ' -f2 writes | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}')
  read=$(grep -o "read in [0-9.e+-]* s" "$read_log" | awk '{print $3}')
  echo "$scene,$cells,$unknowns,$n,$mb,$median,$read,$run_s" | tee -a "$out"
}

run() { # NAME PRM: run, then resume from the last checkpoint (read time)
  local name=$1 prm=$2 start end
  start=$(date +%s.%N)
  "$amfrac" "$prm" > "$name.log"
  end=$(date +%s.%N)
  "$amfrac" --resume "$name/checkpoints" > "$name.read.log"
  summarize "$3" "$name.log" "$name.read.log" "$(echo "$end - $start" | bc)"
}

for n in 16 32 64 96; do
  cat "$here/prm/impact_plate.prm" > impact_$n.prm
  cat >> impact_$n.prm <<EOF
subsection Geometry
  set Elements along length = $n
  set Elements along width  = $n
end
subsection Time
  set End time        = 4e-7
  set Number of steps = 4
end
subsection Output
  set Directory    = impact_$n
  set Field format = none
end
subsection Checkpoint
  set Every n steps = 1
  set Keep          = 1
end
EOF
  run impact_$n impact_$n.prm impact
done

for n in 400 1600 6400; do
  cat "$here/prm/dcb_2d.prm" > dcb_$n.prm
  cat >> dcb_$n.prm <<EOF
subsection Geometry
  set Elements along length = $n
end
subsection Time
  set End time        = 0.4
  set Number of steps = 4
end
subsection Output
  set Directory    = dcb_$n
  set Field format = none
end
subsection Checkpoint
  set Every n steps = 1
  set Keep          = 1
end
EOF
  run dcb_$n dcb_$n.prm dcb
done

# The share of run time: the 64 x 64 impact for 10 microseconds of
# physical time (fields every 20 output steps), a checkpoint every 0.05
# minutes (600 times the default rate); and the share at the default
# interval of 30 minutes, from the mean write time.
cat "$here/prm/impact_plate.prm" > share.prm
cat >> share.prm <<EOF
subsection Geometry
  set Elements along length = 64
  set Elements along width  = 64
end
subsection Time
  set End time        = 1e-5
  set Number of steps = 100
end
subsection Output
  set Directory    = share
  set Write every  = 20
end
subsection Checkpoint
  set Every minutes = 0.05
  set Keep          = 2
end
EOF
start=$(date +%s.%N)
"$amfrac" share.prm > share.log
end=$(date +%s.%N)
total=$(echo "$end - $start" | bc)
spent=$(grep -o ": [0-9.e+-]* MB in [0-9.e+-]* s" share.log | awk '{s += $5} END {print s}')
count=$(grep -c "MB in" share.log)
{
  echo "every 0.05 min: $count checkpoints, $spent s of $total s = $(echo "scale=4; 100 * $spent / $total" | bc) %"
  echo "every 30 min (default): $(echo "scale=6; 100 * $spent / $count / 1800" | bc) % of run time"
} | tee "${out%.csv}_share.txt"
rm -rf "$work"
