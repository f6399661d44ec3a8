"""The lab's jobs end to end against PrusaSlicer 2.5, in one run (issue #37): whole-process wall
time of the product's own command (examples/family.py, a fresh process each time: Python, pymeshlab,
the plugins and the batch engine's start-up included) against PrusaSlicer's command line on the
same STL files, for the same printer (Prusa SL1S SPEED, anti-aliased, its own vendor profile at the
layer height).

    scripts/python bench/bench_end_to_end.py [--thickness 0.05] [--runs 3] [--out DIR]
        [--plate-members 15] [--many-members 100] [--supported-members 10] [--skip-many]

Jobs:
- plate: --plate-members members of two families (an arch of 208k faces and an ear of 100k, half
  each; the arch's first member is the source, the ears are sliced directly) on SL1S plates,
  `family.py --plates`; PrusaSlicer merges and exports each of our plates' members, placed where
  ours are (--merge --dont-arrange: its own arrangement fits at most 3 arches on the plate), one
  run per plate, the runs' seconds summed;
- many: --many-members members of the same two families on plates, the same way;
- supported: --supported-members ear members of 200k faces tilted 60 degrees (bench_supports.py's),
  one supported .sl1s each,
  `family.py --supports` (seconds per member: the whole process over the members); PrusaSlicer
  with supports and pad on one member per run (median over the members);
- load: a member's read by the job (make_print_job's read_seconds) against pymeshlab's
  load_new_mesh of the same STL file, median over the plate's arch members;
- z: members changed in z, `family.py` by reuse against --direct (seconds per member, median).
Ours and PrusaSlicer's are each the median of --runs runs. Prints the table (also into
DIR/bench_end_to_end.md) and what a member's time is made of. Needs PrusaSlicer (scripts/setup
installs it), scripts/setup and scripts/build first.
"""
import argparse
import json
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import slicereuse_pymeshlab as sr
from slicereuse_prusaslicer import prusaslicer_config, write_config

ROOT = Path(__file__).resolve().parent.parent
PRINTER, PRESET = "Original Prusa SL1S SPEED", "prusa_sl1s_speed"
ARCH = dict(shape="arch", faces=208000, height=14.484)
EAR = dict(shape="ear", faces=100000, height=8.8)
TILTED_EAR = dict(EAR, faces=200000)  # bench_supports.py's hearing-aid shell


def wall(cmd):
    """Seconds of running cmd to its end (a fresh process), and its stdout."""
    start = time.perf_counter()
    done = subprocess.run(cmd, check=True, capture_output=True, text=True)
    return time.perf_counter() - start, done.stdout


def median_wall(runs, cmd):
    results = [wall(cmd) for _ in range(runs)]
    return statistics.median(s for s, _ in results), results[-1][1]


def family_stls(out, name, kind, members, seed, extra=()):
    """members + 1 STL files of a generated family (member_000 first), converted from
    gen_family's PLY by pymeshlab, as a lab receives them."""
    folder = out / name
    subprocess.run([str(ROOT / "build/2020/tools/gen_family"), "--shape", kind["shape"], "--faces",
                    str(kind["faces"]), "--members", str(members + 1), "--height", str(kind["height"]),
                    "--seed", str(seed), *extra, "--out", str(folder)], check=True, capture_output=True)
    pymeshlab = sr.load()
    stls = []
    for ply in sorted(folder.glob("member_*.ply")):
        stl = out / f"{name}_{ply.stem}.stl"
        ms = pymeshlab.MeshSet()
        ms.load_new_mesh(str(ply))
        ms.save_current_mesh(str(stl))
        stls.append(str(stl))
    shutil.rmtree(folder)
    return stls


def family_cmd(out, meshes, thickness, *flags):
    return [sys.executable, str(ROOT / "examples/family.py"), "--layer-thickness", str(thickness), "--printer",
            PRESET, "--antialiasing", "--out", str(out), *flags, *meshes]


def placed_stl(mesh, member, center, path):
    """The binary STL mesh turned and moved as the placements file's member entry says
    (placement.h), then by center (PrusaSlicer's bed has its origin at a corner, ours at the
    display's centre), into path."""
    data = Path(mesh).read_bytes()
    count = int(np.frombuffer(data, "<u4", 1, 80)[0])
    facets = np.frombuffer(data, np.dtype([("n", "<3f4"), ("v", "<3f4", (3,)), ("a", "<u2")]), count, 84).copy()
    theta = np.radians(member["theta_deg"])
    c, s = np.cos(theta), np.sin(theta)
    v = facets["v"].astype(np.float64)
    x, y = v[..., 0].copy(), v[..., 1].copy()
    v[..., 0] = c * x - s * y + member["tx_mm"] + center[0]
    v[..., 1] = s * x + c * y + member["ty_mm"] + center[1]
    facets["v"] = v
    Path(path).write_bytes(data[:84] + facets.tobytes())


def prusaslicer_plates(runs, config, placements, meshes, out):
    """PrusaSlicer's seconds for the plates of a placements file (plates.json): each plate's members (meshes,
    by file name) placed where ours are (its own arrangement does not fit as many on a plate),
    merged and exported into one .sl1s (--merge --dont-arrange), one run per plate (median of
    runs), summed."""
    by_name = {Path(m).name: m for m in meshes}
    corners = [tuple(map(float, p.split("x"))) for p in config["bed_shape"].split(",")]
    center = [sum(c[i] for c in corners) / len(corners) for i in (0, 1)]
    ini = out / "unsupported.ini"
    total = 0
    for k, plate in enumerate(json.loads(Path(placements).read_text())["plates"], 1):
        placed = []
        for i, m in enumerate(plate["members"]):
            placed.append(out / f"placed_{k}_{i}.stl")
            placed_stl(by_name[m["name"]], m, center, placed[-1])
        seconds, _ = median_wall(runs, ["prusa-slicer", "--export-sla", "--load", str(ini), "--merge",
                                        "--dont-arrange", "-o", str(out / f"ps_plate_{k}.sl1s"), *map(str, placed)])
        total += seconds
        for p in placed:
            p.unlink()
    return total


def plate_job(a, name, source, members):
    """(our seconds, PrusaSlicer's seconds, plates) of members on plates."""
    ours, stdout = median_wall(a.runs, family_cmd(a.out / name, [source, *members], a.thickness, "--plates"))
    result = json.loads(stdout)
    assert not result["failed"], result
    ps = prusaslicer_plates(a.runs, a.config, a.out / name / "plates.json", members, a.out)
    return ours, ps, len(result["plates"])


def member_parts(a, source, members):
    """What a reused member's seconds are made of in the job (family(details=True) in this process,
    medians over members): read, transfer, masks and file, and the rest (the filter call, the
    record); and pymeshlab's load_new_mesh of the same files (median over them of the median of
    runs)."""
    r = sr.family(source, members, a.thickness, str(a.out / "parts"),
                  profile={"printer": PRESET, "antialiasing": True}, details=True, workers=0)
    t = r["targets"]
    parts = {k: statistics.median(e[k] for e in t)
             for k in ("seconds", "read_seconds", "slicing_seconds", "masks_seconds")}
    parts["rest"] = parts["seconds"] - parts["read_seconds"] - parts["slicing_seconds"] - parts["masks_seconds"]
    pymeshlab = sr.load()
    host = []
    for mesh in members:
        times = []
        for _ in range(a.runs):
            ms = pymeshlab.MeshSet()
            start = time.perf_counter()
            ms.load_new_mesh(mesh)
            times.append(time.perf_counter() - start)
        host.append(statistics.median(times))
    return parts, statistics.median(host)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--thickness", type=float, default=0.05)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--plate-members", type=int, default=15)
    ap.add_argument("--many-members", type=int, default=100)
    ap.add_argument("--supported-members", type=int, default=10)
    ap.add_argument("--skip-many", action="store_true", help="leave out the many-member job (PrusaSlicer takes minutes)")
    ap.add_argument("--out", type=Path, default=ROOT / "out" / "bench_end_to_end")
    a = ap.parse_args()
    if shutil.which("prusa-slicer") is None:
        raise SystemExit("prusa-slicer is not installed (scripts/setup installs it)")
    shutil.rmtree(a.out, ignore_errors=True)
    a.out.mkdir(parents=True)
    config = a.config = prusaslicer_config(PRINTER, layer_height=str(a.thickness), initial_layer_height=str(a.thickness))
    write_config(a.out / "supported.ini", config)
    write_config(a.out / "unsupported.ini", {**config, "supports_enable": "0", "pad_enable": "0"})

    many = 0 if a.skip_many else a.many_members
    n = max(a.plate_members, many)
    arch = family_stls(a.out, "arch", ARCH, n - n // 2, 1)
    ears = family_stls(a.out, "ear", EAR, n // 2 - 1, 3)
    source = arch[0]

    def mixed(count):
        return arch[1:1 + count - count // 2] + ears[:count // 2]

    rows = []
    ours, ps, plates = plate_job(a, "plate", source, mixed(a.plate_members))
    rows.append((f"{a.plate_members} members on {plates} plate{'s' * (plates > 1)}", ours, ps, 20))
    if many:
        ours, ps, plates = plate_job(a, "many", source, mixed(many))
        rows.append((f"{many} members on {plates} plates", ours, ps, 50))

    supported = family_stls(a.out, "tilted", TILTED_EAR, a.supported_members, 1, ("--tilt", "60"))
    ours, _ = median_wall(a.runs, family_cmd(a.out / "supported", supported, a.thickness, "--supports"))
    ps = statistics.median(median_wall(a.runs, ["prusa-slicer", "--export-sla", "--load", str(a.out / "supported.ini"),
                                                "-o", str(a.out / "ps_supported.sl1s"), m])[0]
                           for m in supported[1:4])
    rows.append((f"a supported member ({a.supported_members} in one run)", ours / a.supported_members, ps, 30))

    lines = [f"SL1S SPEED, anti-aliased, {a.thickness:g} mm layers; whole-process wall seconds, medians of {a.runs} "
             "runs, in one run of this benchmark",
             "| job | ours (s) | PrusaSlicer 2.5 (s) | PrusaSlicer / ours | target |", "|---|---|---|---|---|"]
    lines += [f"| {job} | {o:.2f} | {p:.1f} | **{p / o:.0f}x** | {t}x |" for job, o, p, t in rows]

    parts, host = member_parts(a, source, arch[1:6])
    lines.append(f"| a member's load (208k-face STL): the job's read against pymeshlab's load_new_mesh | "
                 f"{parts['read_seconds']:.4f} | {host:.4f} (load_new_mesh) | **{host / parts['read_seconds']:.1f}x** "
                 "| 5x |")

    z = family_stls(a.out, "z", ARCH, 3, 2, ("--z-change",))
    zs = {}
    for way, flags in (("reuse", []), ("direct", ["--direct"])):
        seconds = []
        for _ in range(a.runs):
            r = json.loads(wall(family_cmd(a.out / f"z_{way}", [source, *z[1:]], a.thickness, "--workers", "0",
                                           *flags))[1])
            seconds += [e["seconds"] for e in r["targets"]]
        zs[way] = statistics.median(seconds)
    lines.append(f"| a member changed in z, by reuse against direct slicing (s per member) | {zs['reuse']:.3f} | "
                 f"{zs['direct']:.3f} (direct) | **{zs['reuse'] / zs['direct']:.2f}x** | at most 1.1x |")

    lines.append("")
    lines.append("A reused arch member in one process (family(details=True), median of 5): " +
                 ", ".join(f"{k.replace('_seconds', '')} {v:.3f} s" for k, v in parts.items()))
    text = "\n".join(lines)
    print(text)
    (a.out / "bench_end_to_end.md").write_text(text + "\n")


if __name__ == "__main__":
    main()
