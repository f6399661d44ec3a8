#!/usr/bin/env bash
# PrusaSlicer's hollowing against ours, in the same run, on the same part (#36): a generated
# sphere 35 mm tall (the part bench_hollowing makes) at 0.05 mm layers on the SL1S's display.
# PrusaSlicer's CLI exports it solid and hollowed (walls of 2 mm, its 2 mm closing distance and
# quality 0.5; supports and pad off); its hollowing costs the difference in CPU seconds (user +
# system, medians). Then bench_hollowing (one thread) gives what hollowing, draining and
# labelling add to our job. Prints both and the ratio.
# Needs PrusaSlicer (Debian's prusa-slicer, which scripts/setup installs) and build/2020.
# bench/RESULTS.md runs it with TMPDIR=/dev/shm: masks written to a disk's folder just emptied
# cost the job a varying 0.1-0.8 s of creating files ("Hollowing" there).
#   bench/bench_hollowing_prusa.sh [--faces N] [--runs R]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
faces=200000 runs=3
while [ $# -gt 0 ]; do
  case "$1" in
    --faces) faces=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    *) echo "usage: bench/bench_hollowing_prusa.sh [--faces N] [--runs R]" >&2; exit 2 ;;
  esac
done
. "$root/bench/prusaslicer_part.sh"
prusaslicer_part sphere "$faces" 35

cpu() {  # median CPU seconds (user + system) of running "$@" $runs times
  for _ in $(seq "$runs"); do
    /usr/bin/time -f "%U %S" -o t.txt "$@" >/dev/null 2>&1
    awk '{print $1 + $2}' t.txt
  done | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}
sla=(prusa-slicer --export-sla --printer-technology SLA --layer-height 0.05 --initial-layer-height 0.05
     --display-pixels-x 1620 --display-pixels-y 2560 --display-width 81 --display-height 128
     --display-orientation portrait --no-supports-enable --no-pad-enable)
solid=$(cpu "${sla[@]}" -o solid.sl1 part.stl)
hollow=$(cpu "${sla[@]}" --hollowing-enable --hollowing-min-thickness 2 --hollowing-closing-distance 2 \
  --hollowing-quality 0.5 -o hollow.sl1 part.stl)
ps=$(echo "$hollow - $solid" | bc)
ours=$(OMP_NUM_THREADS=1 TMPDIR=${TMPDIR:-/tmp} "$root/build/2020/bench/bench_hollowing" --faces "$faces" \
  --runs "$runs" --wall 2 --closing 2 | tee bench.txt | sed -n 's/.*the three add [0-9.]* s (CPU \([0-9.]*\)).*/\1/p')
echo "part: sphere, $faces faces, 35 mm, 700 layers of 0.05 mm; walls 2 mm, closing 2 mm; CPU seconds, median of $runs"
cat bench.txt
printf "%-52s %8.2f\n" "PrusaSlicer: solid export" "$solid" "PrusaSlicer: hollowed export" "$hollow" \
  "PrusaSlicer: its hollowing (the difference)" "$ps" "ours: hollowing, draining and labelling the job" "$ours"
echo "ratio: $(echo "scale=1; $ps / $ours" | bc)x"
