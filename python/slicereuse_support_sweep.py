"""The supports' property sweep (issue #35, item 5) with PrusaSlicer's resin: runs the C++ sweep
(build/2020/tests/support_sweep, tests/support/support_sweep.h) and adds, per part, PrusaSlicer's
supports' resin for the same part, critical angle and density. Used by the large sweep
(bench/support_sweep.py) and the small one's resin test (tests/python/test_support_sweep.py)."""
import json
import re
import subprocess
from pathlib import Path

from slicereuse_prusaslicer import support_resin_mm3

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
