#!/usr/bin/env bash
# PrusaSlicer's hollowing against ours, in the same run, on the same part (#36): a generated
# sphere 35 mm tall (the part bench_hollowing makes) at 0.05 mm layers on the SL1S's display.
# PrusaSlicer's CLI exports it solid and hollowed (walls of 2 mm, its 2 mm closing distance and
# quality 0.5; supports and pad off); its hollowing costs the difference in CPU seconds (user +
# system, medians). Then bench_hollowing (one thread) gives what hollowing, draining and
# labelling add to our job, and the same as whole processes of meshlabserver's Make Print Job.
# Prints each, the ratios, and the resin each saves.
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
material() { unzip -p "$1" config.ini | sed -n 's/^usedMaterial = //p'; }  # ml, from its layers' areas
ps_saved=$(echo "scale=4; 100 * (1 - $(material hollow.sl1) / $(material solid.sl1))" | bc)
ours=$(OMP_NUM_THREADS=1 TMPDIR=${TMPDIR:-/tmp} "$root/build/2020/bench/bench_hollowing" --faces "$faces" \
  --runs "$runs" --wall 2 --closing 2 | tee bench.txt | sed -n 's/.*the three add [0-9.]* s (CPU \([0-9.]*\)).*/\1/p')
# The product's own command, a process each, as PrusaSlicer's: meshlabserver's Make Print Job on
# the same STL (sliced directly, the SL1S SPEED's .sl1s, no check), solid and then hollowed,
# drained and labelled on its front (its name; none fits a sphere, so this is the attempt).
job() {
  sed -e 's#name="encoding_file" value="[^"]*"#name="encoding_file" value=""#' \
      -e 's/name="layer_thickness" value="[^"]*"/name="layer_thickness" value="0.05"/' \
      -e 's/name="check_printability" value="[^"]*"/name="check_printability" value="false"/' \
      -e 's/name="printer" value="[^"]*"/name="printer" value="2"/' \
      -e 's#name="output_path" value="[^"]*"#name="output_path" value="ours.sl1s"#' "$@" "$root/examples/print_job.mlx"
}
job > solid.mlx
job -e 's/name="hollow_wall_mm" value="[^"]*"/name="hollow_wall_mm" value="2"/' \
    -e 's/name="labels" value="[^"]*"/name="labels" value="true"/' \
    -e 's/name="label_side" value="[^"]*"/name="label_side" value="1"/' \
    -e 's/name="label_depth_mm" value="[^"]*"/name="label_depth_mm" value="1"/' \
    -e 's/name="allow_unlabelled" value="[^"]*"/name="allow_unlabelled" value="true"/' > hollow.mlx
our_solid=$(OMP_NUM_THREADS=1 cpu "$root/scripts/meshlabserver" -i part.stl -s solid.mlx)
our_hollow=$(OMP_NUM_THREADS=1 cpu "$root/scripts/meshlabserver" -i part.stl -s hollow.mlx)
ours_process=$(echo "$our_hollow - $our_solid" | bc)
echo "part: sphere, $faces faces, 35 mm, 700 layers of 0.05 mm; walls 2 mm, closing 2 mm; CPU seconds, median of $runs"
cat bench.txt
printf "%-52s %8.2f\n" "PrusaSlicer: solid export" "$solid" "PrusaSlicer: hollowed export" "$hollow" \
  "PrusaSlicer: its hollowing (the difference)" "$ps" "ours: hollowing, draining and labelling the job" "$ours"
echo "ratio: $(echo "scale=1; $ps / $ours" | bc)x"
printf "%-52s %8.2f\n" "ours, meshlabserver: solid job" "$our_solid" "ours, meshlabserver: hollowed, drained, labelled" \
  "$our_hollow" "ours, meshlabserver: the difference" "$ours_process"
echo "ratio, whole processes: $(echo "scale=1; $ps / $ours_process" | bc)x"
printf "resin saved: PrusaSlicer %.1f %% (its archives' usedMaterial), ours %s (the cavity's share of the part)\n" \
  "$ps_saved" "$(awk 'NR == 3 {print $6}' bench.txt)"
