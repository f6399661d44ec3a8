"""Our .sl1 / .sl1s against PrusaSlicer's own: the same part exported by PrusaSlicer's command line
(prusa-slicer --export-sla, Debian's 2.5) and by make_print_job, for the SL1 and the SL1S SPEED.

PrusaSlicer's configuration is its own: the printer preset from its PrusaResearch.ini with that
preset's default print and material presets, with supports, pad and elephant foot compensation
off, gamma_correction 1 and initial_layer_height = layer_height. Placement: PrusaSlicer centres
the part's bounding box on its bed (--center at the bed's centre; --dont-arrange, since its
arrangement places the part by an optimizer, measured 0.074 mm off the centre); ours puts the
model's origin at the display's centre plus the offset, so the offset is the bed's centre minus
the display's centre minus the part's centre. Layers: PrusaSlicer cuts layer k at
(k + 1/2) * layer_height above the part's bottom when initial_layer_height = layer_height (its
slice index, SLAPrintSteps.cpp), as make_print_job does from the lowest vertex.

Per layer, the images must have the printer's size and nearly every pixel of the part (non-zero
in either image) must be within 2 grey levels: this pins our orientation, mirrors, placement and
anti-aliasing to PrusaSlicer's. The part is a tapered L turned by 17 degrees, so its edges cross
pixels at arbitrary places and a mirror or turn would not go unnoticed.
Skipped only when prusa-slicer is not installed (scripts/setup installs it).
"""
import math
import shutil
import struct
import subprocess

import numpy as np
import pytest
from conftest import write_stl
from slicereuse_prusaslicer import VENDOR_PROFILES, read_archive, write_config
from slicereuse_prusaslicer import prusaslicer_config as vendor_config

PRUSA_SLICER = shutil.which("prusa-slicer")
LAYER_HEIGHT = 0.05
PART_HEIGHT = 5.0  # mm: 100 layers

pytestmark = pytest.mark.skipif(PRUSA_SLICER is None,
                                reason="prusa-slicer is not installed (scripts/setup installs Debian's prusa-slicer)")

# Measured with PrusaSlicer 2.5.0 (Debian 2.5.0+dfsg-4), on every layer: at least 99.979 % of the
# part's pixels within 2 levels, at most 3 levels apart anywhere (where they differ, PrusaSlicer's
# AGG rasterizer is about 0.8 levels brighter along slanted edges; axis-aligned edges give the same
# levels); the covered area per layer within 8 pixels of 157,000. The bounds leave a margin.
MIN_SHARE_WITHIN_2 = 0.999
MAX_DIFFERENCE = 4
MAX_AREA_RATIO_DIFFERENCE = 1e-3


def tapered_l():
    """Triangles (n, 3, 3) of a closed L-shaped prism: the L's foot 24 mm, its arm 30 mm, 7 and 8 mm
    wide, 5 mm tall, its top 0.7 times its bottom, turned by 17 degrees about z, off the origin."""
    outline = np.array([(0, 0), (24, 0), (24, 7), (8, 7), (8, 30), (0, 30)], float)
    top = np.array([4.0, 4.0]) + (outline - np.array([4.0, 4.0])) * 0.7
    a = math.radians(17)
    turn = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    bottom3 = np.c_[outline @ turn.T, np.zeros(6)]
    top3 = np.c_[top @ turn.T, np.full(6, PART_HEIGHT)]
    triangles = []
    for i, j, k in [(0, 1, 2), (0, 2, 3), (0, 3, 4), (0, 4, 5)]:  # the L's caps, as a fan from corner 0
        triangles += [(bottom3[i], bottom3[k], bottom3[j]), (top3[i], top3[j], top3[k])]
    for i in range(6):
        j = (i + 1) % 6
        triangles += [(bottom3[i], bottom3[j], top3[j]), (bottom3[i], top3[j], top3[i])]
    return np.array(triangles)


def prusaslicer_config(printer):
    """The printer preset with its default print and material presets, as the GUI would combine
    them, with supports, pad and elephant foot compensation off, gamma 1 and equal layers."""
    assert VENDOR_PROFILES.is_file(), f"PrusaSlicer's profiles are missing: {VENDOR_PROFILES}"
    return vendor_config(printer, supports_enable="0", pad_enable="0", elefant_foot_compensation="0",
                         gamma_correction="1", layer_height=str(LAYER_HEIGHT), initial_layer_height=str(LAYER_HEIGHT))


def same_value(a, b):
    try:
        return [float(x) for x in a.split(",")] == [float(x) for x in b.split(",")]
    except ValueError:
        return a == b


@pytest.fixture(scope="module")
def part(tmp_path_factory):
    folder = tmp_path_factory.mktemp("prusaslicer_sl1")
    triangles = tapered_l()
    write_stl(folder / "part.stl", triangles)
    # The part's centre as PrusaSlicer computes it: from the STL's single-precision vertices.
    points = triangles.reshape(-1, 3).astype(np.float32).astype(float)
    return folder, (points.min(0) + points.max(0)) / 2


@pytest.mark.parametrize("preset, printer, extension", [("prusa_sl1", "Original Prusa SL1", ".sl1"),
                                                        ("prusa_sl1s_speed", "Original Prusa SL1S SPEED", ".sl1s")])
def test_our_archive_is_prusaslicers_pixel_for_pixel_within_2_levels(pymeshlab, part, preset, printer, extension):
    folder, centre = part
    config = prusaslicer_config(printer)
    write_config(folder / f"{preset}.ini", config)
    bed = np.array([[float(c) for c in p.split("x")] for p in config["bed_shape"].split(",")])
    bed_centre = (bed.min(0) + bed.max(0)) / 2
    display_centre = np.array([float(config["display_width"]), float(config["display_height"])]) / 2
    theirs, ours = folder / f"ps_{preset}{extension}", folder / f"ours_{preset}{extension}"
    run = subprocess.run([PRUSA_SLICER, "--export-sla", "--load", str(folder / f"{preset}.ini"),
                          "--center", f"{bed_centre[0]},{bed_centre[1]}", "--dont-arrange", "-o", str(theirs),
                          str(folder / "part.stl")], capture_output=True, text=True)
    assert run.returncode == 0 and theirs.is_file(), run.stdout[-2000:] + run.stderr[-2000:]

    offset = bed_centre - display_centre - centre[:2]
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(folder / "part.stl"))
    ms.apply_filter("make_print_job", encoding_file="", layer_thickness=LAYER_HEIGHT, output_path=str(ours),
                    printer=preset, offset_x_mm=float(offset[0]), offset_y_mm=float(offset[1]),
                    antialiasing=True, gamma=1.0, elephant_foot=0.0)

    their_layers, their_config, their_profile = read_archive(theirs)
    our_layers, our_config, our_profile = read_archive(ours)
    assert len(their_layers) == len(our_layers) == round(PART_HEIGHT / LAYER_HEIGHT)
    # The firmware's keys: the same keys, the same job (jobDir is the file's name).
    assert set(our_config) == set(their_config)
    for key in ("action", "expTime", "expTimeFirst", "expUserProfile", "hollow", "layerHeight", "numFade",
                "numFast", "printerModel", "printerVariant"):
        assert same_value(our_config[key], their_config[key]), (key, our_config[key], their_config[key])
    assert float(our_config["usedMaterial"]) == pytest.approx(float(their_config["usedMaterial"]), rel=0.01)
    # The profile: only keys PrusaSlicer knows, with its values, but for the names of the presets
    # and the bed (ours is the display's rectangle).
    assert set(our_profile) <= set(their_profile), set(our_profile) - set(their_profile)
    for key in set(our_profile) - {"bed_shape", "printer_settings_id", "sla_print_settings_id",
                                   "sla_material_settings_id"}:
        assert same_value(our_profile[key], their_profile[key]), (key, our_profile[key], their_profile[key])

    size = (int(config["display_pixels_x"]), int(config["display_pixels_y"]))  # portrait: turned
    worst = (1.0, 0, -1)
    for k, (a, b) in enumerate(zip(their_layers, our_layers)):
        assert a.shape == b.shape == (size[0], size[1]), (k, a.shape, b.shape)
        d = np.abs(a.astype(int) - b.astype(int))
        part_pixels = (a > 0) | (b > 0)
        share = float((d[part_pixels] <= 2).mean())
        worst = min(worst, (share, -int(d.max()), k))
        assert share >= MIN_SHARE_WITHIN_2, f"layer {k}: {share:.6f} of the part's pixels within 2 levels"
        assert d.max() <= MAX_DIFFERENCE, f"layer {k}: pixels {d.max()} levels apart"
        area_a, area_b = a.sum(dtype=np.int64), b.sum(dtype=np.int64)
        assert abs(area_a - area_b) <= MAX_AREA_RATIO_DIFFERENCE * area_a, (k, area_a / 255, area_b / 255)
    print(f"{preset}: worst layer {worst[2]}: {worst[0]:.6f} of the part's pixels within 2 levels, "
          f"largest difference {-worst[1]}")
