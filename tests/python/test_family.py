"""The family pipeline on the pymeshlab host: transferring the source's slicing to every member
gives exactly the member's own slicing (same points, masks with S = 1)."""
import json
import subprocess

import pytest

import slicereuse_pymeshlab as sr
from conftest import ROOT, THICKNESS

SHAPES = ["arch", "ear", "handle", "box", "sphere", "torus"]
KEYS = {"mesh", "layers", "points", "resliced_layers", "transfer_seconds", "direct_seconds",
        "transfer_total_seconds", "direct_total_seconds", "min_similarity"}


CASES = [(shape, z) for z in (None, "band") for shape in SHAPES] + [("arch", "everywhere")]


@pytest.mark.parametrize("shape, z_change", CASES, ids=[f"{s}-{z or 'xy'}" for s, z in CASES])
def test_transfer_equals_direct_slicing(make_family, tmp_path, shape, z_change):
    """Transferred members equal direct slicing (same points, S = 1), and the layer counts show
    the path taken: x-y members transfer every layer; a z change within one band of heights
    re-slices that band's layers and transfers most; a z change everywhere fails most layers'
    certificate, so the transfer falls back to slicing every layer."""
    members = make_family(shape, 3, z_change=z_change)
    result = sr.family(members[0], members[1:], THICKNESS, tmp_path)
    assert result["source"] == str(members[0])
    assert [t["mesh"] for t in result["targets"]] == [str(m) for m in members[1:]]
    for t in result["targets"]:
        assert t["points"] == t["direct_points"] > 0, t
        # x-y and band members keep the base's height: 8 mm at 0.1 mm.
        assert t["layers"] == (80 if z_change != "everywhere" else pytest.approx(80, abs=3)), t
        assert t["min_similarity"] == 1.0, t
        transferred = t["layers"] - t["resliced_layers"]
        if z_change is None:
            # x-y deformations keep every vertex on its side of every plane.
            assert t["resliced_layers"] == 0, t
        elif z_change == "band":
            assert t["resliced_layers"] > 0 and transferred > 2 * t["resliced_layers"], t
        else:
            assert transferred == 0, t


def test_cli_prints_one_json_object(make_family, tmp_path):
    members = make_family("arch", 3)
    out = subprocess.run([str(ROOT / "scripts" / "python"), str(ROOT / "examples" / "family.py"),
                          "--layer-thickness", str(THICKNESS), "--out", str(tmp_path / "out"),
                          *map(str, members)], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    result = json.loads(out.stdout)
    assert set(result) == {"source", "targets"}
    assert len(result["targets"]) == 2
    for t in result["targets"]:
        assert set(t) == KEYS
        assert isinstance(t["layers"], int) and isinstance(t["points"], int)
        assert isinstance(t["resliced_layers"], int)
        assert t["transfer_seconds"] >= 0 and t["direct_seconds"] >= 0
        assert t["min_similarity"] == 1.0
    # 8 mm at 0.1 mm: layers whose bottom is below the top, z in [0, 8].
    assert result["targets"][0]["layers"] == 80
    assert out.stderr == ""  # no progress bar when stderr is not a terminal


@pytest.mark.parametrize("args, message", [
    (["--layer-thickness", "0"], "--layer-thickness must be greater than 0"),
    (["--layer-thickness", "0.1", "MISSING"], "mesh file not found: "),
])
def test_cli_errors_are_one_line(make_family, tmp_path, args, message):
    members = make_family("arch", 3)
    argv = [str(ROOT / "scripts" / "python"), str(ROOT / "examples" / "family.py"),
            "--out", str(tmp_path / "out")]
    argv += [str(tmp_path / "missing.ply") if a == "MISSING" else a for a in args]
    if "MISSING" not in args:
        argv += [str(m) for m in members]
    else:
        argv.insert(len(argv) - 1, str(members[0]))
    out = subprocess.run(argv, capture_output=True, text=True)
    assert out.returncode != 0
    assert message in out.stderr
    assert "Traceback" not in out.stderr
    assert out.stdout == ""
