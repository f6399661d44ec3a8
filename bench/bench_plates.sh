#!/usr/bin/env bash
# A plate of family members (issue #17): bench_plates arranges 20 members of the generated arch
# family on plates of a printer and times the first plate by reuse and by direct slicing, then
# PrusaSlicer slices the same arranged plate (the placed members as one STL, kept where they are
# placed: --dont-arrange) into an .sl1 for the same display and layer height, one run.
#   bench/bench_plates.sh [--printer ID] [--faces N] [--thickness MM] [--members M] [--format EXT]
# (--format: our print file's extension, bench_plates' option; PrusaSlicer writes an .sl1.)
# Needs PrusaSlicer (apt-get install prusa-slicer) for its line; without it, that line is skipped.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
printer=prusa_sl1s_speed faces=545000 thickness=0.05 members=20 format=()
while [ $# -gt 0 ]; do
  case "$1" in
    --printer) printer=$2; shift 2 ;;
    --faces) faces=$2; shift 2 ;;
    --thickness) thickness=$2; shift 2 ;;
    --members) members=$2; shift 2 ;;
    --format) format=(--format "$2"); shift 2 ;;
    *) echo "usage: bench/bench_plates.sh [--printer ID] [--faces N] [--thickness MM] [--members M] [--format EXT]" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$root/build/2020/bench/bench_plates" --printer "$printer" --faces "$faces" --thickness "$thickness" \
  --members "$members" "${format[@]}" --out "$work" | tee "$work/ours.txt"
if ! command -v prusa-slicer >/dev/null; then
  echo "PrusaSlicer: not installed (apt-get install prusa-slicer)"
  exit 0
fi
s=$(date +%s.%N)
# shellcheck disable=SC2046  # the display options are words
prusa-slicer --export-sla --printer-technology SLA --layer-height "$thickness" --initial-layer-height "$thickness" \
  $(cat "$work/prusa_display_args") --no-supports-enable --no-pad-enable --dont-arrange \
  -o "$work/ps.sl1" "$work/plate_1.stl" >/dev/null 2>&1
e=$(date +%s.%N)
ps=$(echo "$e - $s" | bc)
ps_layers=$(unzip -l "$work/ps.sl1" | grep -c '[0-9]\.png$')
reuse=$(awk '$1 == "1" {print $5}' "$work/ours.txt")
printf "PrusaSlicer %s, the same plate: %s layers, %.2f s (one run); reuse is %.1fx faster\n" \
  "$(prusa-slicer --help 2>/dev/null | grep -o 'PrusaSlicer-[0-9.]*' | head -n1)" "$ps_layers" "$ps" \
  "$(echo "scale=3; $ps / $reuse" | bc)"
