#!/usr/bin/env bash
# Plates of family members (issue #17): bench_plates arranges 20 members of the generated arch
# family on plates of a printer and times every plate by reuse and by direct slicing, then
# PrusaSlicer slices the same arranged plates (each plate's placed members as one STL, kept where
# they are placed: --dont-arrange) into an .sl1 for the same display and layer height, one run
# per plate: each plate's ratio, and all of them together (the lab's job, plate after plate).
# Ours is timed three times, before, between and after PrusaSlicer's runs (a minute or more of
# them), and each plate's ratio takes the median of the three: a shared machine's speed drifts
# within minutes, and one pass before all of PrusaSlicer's runs would measure the drift too
# (bench/RESULTS.md, "Method").
#   bench/bench_plates.sh [--printer ID] [--faces N] [--thickness MM] [--members M] [--format EXT]
#                         [--prusa-plates P]
# (--format: our print file's extension, bench_plates' option; PrusaSlicer writes an .sl1.
# --prusa-plates: PrusaSlicer on the first P plates only, default all; at 1 um one plate takes it
# two minutes.) Needs PrusaSlicer (apt-get install prusa-slicer) for its lines; without it, they
# are skipped.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
printer=prusa_sl1s_speed faces=545000 thickness=0.05 members=20 format=() prusa_plates=1000
usage="usage: bench/bench_plates.sh [--printer ID] [--faces N] [--thickness MM] [--members M] [--format EXT] [--prusa-plates P]"
while [ $# -gt 0 ]; do
  case "$1" in
    --printer) printer=$2; shift 2 ;;
    --faces) faces=$2; shift 2 ;;
    --thickness) thickness=$2; shift 2 ;;
    --members) members=$2; shift 2 ;;
    --format) format=(--format "$2"); shift 2 ;;
    --prusa-plates) prusa_plates=$2; shift 2 ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v prusa-slicer >/dev/null || prusa_plates=0
# ours PASS [STL_PLATES]: one pass of bench_plates, its output in $work/ours_PASS.txt.
ours() {
  "$root/build/2020/bench/bench_plates" --printer "$printer" --faces "$faces" --thickness "$thickness" \
    --members "$members" "${format[@]}" --stl-plates "${2:-0}" --out "$work" > "$work/ours_$1.txt"
}
ours 1 "$prusa_plates"
cat "$work/ours_1.txt"
if [ "$prusa_plates" = 0 ]; then
  echo "PrusaSlicer: not installed (apt-get install prusa-slicer)"
  exit 0
fi
version=$(prusa-slicer --help 2>/dev/null | grep -o 'PrusaSlicer-[0-9.]*' | head -n1)
stls=$(ls "$work"/plate_*.stl | sort -V)
half=$(( ($(echo "$stls" | wc -l) + 1) / 2 ))
declare -A ps_seconds ps_layer_count
for stl in $stls; do
  k=$(basename "$stl" .stl | sed 's/plate_//')
  [ "$k" = "$((half + 1))" ] && ours 2
  s=$(date +%s.%N)
  # shellcheck disable=SC2046  # the display options are words
  prusa-slicer --export-sla --printer-technology SLA --layer-height "$thickness" --initial-layer-height "$thickness" \
    $(cat "$work/prusa_display_args") --no-supports-enable --no-pad-enable --dont-arrange \
    -o "$work/ps.sl1" "$stl" >/dev/null 2>&1
  e=$(date +%s.%N)
  ps_seconds[$k]=$(echo "$e - $s" | bc)
  ps_layer_count[$k]=$(unzip -l "$work/ps.sl1" | grep -c '[0-9]\.png$')
  rm -f "$work/ps.sl1" "$stl"
done
[ -f "$work/ours_2.txt" ] || ours 2
ours 3
ours_total=0 ps_total=0 plates=0
for k in $(echo "${!ps_seconds[@]}" | tr ' ' '\n' | sort -n); do
  ps=${ps_seconds[$k]}
  n=$(awk -v k="$k" '$1 == k {print $2}' "$work/ours_1.txt")
  read -r a b c < <(for pass in 1 2 3; do awk -v k="$k" '$1 == k {print $5}' "$work/ours_$pass.txt"; done | tr '\n' ' '; echo)
  reuse=$(printf "%s\n%s\n%s\n" "$a" "$b" "$c" | sort -g | sed -n 2p)
  printf "%s, plate %s (%s members): %s layers, %.2f s (one run); reuse %.3f s (median of %s, %s, %s) is %.1fx faster\n" \
    "$version" "$k" "$n" "${ps_layer_count[$k]}" "$ps" "$reuse" "$a" "$b" "$c" "$(echo "scale=3; $ps / $reuse" | bc)"
  ours_total=$(echo "$ours_total + $reuse" | bc)
  ps_total=$(echo "$ps_total + $ps" | bc)
  plates=$((plates + 1))
done
printf "These %s plates together: PrusaSlicer %.2f s, reuse %.2f s: %.1fx faster\n" "$plates" "$ps_total" "$ours_total" \
  "$(echo "scale=3; $ps_total / $ours_total" | bc)"
