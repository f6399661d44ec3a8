"""The float host (Debian's MeshLab 2020.09 through scripts/meshlabserver) and this double host
(pymeshlab 2025.07) slice the same member into the same contours, up to the float rounding of
the 2020 host's vertex coordinates, and into identical masks."""
import shutil
import subprocess
import xml.etree.ElementTree as ET

import pytest

from conftest import ROOT, THICKNESS, read_text_contours

MESHLABSERVER = ROOT / "scripts" / "meshlabserver"
PLUGIN_2020 = ROOT / "build" / "2020" / "plugins" / "libfilter_slicereuse.so"


def _skip_reason():
    if not MESHLABSERVER.is_file():
        return f"{MESHLABSERVER} missing"
    if not shutil.which("meshlabserver"):
        return "Debian's meshlabserver is not installed (scripts/setup installs it)"
    if not PLUGIN_2020.is_file():
        return f"2020 plugin not built ({PLUGIN_2020}): cmake --build build/2020"
    return None


def _script(path, values):
    """Writes slice.mlx followed by masks.mlx from examples/, with parameter values replaced."""
    root = ET.Element("FilterScript")
    for example in ("slice.mlx", "masks.mlx"):
        for f in ET.parse(ROOT / "examples" / example).getroot().iter("filter"):
            for p in f.iter("Param"):
                if p.get("name") in values.get(f.get("name"), {}):
                    p.set("value", values[f.get("name")][p.get("name")])
            root.append(f)
    path.write_text("<!DOCTYPE FilterScript>\n" + ET.tostring(root, encoding="unicode"))


@pytest.mark.skipif(_skip_reason() is not None, reason=str(_skip_reason()))
@pytest.mark.parametrize("shape", ["arch", "torus"])
def test_float_and_double_hosts_agree(pymeshlab, make_family, tmp_path, shape):
    mesh = make_family(shape, 2)[1]
    f_ctr, d_ctr = tmp_path / "float.ctr", tmp_path / "double.ctr"
    _script(tmp_path / "run.mlx", {
        "Slice Mesh with Encoding": {"layer_thickness": str(THICKNESS), "contour_file": str(f_ctr),
                                     "encoding_file": str(tmp_path / "float.enc"), "file_format": "0"},
        "Export Mask Images": {"contour_file": str(f_ctr), "output_path": str(tmp_path / "masks_float")},
    })
    run = subprocess.run([str(MESHLABSERVER), "-i", str(mesh), "-s", str(tmp_path / "run.mlx")],
                         capture_output=True, text=True, cwd=tmp_path, timeout=300)
    assert run.returncode == 0, run.stdout + run.stderr

    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(mesh))
    ms.apply_filter("slice_mesh_with_encoding", layer_thickness=THICKNESS, contour_file=str(d_ctr))
    ms.apply_filter("export_mask_images", contour_file=str(d_ctr), output_path=str(tmp_path / "masks_double"))

    f_head, f_layers = read_text_contours(f_ctr)
    d_head, d_layers = read_text_contours(d_ctr)
    assert f_head["thickness"] == d_head["thickness"] == [str(THICKNESS)]
    assert f_head["layers"] == d_head["layers"]  # layers, contours and points counts
    for (fz, fc), (dz, dc) in zip(f_layers, d_layers):
        assert fz == pytest.approx(dz, abs=1e-5)
        assert [(o, len(p)) for o, p in fc] == [(o, len(p)) for o, p in dc]
        for (_, fp), (_, dp) in zip(fc, dc):
            for a, b in zip(fp, dp):
                assert a == pytest.approx(b, abs=1e-4)  # float coordinates of a ~30 mm part

    c = ms.apply_filter("compare_mask_stacks", stack_a=str(tmp_path / "masks_float"),
                        stack_b=str(tmp_path / "masks_double"))
    assert c["min_similarity"] == 1.0 and c["differing_pixels"] == 0
