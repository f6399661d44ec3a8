#!/usr/bin/env bash
# The family benchmark: the method's Table 1 (Model, Size, #L, T_slice, T_S2I, T_reuse) for the
# product's own pipeline (examples/family.py's code, pymeshlab), extended with PrusaSlicer,
# both of our paths end to end, their ratios, peak memory and members per hour; in one run.
#
#   bench/bench_family.sh [--faces 545000] [--thickness 0.001] [--members 4] [--out DIR]
#                         [--skip-prusa] [--prusa-thickness MM]
#
# Workload: gen_family's arch (14.484 mm tall), member 0 the source, --members members that
# differ in x-y (same connectivity) and three that also changed in z; masks 1024x768 at 75 um into
# one .sl1 per member. Runs the family pipeline twice, as family.py does: reuse (default) and
# --direct, each under /usr/bin/time for its peak memory; then PrusaSlicer (bench_prusaslicer.sh)
# on one member, at --prusa-thickness (default: --thickness; at 1 um PrusaSlicer takes minutes,
# so --prusa-thickness 0.01 with its time scaled by the layer ratio is offered, and marked so),
# unless --skip-prusa or PrusaSlicer is missing.
#   T_slice  direct slicing of a member in memory (median over the x-y members)
#   T_S2I    its masks into an .sl1 (slice to image; median over the x-y members, reuse run)
#   T_reuse  exact transfer from the cached encoding (median over the x-y members)
#   direct / reuse: seconds per member everything included (load, slicing or transfer, .sl1),
#   median over the x-y members; z: the members changed in z (median), reuse against direct.
#   CPU: the same spans in CPU seconds of all threads; on a busy shared machine their ratio is
#   the steadier one (wall seconds on 2 idle cores are about CPU / 2 for the parallel parts).
#   S: each member's reused .sl1 against its direct one (1 when every layer image is the same bytes).
# Prints the table and writes it to DIR/bench_family.md, the raw JSON next to it, and a chart
# to docs/bench_family.png (gnuplot). Unattended; needs scripts/setup and scripts/build first.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
faces=545000 thickness=0.001 members=4 out="$root/out/bench_family" skip_prusa=0 prusa_thickness=""
while [ $# -gt 0 ]; do
  case "$1" in
    --faces) faces=$2; shift 2 ;;
    --thickness) thickness=$2; shift 2 ;;
    --members) members=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --skip-prusa) skip_prusa=1; shift ;;
    --prusa-thickness) prusa_thickness=$2; shift 2 ;;
    *) sed -n '5,6p' "$0" >&2; exit 2 ;;
  esac
done
prusa_thickness=${prusa_thickness:-$thickness}
[ -x /usr/bin/time ] || { echo "bench_family: /usr/bin/time is missing (scripts/setup installs it)" >&2; exit 1; }
rm -rf "$out" && mkdir -p "$out"

"$root/build/2020/tools/gen_family" --shape arch --faces "$faces" --members "$((members + 1))" --height 14.484 \
  --seed 1 --out "$out/family" >/dev/null
"$root/build/2020/tools/gen_family" --shape arch --faces "$faces" --members 4 --height 14.484 --seed 2 \
  --z-change --out "$out/family_z" >/dev/null
for i in 1 2 3; do mv "$out/family_z/member_00$i.ply" "$out/family/member_z0$i.ply"; done
rm -rf "$out/family_z"

# run NAME ARGS: the pipeline (family() with per-filter details) under /usr/bin/time.
run() {
  local name=$1; shift
  /usr/bin/time -f '%M' -o "$out/$name.maxrss" "$root/scripts/python" - "$@" >"$out/$name.json" <<'PY'
import json, sys
import slicereuse_pymeshlab as sr
thickness, out, mode, *meshes = sys.argv[1:]
print(json.dumps(sr.family(meshes[0], meshes[1:], float(thickness), out, direct=mode == "direct",
                           details=True, extension=".sl1")))
PY
}
meshes=("$out"/family/member_*.ply)
run reuse "$thickness" "$out/reuse" reuse "${meshes[@]}"
run direct "$thickness" "$out/direct" direct "${meshes[@]}"

prusa="" prusa_note=""
if [ "$skip_prusa" = 0 ] && command -v prusa-slicer >/dev/null; then
  "$root/bench/bench_prusaslicer.sh" --faces "$faces" --thickness "$prusa_thickness" --runs 1 >"$out/prusa.txt"
  prusa=$(awk '/^PrusaSlicer/ {print $(NF)}' "$out/prusa.txt")
  prusa_note="at $prusa_thickness mm"
else
  prusa_note="skipped"
fi

"$root/scripts/python" - "$out" "$faces" "$thickness" "$prusa" "$prusa_thickness" "$prusa_note" "$root/docs" <<'PY'
import json, statistics, subprocess, sys, zipfile
from pathlib import Path
out, faces, thickness, prusa, prusa_thickness, prusa_note, docs = sys.argv[1:]
out, thickness, prusa_thickness = Path(out), float(thickness), float(prusa_thickness)
runs = {k: json.loads((out / f"{k}.json").read_text()) for k in ("reuse", "direct")}
rss = {k: int((out / f"{k}.maxrss").read_text().split()[-1]) / 1e6 for k in runs}  # KB -> GB
def rows(kind, z):
    return [t for t in runs[kind]["targets"] if ("member_z" in t["mesh"]) == z]
med = lambda kind, key, z=False: statistics.median(t[key] for t in rows(kind, z))
layers = rows("reuse", False)[0]["layers"]
t_slice, t_s2i, t_reuse = med("direct", "slicing_seconds"), med("reuse", "masks_seconds"), med("reuse", "slicing_seconds")
direct, reuse = med("direct", "seconds"), med("reuse", "seconds")
cpu_direct, cpu_reuse = med("direct", "cpu_seconds"), med("reuse", "cpu_seconds")
z_direct, z_reuse = med("direct", "seconds", True), med("reuse", "seconds", True)
ps = None
if prusa:
    ps = float(prusa) * (prusa_thickness / thickness)  # layer count scales as 1 / thickness
    if prusa_thickness != thickness:
        prusa_note += f", scaled x{prusa_thickness / thickness:g} to {thickness} mm"
fmt = lambda x, d=2: "-" if x is None else f"{x:.{d}f}"


def similarity(a, b):
    """S of two .sl1 archives: 1 when every layer's PNG is the same bytes (cheap), otherwise
    compare_mask_stacks' smallest per-layer S."""
    with zipfile.ZipFile(a) as za, zipfile.ZipFile(b) as zb:
        # The layers: the PNGs at the root (the thumbnails are in thumbnail/).
        layers = lambda z: [z.read(n) for n in sorted(n for n in z.namelist() if n.endswith(".png") and "/" not in n)]
        if layers(za) == layers(zb):
            return "1 (identical)"
    import slicereuse_pymeshlab as sr
    ms = sr.load().MeshSet()
    return f"{ms.apply_filter('compare_mask_stacks', stack_a=a, stack_b=b, report_file='')['min_similarity']:.6f}"


head = ["Model", "Size (faces)", "#L", "T_slice (s)", "T_S2I (s)", "T_reuse (s)",
        "PrusaSlicer (s/member)", "direct (s/member)", "reuse (s/member)", "direct / reuse",
        "PrusaSlicer / reuse", "CPU s/member direct / reuse", "z member: reuse / direct", "peak memory reuse / direct (GB)",
        "members per hour (reuse)"]
row = ["arch (gen_family)", f"{int(faces):,}", str(layers), fmt(t_slice), fmt(t_s2i), fmt(t_reuse),
       fmt(ps, 1), fmt(direct), fmt(reuse), f"{direct / reuse:.2f}x", "-" if ps is None else f"{ps / reuse:.0f}x",
       f"{cpu_direct:.2f} / {cpu_reuse:.2f} ({cpu_direct / cpu_reuse:.2f}x)",
       f"{z_reuse / z_direct:.2f}x", f"{rss['reuse']:.1f} / {rss['direct']:.1f}", f"{3600 / reuse:.0f}"]
md = [f"Family benchmark: arch, {int(faces):,} faces, 14.484 mm at {thickness} mm, .sl1 1024x768 at 75 um; "
      f"{len(rows('reuse', False))} x-y members and {len(rows('reuse', True))} changed in z; medians over each kind; "
      f"PrusaSlicer {prusa_note}.", "",
      "| " + " | ".join(head) + " |", "|" + "---|" * len(head), "| " + " | ".join(row) + " |", "",
      "Per member (seconds, everything included; S: the reused .sl1 against the direct one, the "
      "smallest over its layers):", "",
      "| member | layers | points | re-sliced | reuse | direct | reuse CPU | direct CPU | S |",
      "|---|---|---|---|---|---|---|---|---|"]
for r, d in zip(runs["reuse"]["targets"], runs["direct"]["targets"]):
    md.append(f"| {Path(r['mesh']).name} | {r['layers']} | {r['points']} | {r['resliced_layers']} | "
              f"{r['seconds']:.2f} | {d['seconds']:.2f} | {r['cpu_seconds']:.2f} | {d['cpu_seconds']:.2f} | "
              f"{similarity(r['output'], d['output'])} |")
text = "\n".join(md) + "\n"
(out / "bench_family.md").write_text(text)
print(text)
# The chart: seconds per member of each path, wall and CPU (all threads; steadier on a busy
# machine); log scale, as PrusaSlicer takes minutes.
bars = [("PrusaSlicer", ps, None), ("slicereuse direct", direct, cpu_direct), ("slicereuse reuse", reuse, cpu_reuse)]
bars = [b for b in bars if b[1] is not None]
data = out / "chart.dat"
data.write_text("".join(f'{i} "{n}" {w} {"NaN" if c is None else c}\n' for i, (n, w, c) in enumerate(bars)))
low = min(v for _, w, c in bars for v in (w, c) if v is not None) / 3
png = Path(docs) / "bench_family.png"
script = f"""set terminal pngcairo size 800,420 font ',11'
set output '{png}'
set title "One .sl1 per family member: arch, {int(faces):,} faces, {layers} layers, 1024x768"
set ylabel 'seconds per member (log scale)'
set logscale y
set yrange [{low:.3g}:*]
set xrange [-0.6:{len(bars) - 0.4}]
set style fill solid 0.8
set boxwidth 0.36
set grid ytics
set key top right
plot '{data}' using ($1-0.19):3:xtic(2) with boxes lc rgb '#3a7dc9' title 'wall', \\
     '' using ($1-0.19):3:(sprintf('%.2f', $3)) with labels offset 0,0.8 notitle, \\
     '' using ($1+0.19):4 with boxes lc rgb '#e08a2c' title 'CPU (all threads)', \\
     '' using ($1+0.19):4:(sprintf('%.2f', $4)) with labels offset 0,0.8 notitle
"""
subprocess.run(["gnuplot"], input=script, text=True, check=True)
print(f"chart: {png}")
PY
