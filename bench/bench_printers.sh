#!/usr/bin/env bash
# Real printers against PrusaSlicer 2.5, in one run: per printer profile, the seconds per member
# and the print file's size of the family pipeline (examples/family.py's code, pymeshlab) by
# reuse and by direct slicing, anti-aliased at gamma 1, and PrusaSlicer's --export-sla of the
# same member for the same display (gamma 1, supports and pad off).
#
#   bench/bench_printers.sh [--faces 545000] [--thickness 0.05] [--members 3] [--runs 3]
#                           [--printers "prusa_sl1s_speed:sl1s elegoo_saturn_3_ultra:goo"] [--out DIR]
#
# Each entry of --printers is a preset id and our print file for it; ours is also written as .sl1
# when that is another format, so that both tools write the same kind of file once. PrusaSlicer
# gets the display exactly as our archive's prusaslicer.ini gives it (pixels, size, orientation,
# mirrors), so the presets stay written in one place (printer_presets.cpp).
# Columns: seconds per member (median over the members; load, slicing or transfer, masks and
# file, everything included; PrusaSlicer: median of --runs runs of its command line, start-up
# included), MB of one member's file, and PrusaSlicer's seconds over ours.
# Needs PrusaSlicer (scripts/setup installs it), scripts/setup and scripts/build first.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
faces=545000 thickness=0.05 members=3 runs=3 out="$root/out/bench_printers"
printers="prusa_sl1s_speed:sl1s elegoo_saturn_3_ultra:goo"
while [ $# -gt 0 ]; do
  case "$1" in
    --faces) faces=$2; shift 2 ;;
    --thickness) thickness=$2; shift 2 ;;
    --members) members=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --printers) printers=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) sed -n '7,8p' "$0" >&2; exit 2 ;;
  esac
done
command -v prusa-slicer >/dev/null || { echo "prusa-slicer is not installed (scripts/setup installs it)" >&2; exit 1; }
rm -rf "$out" && mkdir -p "$out"
"$root/build/2020/tools/gen_family" --shape arch --faces "$faces" --members "$((members + 1))" --height 14.484 \
  --seed 1 --out "$out/family" >/dev/null
"$root/scripts/meshlabserver" -i "$out/family/member_001.ply" -o "$out/member_001.stl" >/dev/null 2>&1
mapfile -t meshes < <(ls "$out"/family/member_*.ply)

seconds() {  # median wall seconds of running "$@" $runs times
  for _ in $(seq "$runs"); do
    s=$(date +%s.%N); "$@" >/dev/null 2>&1; e=$(date +%s.%N)
    echo "$e - $s" | bc
  done | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}
family() {  # family.py run: $1 out folder, $2 printer id, $3 format, then extra flags
  local dir=$1 printer=$2 format=$3; shift 3
  "$root/scripts/python" "$root/examples/family.py" --layer-thickness "$thickness" --out "$dir" \
    --printer "$printer" --antialiasing --gamma 1 --format "$format" "$@" "${meshes[@]}" > "$dir.json"
}
ini() { unzip -p "$1" prusaslicer.ini | sed -n "s/^$2 = //p"; }

report="$out/bench_printers.md"
{
  echo "arch, $faces faces, 14.484 mm, layers $thickness mm, anti-aliased (gamma 1); $members members; $(nproc) cores"
  echo
  echo "| printer | file | reuse s/member | direct s/member | PrusaSlicer s | PrusaSlicer / reuse | MB ours | MB PrusaSlicer |"
  echo "|---|---|---|---|---|---|---|---|"
} > "$report"
for entry in $printers; do
  printer=${entry%%:*} format=${entry#*:}
  formats=$format  # .sl1 and .sl1s are one format; another one is also written as .sl1
  case "$format" in sl1|sl1s) ;; *) formats="$format sl1" ;; esac
  for f in $formats; do
    family "$out/$printer.$f.reuse" "$printer" "$f"
    family "$out/$printer.$f.direct" "$printer" "$f" --direct
  done
  # PrusaSlicer with our display, from our own archive of member 1.
  ours_sl1=$(ls "$out/$printer".sl1*.reuse/member_001.sl1*)
  mirror_x=$([ "$(ini "$ours_sl1" display_mirror_x)" = 1 ] && echo --display-mirror-x || echo --no-display-mirror-x)
  mirror_y=$([ "$(ini "$ours_sl1" display_mirror_y)" = 1 ] && echo --display-mirror-y || echo --no-display-mirror-y)
  ps=$(seconds prusa-slicer --export-sla --printer-technology SLA --layer-height "$thickness" \
    --initial-layer-height "$thickness" --display-pixels-x "$(ini "$ours_sl1" display_pixels_x)" \
    --display-pixels-y "$(ini "$ours_sl1" display_pixels_y)" --display-width "$(ini "$ours_sl1" display_width)" \
    --display-height "$(ini "$ours_sl1" display_height)" \
    --display-orientation "$(ini "$ours_sl1" display_orientation)" "$mirror_x" "$mirror_y" \
    --bed-shape "$(ini "$ours_sl1" bed_shape)" --gamma-correction 1 --no-supports-enable --no-pad-enable \
    --elefant-foot-compensation 0 -o "$out/$printer.prusaslicer.sl1" "$out/member_001.stl")
  for f in $formats; do
    "$root/scripts/python" - "$out/$printer.$f.reuse.json" "$out/$printer.$f.direct.json" "$ps" \
      "$out/$printer.prusaslicer.sl1" \
      "$printer" "$f" >> "$report" <<'PY'
import json, os, statistics, sys
reuse, direct = (json.load(open(p)) for p in sys.argv[1:3])
ps, ps_mb, printer, fmt = float(sys.argv[3]), os.path.getsize(sys.argv[4]) / 1e6, sys.argv[5], sys.argv[6]
r = statistics.median(t["seconds"] for t in reuse["targets"])
d = statistics.median(t["seconds"] for t in direct["targets"])
path = reuse["targets"][0]["output"]
mb = os.path.getsize(path) / 1e6
same = fmt in ("sl1", "sl1s")
print(f"| {printer} | .{fmt} | {r:.2f} | {d:.2f} | {ps:.1f}{'' if same else ' (.sl1)'} | "
      f"{ps / r:.0f}x | {mb:.1f} | {f'{ps_mb:.1f}' if same else '-'} |")
PY
  done
done
cat "$report"
