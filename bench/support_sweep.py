"""The supports' property sweep over many parts (issue #35, item 5): random family members (any
shape, tilts of 0 to 90 degrees, critical angles of 10 to 80 degrees, densities of 50 to 300 %),
each supported and printed by the product and checked (tests/support/support_sweep.h): no island
and no resin trap in the print file, nothing lit more than 1 mm from the layer below, no foot in
the air, pillars entering the part only at heads; and, where PrusaSlicer is installed, the
supports' resin (supports and pad: the supported stack's cured volume minus the part's alone)
within 1.3x PrusaSlicer's for the same part, critical angle and density.

    scripts/python bench/support_sweep.py [--parts 100] [--seed 1] [--thickness 0.05]
        [--part "shape family_seed member tilt critical density height faces" ...] [--out DIR]

Also, where bench_printability is built, UVtools' findings in PrusaSlicer's file of each part
(for reference: what its supports give by the same definitions). Prints a line per part as it
goes, then the table: parts, failures per property, the resin ratio (ours over PrusaSlicer's)
median and maximum, and each failing part with its parameters and the --part text that
reproduces it. Writes DIR/support_sweep.md and .json (and .jsonl, a line per part as it goes).
Needs scripts/build (build/2020/tests/support_sweep); PrusaSlicer is optional (scripts/setup installs it).
"""
import argparse
import json
import re
import shutil
import statistics
import subprocess
import sys
from pathlib import Path

from slicereuse_prusaslicer import support_resin_mm3

ROOT = Path(__file__).resolve().parent.parent

PROPERTIES = ["error", "island", "resin trap", "far reach", "foot in air", "pillar into part"]
RESIN_LIMIT = 1.3  # ours over PrusaSlicer's


def printability_counts(checker, archive, thickness):
    """{kind: count} of the printability findings (check_layers.h) in an SL1S archive (50 um
    pixels), as bench_printability prints them ("island: 2")."""
    text = subprocess.run([str(checker), str(archive), "0.05", "0.05", f"{thickness:g}"], check=True,
                          capture_output=True, text=True).stdout
    return {m[1]: int(m[2]) for m in re.finditer(r"^(\w+): (\d+)$", text, re.M)}


def sweep(binary, out, thickness, parts=0, seed=1, given=(), prusaslicer=True, checker=None):
    """Runs support_sweep with --resin --stl and yields each part's findings (its JSON line) with,
    where PrusaSlicer runs, "ps_mm3" (PrusaSlicer's supports' resin), "ratio" (ours over it) and
    "resin" in "failed" beyond RESIN_LIMIT; "ps_error" when PrusaSlicer failed. With checker
    (bench_printability), "ps_findings": UVtools' findings in PrusaSlicer's file, for reference."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    cmd = [str(binary), "--out", str(out), "--thickness", f"{thickness:g}", "--resin", "--stl"]
    cmd += ["--parts", str(parts), "--seed", str(seed)] if not given else [a for p in given for a in ("--part", p)]
    with subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True) as proc:
        for line in proc.stdout:
            r = json.loads(line)
            ours = r["supported_mm3"] - r["part_mm3"] if r["error"] == "" else None
            if prusaslicer and ours is not None:
                try:
                    r["ps_mm3"] = support_resin_mm3(r["stl"], out, thickness, r["critical_angle"], 100 * r["density"],
                                                    r["display_px"])
                    if checker is not None:
                        r["ps_findings"] = printability_counts(checker, out / f"{Path(r['stl']).stem}_supported.sl1s",
                                                               thickness)
                    r["ratio"] = ours / r["ps_mm3"]
                    if r["ratio"] > RESIN_LIMIT:
                        r["failed"].append("resin")
                except subprocess.CalledProcessError as e:
                    r["ps_error"] = (e.stderr or b"").decode(errors="replace").strip().splitlines()[-1:] or [str(e)]
            r["ours_mm3"] = ours
            yield r
    if proc.returncode != 0:
        raise RuntimeError(f"{binary} failed (exit {proc.returncode}): {' '.join(cmd)}")


def failure_text(r, prop):
    """What part r's findings show for a failed property, in words."""
    if prop == "error":
        return f"error: {r['error']}"
    if prop == "island":
        return f"{r['islands']} islands"
    if prop == "resin trap":
        return f"{r['resin_traps']} resin traps"
    if prop == "far reach":
        return f"lit {r['far_mm']} mm from the layer below (layer {r['far_layer']})"
    if prop == "foot in air":
        return (f"{r['feet_in_air']} of {r['feet']} feet off the part (up to {r['foot_off_mm']:.3g} mm), "
                f"{r['support_islands']} support islands (the first on layer {r.get('support_island_layer')})")
    if prop == "pillar into part":
        return (f"supports in the part outside the heads: {r['outside_zones_mm2']:.3g} mm2 at (x, y, z) = "
                f"({', '.join(f'{v:.3f}' for v in r['outside_zones_xyz'])})")
    return f"resin {r['ratio']:.2f}x PrusaSlicer's ({r['ours_mm3']:.1f} / {r['ps_mm3']:.1f} mm3)"


def table(rows, prusaslicer):
    properties = PROPERTIES + (["resin"] if prusaslicer else [])
    lines = [f"{len(rows)} parts; failures per property:",
             "  ".join(f"{p}: {sum(p in r['failed'] for r in rows)}" for p in properties)]
    ratios = [r["ratio"] for r in rows if "ratio" in r]
    if ratios:
        lines.append(f"supports' resin over PrusaSlicer's ({len(ratios)} parts): "
                     f"median {statistics.median(ratios):.2f}x, "
                     f"min {min(ratios):.2f}x, max {max(ratios):.2f}x; over {RESIN_LIMIT}x: "
                     f"{sum(x > RESIN_LIMIT for x in ratios)}")
    elif not prusaslicer:
        lines.append("prusa-slicer is not on PATH: the supports' resin is not compared")
    checked = [r for r in rows if "ps_findings" in r]
    if checked:
        lines.append(f"for reference, UVtools' findings in PrusaSlicer's files of the same parts ({len(checked)}): "
                     f"islands in {sum(r['ps_findings'].get('island', 0) > 0 for r in checked)} parts "
                     f"({sum(r['ps_findings'].get('island', 0) for r in checked)}), resin traps in "
                     f"{sum(r['ps_findings'].get('resin_trap', 0) > 0 for r in checked)} parts "
                     f"({sum(r['ps_findings'].get('resin_trap', 0) for r in checked)}); ours: islands in "
                     f"{sum(r['islands'] > 0 for r in checked)} ({sum(r['islands'] for r in checked)}), "
                     f"resin traps in {sum(r['resin_traps'] > 0 for r in checked)} "
                     f"({sum(r['resin_traps'] for r in checked)})")
    ps_errors = [r for r in rows if "ps_error" in r]
    if ps_errors:
        lines.append(f"PrusaSlicer failed on {len(ps_errors)} parts: " +
                     "; ".join(f"{r['index']}: {r['ps_error']}" for r in ps_errors))
    failing = [r for r in rows if r["failed"]]
    if failing:
        lines.append("failing parts (shape family_seed member tilt critical density height faces):")
    for r in failing:
        what = [failure_text(r, p) for p in r["failed"]]
        ps = r.get("ps_findings")
        if ps is not None:
            what.append(f"PrusaSlicer's file: {ps.get('island', 0)} islands, {ps.get('resin_trap', 0)} resin traps")
        lines.append(f"  part {r['index']}: --part \"{r['part']}\": " + "; ".join(what))
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--parts", type=int, default=100)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--thickness", type=float, default=0.05)
    ap.add_argument("--part", action="append", default=[], help="a part's text (repeatable), instead of --parts")
    ap.add_argument("--out", type=Path, default=ROOT / "out" / "support_sweep")
    a = ap.parse_args()
    binary = ROOT / "build" / "2020" / "tests" / "support_sweep"
    if not binary.is_file():
        raise SystemExit(f"{binary} is missing: cmake --build build/2020 --target support_sweep")
    prusaslicer = shutil.which("prusa-slicer") is not None
    shutil.rmtree(a.out, ignore_errors=True)
    a.out.mkdir(parents=True)
    rows = []
    log = (a.out / "support_sweep.jsonl").open("w")  # as it goes: an interrupted sweep keeps its parts
    checker = ROOT / "build" / "2020" / "bench" / "bench_printability"
    for r in sweep(binary, a.out, a.thickness, a.parts, a.seed, a.part, prusaslicer,
                   checker if checker.is_file() else None):
        rows.append(r)
        log.write(json.dumps(r) + "\n")
        log.flush()
        ratio = f"{r['ratio']:.2f}x" if "ratio" in r else "-"
        print(f"{r['index']:4d} {r['part']:<40} {r['points']:4d} points {r['seconds']:6.2f} s  resin {ratio:>6}  "
              f"{', '.join(r['failed']) or 'ok'}", file=sys.stderr, flush=True)
    text = (f"support sweep: seed {a.seed}, {a.thickness:g} mm layers, SL1S\n" if not a.part else "") + \
        table(rows, prusaslicer)
    print(text)
    (a.out / "support_sweep.md").write_text(text + "\n")
    (a.out / "support_sweep.json").write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
