#!/usr/bin/env bash
# PrusaSlicer against slicereuse on the same job, in the same run: a generated part (default the
# 545k-face arch, 14.484 mm tall) sliced at the same layer height into a .sl1 archive for the
# same display (1024x768 pixels at 75 um). PrusaSlicer runs its CLI (supports and pad off);
# slicereuse runs meshlabserver with "Make Print Job" (direct slicing and masks, in memory),
# start-up and mesh loading included. Prints the median seconds of each and the ratio.
# Needs PrusaSlicer (Debian's prusa-slicer, which scripts/setup installs; bench_family.sh runs
# this when it is there).
#   bench/bench_prusaslicer.sh [--faces N] [--thickness MM] [--runs R]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
faces=545000 thickness=0.01 runs=3
while [ $# -gt 0 ]; do
  case "$1" in
    --faces) faces=$2; shift 2 ;;
    --thickness) thickness=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    *) echo "usage: bench/bench_prusaslicer.sh [--faces N] [--thickness MM] [--runs R]" >&2; exit 2 ;;
  esac
done
. "$root/bench/prusaslicer_part.sh"
prusaslicer_part arch "$faces" 14.484

# One filter: Make Print Job, slicing directly (no encoding file) into an .sl1 archive in memory.
sed -e "s/name=\"layer_thickness\" value=\"[^\"]*\"/name=\"layer_thickness\" value=\"$thickness\"/" \
    -e 's#name="encoding_file" value="[^"]*"#name="encoding_file" value=""#' \
    -e 's#name="output_path" value="[^"]*"#name="output_path" value="ours.sl1"#' "$root/examples/print_job.mlx" > job.mlx

seconds() {  # median wall seconds of running "$@" $runs times
  for _ in $(seq "$runs"); do
    s=$(date +%s.%N); "$@" >/dev/null 2>&1; e=$(date +%s.%N)
    echo "$e - $s" | bc
  done | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}
ps=$(seconds prusa-slicer --export-sla --printer-technology SLA --layer-height "$thickness" \
  --initial-layer-height "$thickness" --display-pixels-x 1024 --display-pixels-y 768 --display-width 76.8 \
  --display-height 57.6 --display-orientation landscape --no-supports-enable --no-pad-enable -o ps.sl1 part.stl)
ours=$(seconds "$root/scripts/meshlabserver" -i member_000.ply -s job.mlx)
# The layers: the numbered PNGs at the archive's root (ours also has thumbnail/*.png).
ps_layers=$(unzip -Z1 ps.sl1 | grep -c '^[^/]*[0-9]\.png$')
our_layers=$(unzip -Z1 ours.sl1 | grep -c '^[^/]*[0-9]\.png$')
echo "part: arch, $faces faces, 14.484 mm; layers ${thickness} mm; .sl1 for 1024x768 at 75 um; median of $runs"
printf "%-28s %8s %8s\n" "" layers seconds
printf "%-28s %8s %8.2f\n" "PrusaSlicer $(prusa-slicer --help 2>/dev/null | grep -o 'PrusaSlicer-[0-9.]*' | head -n1)" "$ps_layers" "$ps"
printf "%-28s %8s %8.2f\n" "slicereuse (meshlabserver)" "$our_layers" "$ours"
echo "ratio: $(echo "scale=1; $ps / $ours" | bc)x"
