"""The supports' resin against PrusaSlicer's (issue #35, item 5), on the 12 parts of the small sweep
(tests/unit/test_support_sweep.cpp's small_sweep_part, by their text): each part supported and
printed by the product (build/2020/tests/support_sweep) and by PrusaSlicer 2.5 with its own
supports and pad (bench/support_sweep.py, the large sweep's code). Where PrusaSlicer's own print
file passes UVtools' island and resin-trap checks (bench_printability), ours takes at most 1.3x
its resin; where it does not, its supports hold too little to be the measure (the arch lying flat,
where ours take 1.68x, has 3 islands in PrusaSlicer's file). Skipped only when prusa-slicer is not
installed (scripts/setup installs it).
"""
import shutil
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "bench"))
from support_sweep import RESIN_LIMIT, sweep  # noqa: E402

SMALL_SWEEP = ["arch 1 1 0 10 0.5 5 4000", "ear 2 2 30 16.5 1.65 5 4000", "handle 3 3 60 22.5 2.75 5 4000",
               "box 4 1 90 29 1.2 5 4000", "sphere 5 2 0 35.5 2.3 5 4000", "torus 6 3 30 42 0.75 5 4000",
               "arch 7 1 60 48 1.85 5 4000", "ear 8 2 90 54.5 3 5 4000", "handle 9 3 0 61 1.4 5 4000",
               "box 10 1 30 67.5 2.55 5 4000", "sphere 11 2 60 73.5 0.95 5 4000", "torus 12 3 90 80 2.1 5 4000"]


@pytest.mark.skipif(shutil.which("prusa-slicer") is None,
                    reason="prusa-slicer is not installed (scripts/setup installs Debian's prusa-slicer)")
def test_supports_take_at_most_1_3x_prusaslicers_resin_where_its_file_is_printable(tmp_path):
    rows = list(sweep(ROOT / "build/2020/tests/support_sweep", tmp_path, 0.05, given=SMALL_SWEEP,
                      checker=ROOT / "build/2020/bench/bench_printability"))
    assert [r["part"] for r in rows] == SMALL_SWEEP
    compared = []
    for r in rows:
        assert r["error"] == "" and "ps_error" not in r, r
        held = r["ps_findings"].get("island", 0) == 0 and r["ps_findings"].get("resin_trap", 0) == 0
        if held:
            compared.append(r["part"])
            assert r["ratio"] <= RESIN_LIMIT, \
                f"{r['part']}: {r['ours_mm3']:.1f} mm3 of supports, {r['ratio']:.2f}x PrusaSlicer's {r['ps_mm3']:.1f}"
    # PrusaSlicer's files leave islands on 2 to 4 of these parts, run to run (its supports differ
    # from run to run): the bound is measured on the rest.
    assert len(compared) >= 6, compared
