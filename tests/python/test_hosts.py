"""The float host (Debian's MeshLab 2020.09 through scripts/meshlabserver) and this double host
(pymeshlab 2025.07) behave the same: the same filters with the same parameters give the same
result dicts (meshlabserver's from the "slicereuse-result" log lines of host_adapter.h), the
same contours up to the float rounding of the 2020 host's vertex coordinates, and identical
masks. meshlabserver missing is an error, not a skip: scripts/setup installs it."""
import json
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET

import pytest

from conftest import ROOT, THICKNESS, read_text_contours

MESHLABSERVER = ROOT / "scripts" / "meshlabserver"
PLUGIN_2020 = ROOT / "build" / "2020" / "plugins" / "libfilter_slicereuse.so"
# meshlabserver prints each log line to stderr as "LOG: <level> <line>" (and once more,
# unprefixed, to stdout).
RESULT_LINE = re.compile(r"^LOG: \d+ slicereuse-result (\w+) (\{.*\})$", re.M)


@pytest.fixture(scope="session")
def meshlabserver():
    assert shutil.which("meshlabserver"), "Debian's meshlabserver is not installed (scripts/setup installs it)"
    assert PLUGIN_2020.is_file(), f"2020 plugin not built ({PLUGIN_2020}): scripts/build"
    return MESHLABSERVER


def _script(path, filters):
    """Writes a script of example filters [(example .mlx, {param: value})], values replaced."""
    root = ET.Element("FilterScript")
    for example, values in filters:
        for f in ET.parse(ROOT / "examples" / example).getroot().iter("filter"):
            for p in f.iter("Param"):
                if p.get("name") in values:
                    p.set("value", str(values[p.get("name")]))
            root.append(f)
    path.write_text("<!DOCTYPE FilterScript>\n" + ET.tostring(root, encoding="unicode"))


def _run(meshlabserver, tmp_path, meshes, filters):
    """Runs the filters in meshlabserver on meshes; returns [(python name, result dict)]."""
    script = tmp_path / f"run{len(list(tmp_path.glob('run*.mlx')))}.mlx"
    _script(script, filters)
    args = [str(meshlabserver)] + [a for m in meshes for a in ("-i", str(m))] + ["-s", str(script)]
    run = subprocess.run(args, capture_output=True, text=True, cwd=tmp_path, timeout=300)
    assert run.returncode == 0, run.stdout + run.stderr
    return [(name, json.loads(d)) for name, d in RESULT_LINE.findall(run.stderr)]


def _without_timing(result):
    return {k: v for k, v in result.items() if not k.endswith("seconds")}


def test_hosts_give_the_same_result_dicts(pymeshlab, meshlabserver, make_family, tmp_path):
    """Every filter, run with the same parameters in meshlabserver and in pymeshlab, gives the
    same result dict (timings excluded). Counts are equal; the float host's lengths differ from
    the double host's by its rounding of the vertex coordinates only."""
    m0, m1 = make_family("arch", 2, z_change="band")
    out = {h: tmp_path / h for h in ("float", "double")}
    for d in out.values():
        d.mkdir()

    def steps(o):
        slice_ = ("slice.mlx", "slice_mesh_with_encoding",
                  {"layer_thickness": THICKNESS, "contour_file": o / "s.ctr", "encoding_file": o / "s.enc"})
        rest = [
            ("transfer.mlx", "transfer_slicing_to_mesh",
             {"encoding_file": o / "s.enc", "contour_file": o / "t.ctr", "target_encoding_file": o / "t.enc"}),
            ("transfer.mlx", "transfer_slicing_to_mesh",
             {"encoding_file": o / "s.enc", "mode": 1, "contour_file": o / "b.ctr", "target_encoding_file": ""}),
            ("masks.mlx", "export_mask_images", {"contour_file": o / "t.ctr", "output_path": o / "masks_t"}),
            ("masks.mlx", "export_mask_images", {"contour_file": o / "s.ctr", "output_path": o / "masks_s.sl1"}),
            ("compare.mlx", "compare_mask_stacks",
             {"stack_a": o / "masks_t", "stack_b": o / "masks_s.sl1", "report_file": o / "c.csv"}),
        ]
        return slice_, rest

    slice_, rest = steps(out["float"])
    float_results = _run(meshlabserver, out["float"], [m0], [(slice_[0], slice_[2])])
    float_results += _run(meshlabserver, out["float"], [m0, m1], [(e, v) for e, _, v in rest])

    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(m0))
    slice_, rest = steps(out["double"])
    double_results = [(slice_[1], ms.apply_filter(slice_[1], **{k: str(v) if k.endswith("file") else v
                                                                 for k, v in slice_[2].items()}))]
    ms.load_new_mesh(str(m1))
    for _, name, values in rest:
        params = {k: v if isinstance(v, (int, float)) else str(v) for k, v in values.items()}
        if name == "transfer_slicing_to_mesh":
            params["target_mesh"] = 1  # mesh 1 is the second -i in meshlabserver
        double_results.append((name, ms.apply_filter(name, **params)))

    assert [n for n, _ in float_results] == [n for n, _ in double_results] == \
        ["slice_mesh_with_encoding"] + [n for _, n, _ in rest]
    for (name, f), (_, d) in zip(float_results, double_results):
        f, d = _without_timing(f), _without_timing(d)
        assert set(f) == set(d), name
        for key in f:
            if isinstance(d[key], int):
                assert f[key] == d[key], (name, key, f, d)
            else:
                assert f[key] == pytest.approx(d[key], rel=1e-4, abs=1e-5), (name, key, f, d)
    # The results exercise what they name: the transfer mixes transferred and re-sliced layers,
    # and the compared stacks (member 1 transferred, member 0 sliced) differ.
    transfer = double_results[1][1]
    assert transfer["transferred_layers"] > 0 and transfer["resliced_layers"] > 0, transfer
    assert double_results[-1][1]["differing_pixels"] > 0


@pytest.mark.parametrize("shape", ["arch", "torus"])
def test_float_and_double_hosts_agree(pymeshlab, meshlabserver, make_family, tmp_path, shape):
    mesh = make_family(shape, 2)[1]
    f_ctr, d_ctr = tmp_path / "float.ctr", tmp_path / "double.ctr"
    _run(meshlabserver, tmp_path, [mesh], [
        ("slice.mlx", {"layer_thickness": THICKNESS, "contour_file": f_ctr,
                       "encoding_file": tmp_path / "float.enc", "file_format": 0}),
        ("masks.mlx", {"contour_file": f_ctr, "output_path": tmp_path / "masks_float"}),
    ])

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
