"""The jobs check every print file as they write it (UVtools' checks): a hollow part shows a resin
trap, a cup open at the top a suction cup, each counted for its member; --require-printable
refuses them, naming each finding, and writes nothing of them."""
import json
import subprocess
from pathlib import Path

import numpy as np
from conftest import ROOT, THICKNESS, box_triangles, cup_boxes, write_printability_parts, write_stl
import slicereuse_pymeshlab as sr

NOTHING = {"islands": 0, "overhangs": 0, "resin_traps": 0, "suction_cups": 0, "touching_bounds": 0}


def family_py(*args):
    return subprocess.run([str(ROOT / "scripts" / "python"), str(ROOT / "examples" / "family.py"),
                           "--layer-thickness", str(THICKNESS), "--printer", "prusa_sl1s_speed", *map(str, args)],
                          capture_output=True, text=True)


def test_a_plate_counts_each_finding_for_its_member(tmp_path):
    hollow, cup, solid = write_printability_parts(tmp_path / "parts")
    run = family_py("--plates", "--direct", "--out", tmp_path / "out", solid, hollow, cup, solid)
    assert run.returncode == 0, run.stderr
    [plate] = json.loads(run.stdout)["plates"]
    assert plate["printability"]["resin_traps"] == 1 and plate["printability"]["suction_cups"] == 1, plate
    assert plate["printability"]["islands"] == 0
    # The cavity is 6 x 6 x 2 mm.
    assert abs(plate["printability"]["trapped_mm3"] - 72) < 1, plate
    by_name = {m["name"]: m["printability"] for m in plate["members"]}
    # The cavity's ceiling overhangs too (6 mm wide, 2 mm left after UVtools' 40-pixel erosion).
    assert by_name["hollow.stl"] == dict(NOTHING, resin_traps=1, overhangs=1)
    assert by_name["cup.stl"] == dict(NOTHING, suction_cups=1)
    assert by_name["solid.stl"] == NOTHING
    assert Path(plate["output"]).is_file()


def test_require_printable_refuses_the_plate_naming_its_findings(tmp_path):
    hollow, cup, solid = write_printability_parts(tmp_path / "parts")
    run = family_py("--plates", "--direct", "--require-printable", "--out", tmp_path / "out", solid, hollow, cup)
    assert run.returncode == 1, run.stderr
    [plate] = json.loads(run.stdout)["plates"]
    assert "not printable, so not written: resin trap in hollow.stl, layers" in plate["error"], plate
    assert "suction cup in cup.stl, layers" in plate["error"], plate
    assert not Path(plate["output"]).exists()


def test_require_printable_refuses_each_failing_member_and_writes_the_others(pymeshlab, tmp_path):
    hollow, cup, solid = write_printability_parts(tmp_path / "parts")
    r = sr.family(solid, [hollow, cup, solid], THICKNESS, tmp_path / "out", profile={"printer": "prusa_sl1s_speed"},
                  direct=True, printability="require")
    assert r["failed"] == 2, r
    hollow_entry, cup_entry, solid_entry = r["targets"]
    assert "resin trap in hollow" in hollow_entry["error"], hollow_entry
    assert "suction cup in cup" in cup_entry["error"], cup_entry
    assert not (tmp_path / "out" / "hollow.sl1s").exists() and not (tmp_path / "out" / "cup.sl1s").exists()
    assert solid_entry["printability"] == dict(NOTHING, trapped_mm3=0.0), solid_entry
    assert Path(solid_entry["output"]).is_file()


def test_shells_sharing_corners_print_as_their_union(pymeshlab, tmp_path):
    """An STL file of boxes that share corners (so its reader shares their vertices, and some edges
    have four faces) prints exactly as the same union of boxes apart: no open contour, the same
    masks, the same suction cup."""
    lo, hi = np.array([0, 0, 0.0]), np.array([10, 10, 6.0])
    results = {}
    for shared in (False, True):
        stl = tmp_path / f"cup_{shared}.stl"
        write_stl(stl, np.concatenate([box_triangles(a, b) for a, b in cup_boxes(lo, hi, 2.0, shared)]))
        results[shared] = pymeshlab.MeshSet().apply_filter(
            "make_print_job", mesh_file=str(stl), layer_thickness=THICKNESS, output_path=str(tmp_path / f"{shared}"),
            printer=0)  # the method's display
        assert results[shared]["ignored_open_contours"] == 0 and results[shared]["suction_cups"] == 1, results
    for a in sorted((tmp_path / "False").glob("*.png")):
        assert a.read_bytes() == (tmp_path / "True" / a.name).read_bytes(), a.name


def test_no_check_leaves_the_files_unchecked(tmp_path):
    hollow, cup, solid = write_printability_parts(tmp_path / "parts")
    run = family_py("--plates", "--direct", "--no-check", "--out", tmp_path / "out", solid, hollow, cup)
    assert run.returncode == 0, run.stderr
    [plate] = json.loads(run.stdout)["plates"]
    assert "printability" not in plate and all("printability" not in m for m in plate["members"]), plate
    assert family_py("--no-check", "--require-printable", "--out", tmp_path / "x", solid, hollow).returncode == 2


def test_an_unknown_printability_is_refused_before_any_work(pymeshlab, tmp_path):
    hollow, cup, solid = write_printability_parts(tmp_path / "parts")
    for batch in (sr.family, sr.plates):
        out = tmp_path / batch.__name__
        try:
            batch(solid, [hollow], THICKNESS, out, profile={"printer": "prusa_sl1s_speed"}, printability="strict")
        except ValueError as e:
            assert "printability must be one of check, require, off, not 'strict'" in str(e)
        else:
            raise AssertionError(f"{batch.__name__} took printability='strict'")
        # Refused before the source was sliced or anything arranged: nothing in out.
        assert not out.exists() or not any(out.iterdir()), list(out.iterdir())
