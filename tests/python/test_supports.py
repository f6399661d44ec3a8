"""Supported print jobs on the pymeshlab host (issue #30): family.py --supports, by reuse (the
source's points generated once and transferred to every member) and --direct (every member
generates its own), one .sl1s per member and on plates. Every layer of every output rests on the
layer below: no lit region of layer k > 0 without a lit pixel of layer k - 1 under it (0
islands), and no lit pixel farther than 1 mm from a lit pixel of the layer below. The entries'
support figures agree with the source's points file. A points file for another mesh is refused
in words, with nothing written."""
import json
from pathlib import Path

import numpy as np
import pytest

from conftest import THICKNESS, raises_filter_error
from test_batch import family_py
from slicereuse_prusaslicer import read_archive

SHAPES = ["sphere", "handle"]
PRINTER = "prusa_sl1s_speed"
REACH_MM = 1.0  # the farthest a lit pixel may be from the layer below's


def shifted(a, dy, dx, fill):
    """a moved by (dy, dx) pixels, the uncovered border set to fill."""
    out = np.full_like(a, fill)
    h, w = a.shape
    out[max(dy, 0):h + min(dy, 0), max(dx, 0):w + min(dx, 0)] = a[max(-dy, 0):h - max(dy, 0),
                                                                   max(-dx, 0):w - max(dx, 0)]
    return out


def resting_on(below, lit):
    """The lit pixels connected (8-neighbours, within lit) to a lit pixel that has one of below
    under it: geodesic reconstruction by repeated dilation, in numpy."""
    reached = lit & below
    while True:
        grown = reached.copy()
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                grown |= shifted(reached, dy, dx, False)
        grown &= lit
        if (grown == reached).all():
            return reached
        reached = grown


def within(below, radius_px):
    """The pixels at most radius_px (Euclidean, between pixel centres) from a lit pixel of below:
    the squared distance, capped, column-wise then row-wise."""
    r = int(np.floor(radius_px))
    far = radius_px * radius_px + 1
    column = np.where(below, 0.0, far)
    for dy in range(1, r + 1):
        reach = float(dy * dy)
        column = np.minimum(column, np.where(shifted(below, dy, 0, False) | shifted(below, -dy, 0, False), reach, far))
    d2 = column.copy()
    for dx in range(1, r + 1):
        d2 = np.minimum(d2, dx * dx + np.minimum(shifted(column, 0, dx, far), shifted(column, 0, -dx, far)))
    return d2 <= radius_px * radius_px


def assert_every_layer_rests_on_the_one_below(path):
    """0 islands and no lit pixel more than REACH_MM from the layer below, on every layer of the
    .sl1s at path (its display's pixel size from prusaslicer.ini)."""
    images, _, config = read_archive(path)
    pixel_mm = float(config["display_width"]) / float(config["display_pixels_x"])
    lit = [image >= 128 for image in images]  # lit: at or above the binary threshold
    rows = np.flatnonzero(np.any(np.any(lit, axis=0), axis=1))
    cols = np.flatnonzero(np.any(np.any(lit, axis=0), axis=0))
    assert rows.size, f"{path.name}: no lit pixel"
    pad = int(REACH_MM / pixel_mm) + 2
    crop = np.s_[max(rows[0] - pad, 0):rows[-1] + pad + 1, max(cols[0] - pad, 0):cols[-1] + pad + 1]
    layers = [layer[crop] for layer in lit]
    for k in range(1, len(layers)):
        below, here = layers[k - 1], layers[k]
        islands = here & ~resting_on(below, here)
        assert not islands.any(), f"{path.name}: layer {k} has lit pixels resting on nothing, e.g. at " \
                                  f"{np.argwhere(islands)[0]}"
        far = here & ~within(below, REACH_MM / pixel_mm)
        assert not far.any(), f"{path.name}: layer {k} lights {far.sum()} pixels more than {REACH_MM} mm " \
                              "from the layer below"


def assert_the_printer_takes_it(path):
    """What the SL1S firmware's loader checks: config.ini's printerModel, its layer count
    (numFast + numSlow) equal to the layers in the archive, and every image the display's size
    (portrait: 1620 x 2560)."""
    images, config, _ = read_archive(path)
    assert config["printerModel"] == "SL1S", config
    assert int(config["numFast"]) + int(config["numSlow"]) == len(images), config
    assert all(image.shape == (2560, 1620) for image in images), {image.shape for image in images}


def points_in_file(path):
    """The point count a support-points file's header gives."""
    for line in path.read_text().splitlines():
        if line.startswith("points "):
            return int(line.split()[1])
    raise AssertionError(f"{path}: no 'points' line")


SUPPORT_KEYS = {"support_points", "kept", "moved", "added", "dropped"}


def assert_support_figures(entry, source_points):
    """A member's figures: transferred from the source's source_points points (None: generated)."""
    assert entry["support_points"] > 0, entry
    if source_points is None:
        assert entry["kept"] == entry["moved"] == entry["added"] == entry["dropped"] == 0, entry
    else:
        assert entry["kept"] + entry["moved"] + entry["dropped"] == source_points, entry
        assert entry["kept"] + entry["moved"] + entry["added"] == entry["support_points"], entry


@pytest.mark.parametrize("direct", [False, True], ids=["reuse", "direct"])
@pytest.mark.parametrize("shape", SHAPES)
def test_family_supports_print_every_member_on_supports(make_family, tmp_path, shape, direct):
    members = make_family(shape, 3, faces=10000)
    run = family_py("--layer-thickness", THICKNESS, "--printer", PRINTER, "--format", "sl1s", "--supports",
                    "--workers", 0, *(["--direct"] if direct else []), *members, out=tmp_path)
    result = json.loads(run.stdout)
    source_points = tmp_path / f"{members[0].stem}_supports.srp"
    assert source_points.is_file() != direct
    assert result["failed"] == 0, result
    for entry in result["targets"]:
        assert SUPPORT_KEYS <= set(entry) and entry["support_seconds"] >= 0, entry
        assert_support_figures(entry, None if direct else points_in_file(source_points))
        assert_every_layer_rests_on_the_one_below(Path(entry["output"]))
        assert_the_printer_takes_it(Path(entry["output"]))


@pytest.mark.parametrize("shape", SHAPES)
def test_family_supports_on_plates(make_family, tmp_path, shape):
    members = make_family(shape, 3, faces=10000)
    run = family_py("--layer-thickness", THICKNESS, "--printer", PRINTER, "--format", "sl1s", "--supports",
                    "--plates", "--workers", 0, *members, out=tmp_path)
    result = json.loads(run.stdout)
    assert result["failed"] == 0, result
    source_points = points_in_file(tmp_path / f"{members[0].stem}_supports.srp")
    for plate in result["plates"]:
        for member in plate["members"]:
            assert_support_figures(member, source_points)
        assert_every_layer_rests_on_the_one_below(Path(plate["output"]))
        assert_the_printer_takes_it(Path(plate["output"]))


def test_a_points_file_for_another_mesh_is_refused_and_nothing_is_written(pymeshlab, make_family, tmp_path):
    source = make_family("sphere", 2, faces=10000)[0]
    other = make_family("handle", 2, faces=10000)[1]
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(source))
    ms.apply_filter("generate_support_points", layer_thickness=THICKNESS,
                    support_points_file=str(tmp_path / "source.srp"))
    ms.load_new_mesh(str(other))
    raises_filter_error(pymeshlab, ms, "build_supports", "the support points are for a mesh of",
                        support_points_file=str(tmp_path / "source.srp"))
    raises_filter_error(pymeshlab, ms, "transfer_support_points", "the support points are for a mesh of",
                        support_points_file=str(tmp_path / "source.srp"),
                        member_points_file=str(tmp_path / "member.srp"))
    raises_filter_error(pymeshlab, ms, "make_print_job",
                        "the current mesh's supports: the support points are for a mesh of", supports=2,
                        support_points_file=str(tmp_path / "source.srp"), output_path=str(tmp_path / "m.sl1s"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["source.srp"]
