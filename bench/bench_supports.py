"""Supported print files against PrusaSlicer 2.5, in one run (issue #30): per member of a family
that needs supports, PrusaSlicer's --export-sla with supports and pad (its own SL1S SPEED profile
at the layer height) against ours by reuse (family.py --supports: the source's support points
generated once, transferred to each member, certified and completed, the member's supports built,
everything printed into one .sl1s), and ours generated per member (--supports --direct).

    scripts/python bench/bench_supports.py [--shape ear] [--tilt 60] [--faces 200000]
        [--height 8.8] [--members 3] [--thickness 0.05] [--runs 3] [--out DIR]

Columns per member: PrusaSlicer's seconds with supports and pad and without (their difference is
its support time), ours by reuse (load, transfer, support points and tree, masks and .sl1s:
everything) and ours with points generated on the member, PrusaSlicer over ours by reuse, the
share of ours spent on the member's supports (transfer and tree), and resin: the cured volume of
the whole stack (the sum of every layer's grey levels / 255 x pixel area x layer height) of ours
over PrusaSlicer's. Then the source's support point generation against PrusaSlicer's support
time, and each member's points kept, moved, added and dropped. Medians of --runs runs; ours
in this process (family.py --workers 0). Needs PrusaSlicer (scripts/setup installs it),
scripts/setup and scripts/build first.
"""
import argparse
import json
import shutil
import statistics
import subprocess
import time
from pathlib import Path

import slicereuse_pymeshlab as sr
from slicereuse_prusaslicer import SL1S, prusaslicer_config, resin_mm3, write_config

ROOT = Path(__file__).resolve().parent.parent
PRINTER, PRESET = SL1S, "prusa_sl1s_speed"


def median_seconds(runs, job):
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        job()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--shape", default="ear")
    ap.add_argument("--tilt", type=float, default=60)
    ap.add_argument("--faces", type=int, default=200000)
    ap.add_argument("--height", type=float, default=8.8)
    ap.add_argument("--members", type=int, default=3)
    ap.add_argument("--thickness", type=float, default=0.05)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--out", type=Path, default=ROOT / "out" / "bench_supports")
    a = ap.parse_args()
    if shutil.which("prusa-slicer") is None:
        raise SystemExit("prusa-slicer is not installed (scripts/setup installs it)")
    pymeshlab = sr.load()
    shutil.rmtree(a.out, ignore_errors=True)
    a.out.mkdir(parents=True)
    subprocess.run([str(ROOT / "build/2020/tools/gen_family"), "--shape", a.shape, "--faces", str(a.faces),
                    "--members", str(a.members + 1), "--height", str(a.height), "--tilt", str(a.tilt),
                    "--seed", "1", "--out", str(a.out / "family")], check=True, capture_output=True)
    meshes = sorted(str(p) for p in (a.out / "family").glob("member_*.ply"))
    source, members = meshes[0], meshes[1:]

    # PrusaSlicer: its SL1S profile as its GUI combines it, at our layer height; with supports and
    # pad (its defaults) and without.
    config = prusaslicer_config(PRINTER, layer_height=str(a.thickness), initial_layer_height=str(a.thickness))
    write_config(a.out / "supported.ini", config)
    write_config(a.out / "unsupported.ini", {**config, "supports_enable": "0", "pad_enable": "0"})
    pixel_mm2 = float(config["display_width"]) / int(config["display_pixels_x"]) * \
        float(config["display_height"]) / int(config["display_pixels_y"])
    ps = {}
    for mesh in members:
        stl = Path(mesh).with_suffix(".stl")
        ms = pymeshlab.MeshSet()
        ms.load_new_mesh(mesh)
        ms.save_current_mesh(str(stl))
        row = {}
        for kind in ("supported", "unsupported"):
            out = a.out / f"ps_{kind}_{stl.stem}.sl1s"
            cmd = ["prusa-slicer", "--export-sla", "--load", str(a.out / f"{kind}.ini"), "-o", str(out), str(stl)]
            row[kind] = median_seconds(a.runs, lambda: subprocess.run(cmd, check=True, capture_output=True))
        row["resin"] = resin_mm3(a.out / f"ps_supported_{stl.stem}.sl1s", pixel_mm2, a.thickness)
        ps[mesh] = row

    # Ours: the source's points alone (the filter, as family.py runs it), then the batches.
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(source)
    generate = median_seconds(a.runs, lambda: ms.apply_filter(
        "generate_support_points", layer_thickness=a.thickness, support_points_file=str(a.out / "src.srp")))
    profile = {"printer": PRESET}
    runs = {"reuse": [], "direct": []}
    for _ in range(a.runs):
        for way in runs:
            runs[way].append(sr.family(source, members, a.thickness, str(a.out / way), profile=profile,
                                       details=True, supports=True, direct=way == "direct"))
    ours = {way: {m: {"seconds": statistics.median(r["targets"][i]["seconds"] for r in rs),
                      "support_seconds": statistics.median(r["targets"][i]["support_seconds"] for r in rs),
                      "entry": rs[-1]["targets"][i]}
                  for i, m in enumerate(members)} for way, rs in runs.items()}

    lines = [f"{a.shape} tilted {a.tilt:g} deg, {a.faces} faces, {a.height:g} mm, {a.thickness:g} mm layers, "
             f"{PRINTER} (.sl1s, supports and pad); median of {a.runs} runs, seconds per member",
             f"{'member':<12}{'PS supp.':>9}{'PS none':>9}{'ours':>8}{'ours gen.':>10}{'PS/ours':>9}"
             f"{'supports':>10}{'resin':>8}"]
    for m in members:
        p, o, g = ps[m], ours["reuse"][m], ours["direct"][m]
        our_resin = resin_mm3(Path(o["entry"]["output"]), pixel_mm2, a.thickness)
        lines.append(f"{Path(m).stem:<12}{p['supported']:>9.2f}{p['unsupported']:>9.2f}{o['seconds']:>8.3f}"
                     f"{g['seconds']:>10.3f}{p['supported'] / o['seconds']:>8.1f}x"
                     f"{o['support_seconds'] / o['seconds']:>9.0%}{our_resin / p['resin']:>7.2f}x")
    support_time = statistics.median(p["supported"] - p["unsupported"] for p in ps.values())
    lines.append(f"support points on the source: {generate:.3f} s; PrusaSlicer's support time (supported minus "
                 f"unsupported, median): {support_time:.2f} s; ratio {generate / support_time:.3f}")
    lines.append(f"{'member':<12}{'points':>7}{'kept':>6}{'moved':>6}{'added':>6}{'dropped':>8}")
    for m in members:
        e = ours["reuse"][m]["entry"]
        lines.append(f"{Path(m).stem:<12}{e['support_points']:>7}{e['kept']:>6}{e['moved']:>6}{e['added']:>6}"
                     f"{e['dropped']:>8}")
    text = "\n".join(lines)
    print(text)
    (a.out / "bench_supports.md").write_text(text + "\n")
    (a.out / "bench_supports.json").write_text(json.dumps({"prusaslicer": ps, "generate_seconds": generate,
                                                           "ours": {w: {m: {k: v for k, v in r.items() if k != "entry"}
                                                                        for m, r in rs.items()}
                                                                    for w, rs in ours.items()}}, indent=1))


if __name__ == "__main__":
    main()
