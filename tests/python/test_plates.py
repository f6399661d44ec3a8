"""Make Plate Job (issue #17) in both hosts: a plate's masks equal, pixel for pixel, the union of
its members' own masks, each member made alone on its placement (direct slicing of the placed
member), binary and anti-aliased; reuse equals direct slicing per plate; the placements file
written is read back (the same plates from it); family.py --plates. pymeshlab (2025, double)
and meshlabserver (2020, float)."""
import json
import math
import re
import struct
import subprocess
import zlib
from pathlib import Path

import numpy as np
import pytest

import slicereuse_pymeshlab as sr
from conftest import ROOT, THICKNESS
from test_hosts import _run, meshlabserver  # noqa: F401 (fixture)


def png_pixels(data):
    """The grey pixels of one of our mask PNGs (1- or 8-bit grey, no row filter) as a height x
    width array, 1-bit pixels widened to 0/255."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, bits, colour = struct.unpack(">IIBB", body[:10])
            assert colour == 0 and bits in (1, 8)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    rows = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(height, -1)
    assert not rows[:, 0].any(), "row filter"
    if bits == 8:
        return rows[:, 1:]
    return np.unpackbits(rows[:, 1:], axis=1)[:, :width] * np.uint8(255)


def ply_vertices(path):
    """The vertices of a gen_family member (tests/support/ply.cpp: little-endian doubles right
    after the header) as an n x 3 array."""
    data = path.read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    count = int(re.search(rb"element vertex (\d+)", data[:end]).group(1))
    return np.frombuffer(data, "<f8", 3 * count, end).reshape(count, 3)


def region(mask, seeds):
    """The pixels of `mask` (False on the image's border) 8-connected to the seeds in it."""
    inside = np.zeros_like(mask)
    todo = [s for s in seeds if mask[s]]
    if todo:
        inside[tuple(np.array(todo).T)] = True
    while todo:
        r, c = todo.pop()
        for n in ((r + dr, c + dc) for dr in (-1, 0, 1) for dc in (-1, 0, 1)):
            if mask[n] and not inside[n]:
                inside[n] = True
                todo.append(n)
    return inside


def assert_layout_shows(png, placements, plate, members):
    """A plate's layout picture (plate_layout.h) shows the platform at 0.1 mm a pixel in a black
    frame, and each member of the plate (placements: the placements file; members: paths by name)
    drawn on every pixel one of its placed vertices falls in (or the next: the footprint lies on
    the pixels by rounding), its light grey one region of its own, outlined in black (names are
    black too: a name over another member does not join the two); no light grey elsewhere."""
    image = png_pixels(png)
    box = placements["platform_mm"]
    height, width = image.shape
    assert (width, height) == (math.ceil((box["x1"] - box["x0"]) / 0.1), math.ceil((box["y1"] - box["y0"]) / 0.1))
    frame = np.ones_like(image, bool)
    frame[1:-1, 1:-1] = False
    assert not image[frame].any(), "the frame is black"
    assert set(np.unique(image)) <= {0, 215, 255}
    fill, paper = image == 215, image == 255
    assert not (fill[1:] & paper[:-1]).any() and not (fill[:-1] & paper[1:]).any() and \
        not (fill[:, 1:] & paper[:, :-1]).any() and not (fill[:, :-1] & paper[:, 1:]).any(), "light grey meets white"
    regions = []
    for m in plate["members"]:
        v = ply_vertices(members[m["name"]])
        t = math.radians(m["theta_deg"])
        x = math.cos(t) * v[:, 0] - math.sin(t) * v[:, 1] + m["tx_mm"]
        y = math.sin(t) * v[:, 0] + math.cos(t) * v[:, 1] + m["ty_mm"]
        cols = np.floor((x - box["x0"]) / 0.1).astype(int)
        rows = np.floor(height - (y - box["y0"]) / 0.1).astype(int)
        assert all(not paper[r - 1:r + 2, c - 1:c + 2].all() for r, c in zip(rows, cols)), \
            f"{m['name']}: a placed vertex has nothing drawn around its pixel"
        seeds = [(r + dr, c + dc) for r, c in zip(rows, cols) for dr in (-2, 0, 2) for dc in (-2, 0, 2)]
        regions.append(region(fill, seeds))
        assert regions[-1].sum() > 100, f"{m['name']} is not filled light grey"
    assert (np.sum(regions, axis=0) <= 1).all(), "two members are one region"
    assert not fill[~np.any(regions, axis=0)].any(), "light grey off the members"


def stack(path):
    """A mask stack's layers: a folder of layerNNNNN.png, as one layers x height x width array."""
    return np.stack([png_pixels(p.read_bytes()) for p in sorted(path.glob("layer*.png"))])


def union(stacks):
    """The union of member stacks (each ends where it ends); no pixel may be lit by two."""
    out = np.zeros((max(len(s) for s in stacks),) + stacks[0].shape[1:], np.uint8)
    for s in stacks:
        part = out[:len(s)]
        assert not (part.astype(bool) & s.astype(bool)).any(), "two members light one pixel"
        part |= s
    return out


def one_member_placements(written, plate, member):
    """A placements file that puts one member of `written` where it sat, alone."""
    m = written["plates"][plate]["members"][member]
    return {**written, "plates": [{"plate": 1, "area_used": 0, "members": [m]}]}


@pytest.mark.parametrize("antialiasing", [False, True], ids=["binary", "antialiased"])
def test_plate_is_the_union_of_its_members_placed_alone(pymeshlab, make_family, tmp_path, antialiasing):
    members = make_family("arch", 6, z_change="band")
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(members[0]))
    ms.apply_filter("slice_mesh_with_encoding", layer_thickness=THICKNESS, contour_file="",
                    encoding_file=str(tmp_path / "s.srb"))
    ms = pymeshlab.MeshSet()
    for m in members[1:]:
        ms.load_new_mesh(str(m))
    r = ms.apply_filter("make_plate_job", encoding_file=str(tmp_path / "s.srb"), output_path=str(tmp_path / "reuse"),
                        placements_output=str(tmp_path / "plates.json"), antialiasing=antialiasing)
    written = json.loads((tmp_path / "plates.json").read_text())
    assert r["plates"] == len(written["plates"]) >= 1 and r["members"] == 5
    assert r["transferred_layers"] > 0 and r["resliced_layers"] > 0  # the band's layers
    placed = sorted(m["name"] for p in written["plates"] for m in p["members"])
    assert placed == sorted(m.name for m in members[1:])
    # Direct slicing from the file written: the same plates, equal to reuse.
    d = ms.apply_filter("make_plate_job", placements_file=str(tmp_path / "plates.json"),
                        output_path=str(tmp_path / "direct"), antialiasing=antialiasing)
    assert d["plates"] == r["plates"] and d["transferred_layers"] == 0
    for k, plate in enumerate(written["plates"], 1):
        assert plate["output"] == str(tmp_path / f"reuse_{k}")
        reuse, direct = stack(tmp_path / f"reuse_{k}"), stack(tmp_path / f"direct_{k}")
        assert np.array_equal(reuse, direct)
        layout = (tmp_path / f"reuse_{k}_layout.png").read_bytes()
        assert_layout_shows(layout, written, plate, {m.name: m for m in members})
        assert (tmp_path / f"direct_{k}_layout.png").read_bytes() == layout
        # Each member alone on its placement, in a set of its own.
        alone = []
        for i, m in enumerate(plate["members"]):
            f = tmp_path / f"alone_{k}_{i}.json"
            f.write_text(json.dumps(one_member_placements(written, k - 1, i)))
            one = pymeshlab.MeshSet()
            one.load_new_mesh(str(next(p for p in members if p.name == m["name"])))
            one.apply_filter("make_plate_job", placements_file=str(f), output_path=str(tmp_path / f"alone_{k}_{i}"),
                             antialiasing=antialiasing)
            alone.append(stack(tmp_path / f"alone_{k}_{i}_1"))
        assert np.array_equal(reuse, union(alone)) and reuse.any()
        assert bool(((reuse > 0) & (reuse < 255)).any()) == antialiasing


def test_meshlabserver_plate_by_reuse_equals_direct_and_reads_its_placements(meshlabserver, make_family, tmp_path):
    """The float host: the example script arranges and makes the plates by reuse; the same plates
    from the placements file it wrote, sliced directly, have identical masks."""
    members = make_family("arch", 5, z_change="band")
    slice_ = ("slice.mlx", {"layer_thickness": THICKNESS, "contour_file": "", "encoding_file": tmp_path / "s.srb"})
    _run(meshlabserver, tmp_path, [members[0]], [slice_])
    plate = {"encoding_file": tmp_path / "s.srb", "placements_output": tmp_path / "plates.json",
             "output_path": tmp_path / "reuse.sl1", "printer": 5}
    direct = {"encoding_file": "", "placements_file": tmp_path / "plates.json", "placements_output": "",
              "output_path": tmp_path / "direct.sl1", "printer": 5}
    results = _run(meshlabserver, tmp_path, members[1:], [("plate_job.mlx", plate), ("plate_job.mlx", direct)])
    (_, r), (_, d) = results
    assert r["members"] == d["members"] == 4 and r["plates"] == d["plates"] >= 1
    assert r["transferred_layers"] > 0 and d["transferred_layers"] == 0
    compares = [("compare.mlx", {"stack_a": tmp_path / f"reuse_{k}.sl1", "stack_b": tmp_path / f"direct_{k}.sl1",
                                 "report_file": ""}) for k in range(1, r["plates"] + 1)]
    for _, c in _run(meshlabserver, tmp_path, [members[1]], compares):
        assert c["min_similarity"] == 1.0 and c["max_grey_difference"] == 0, c
    written = json.loads((tmp_path / "plates.json").read_text())
    for k, p in enumerate(written["plates"], 1):
        layout = (tmp_path / f"reuse_{k}_layout.png").read_bytes()
        assert_layout_shows(layout, written, p, {m.name: m for m in members})
        assert (tmp_path / f"direct_{k}_layout.png").read_bytes() == layout


def test_family_py_plates_verifies_every_plate(make_family, tmp_path):
    members = make_family("arch", 8, z_change="band")
    run = subprocess.run([str(ROOT / "scripts" / "python"), str(ROOT / "examples" / "family.py"), "--plates",
                          "--verify", "--layer-thickness", str(THICKNESS), "--printer", "prusa_sl1s_speed",
                          "--out", str(tmp_path)] + [str(m) for m in members],
                         capture_output=True, text=True, check=True)
    result = json.loads(run.stdout)
    assert result["members"] == 7
    assert sum(len(p["members"]) for p in result["plates"]) == 7
    written = json.loads((tmp_path / "plates.json").read_text())
    assert [[m["name"] for m in p["members"]] for p in written["plates"]] == \
        [[m["name"] for m in p["members"]] for p in result["plates"]]
    checked = [m.pop("printability") for p in result["plates"] for m in p["members"]]
    assert all(c["resin_traps"] == c["suction_cups"] == 0 for c in checked), checked
    assert all(m == {"name": m["name"], "method": "reuse"} for p in result["plates"] for m in p["members"])
    for p, plate in zip(result["plates"], written["plates"]):
        assert p["min_similarity"] == 1.0 and p["max_grey_difference"] == 0, p
        assert p["output"].endswith(".sl1s")
        assert_layout_shows((tmp_path / p["layout"]).read_bytes(), written, plate, {m.name: m for m in members})


def test_the_batch_reads_every_member_from_its_file(pymeshlab, make_family, tmp_path, monkeypatch):
    """plates() loads no mesh into a MeshSet: the arrangement and every plate read the members
    straight from their files (member_files), and so do the source's slicing and its support
    points; the plates are those of the same members loaded as layers, byte for byte."""
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1764000000")
    members = make_family("arch", 8)
    loads = []
    monkeypatch.setattr(pymeshlab.MeshSet, "load_new_mesh", lambda ms, path, **kw: loads.append(path))
    r = sr.plates(members[0], members[1:], out=tmp_path / "batch", layer_thickness=THICKNESS,
                  profile={"printer": "method", "antialiasing": True}, extension=".sl1", workers=0, supports=True)
    monkeypatch.undo()
    assert r["failed"] == 0 and len(r["plates"]) >= 2 and loads == [], (r, loads)
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1764000000")
    ms = pymeshlab.MeshSet()
    for m in members[1:]:
        ms.load_new_mesh(str(m))
    common = dict(layer_thickness=THICKNESS, placements_file=str(tmp_path / "batch" / "plates.json"),
                  placements_output="", printer=0, antialiasing=True, supports=2,
                  support_points_file=str(tmp_path / "batch" / "member_000_supports.srp"),
                  z_start=ms.apply_filter("slice_mesh_with_encoding", mesh_file=str(members[0]), layer_thickness=1e6,
                                          contour_file="", encoding_file="")["mesh_z_min"])
    encoding = str(tmp_path / "batch" / "member_000_enc.srb")
    (tmp_path / "layers").mkdir()
    layers = ms.apply_filter("make_plate_job", encoding_file=encoding, output_path=str(tmp_path / "layers" / "plate.sl1"),
                             **common)
    assert layers["plates"] == len(r["plates"]) and layers["read_seconds"] == 0
    for k, p in enumerate(r["plates"], 1):
        assert (tmp_path / "layers" / f"plate_{k}.sl1").read_bytes() == Path(p["output"]).read_bytes(), k


@pytest.mark.parametrize("fmt", ["stl", "ascii.stl", "obj", "ply"])
def test_member_files_give_the_masks_of_loaded_layers(pymeshlab, make_family, tmp_path, monkeypatch, fmt):
    """The two ways members reach a job, as layers loaded by pymeshlab and as files the job reads
    itself, give the same print files byte for byte, from binary and ASCII STL, OBJ and PLY
    files (written by pymeshlab); reading is reported, and the layers' way reads nothing."""
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1764000000")
    plys = make_family("arch", 4)
    files = []
    for ply in plys:
        ms = pymeshlab.MeshSet()
        ms.load_new_mesh(str(ply))
        files.append(tmp_path / f"{ply.stem}.{fmt}")
        ms.save_current_mesh(str(files[-1]), **({"binary": False} if fmt == "ascii.stl" else {}))
    ms = pymeshlab.MeshSet()
    ms.apply_filter("slice_mesh_with_encoding", mesh_file=str(files[0]), layer_thickness=THICKNESS, contour_file="",
                    encoding_file=str(tmp_path / "enc.srb"), file_format=1)
    for f in files[1:]:
        ms.load_new_mesh(str(f))
    common = dict(encoding_file=str(tmp_path / "enc.srb"), layer_thickness=THICKNESS, placements_output="",
                  printer=0, antialiasing=True)
    for way in ("layers", "read", "current", "file"):  # the same file names, as the archive holds its own
        (tmp_path / way).mkdir()
    layers = ms.apply_filter("make_plate_job", output_path=str(tmp_path / "layers" / "plate.sl1"), **common)
    read = pymeshlab.MeshSet().apply_filter("make_plate_job", member_files=";".join(map(str, files[1:])),
                                            output_path=str(tmp_path / "read" / "plate.sl1"), **common)
    assert layers["read_seconds"] == 0 < read["read_seconds"]
    assert layers["plates"] == read["plates"] >= 1 and read["direct_members"] == 0
    for k in range(1, read["plates"] + 1):
        assert (tmp_path / "layers" / f"plate_{k}.sl1").read_bytes() == (tmp_path / "read" / f"plate_{k}.sl1").read_bytes()
    ms.set_current_mesh(ms.mesh_number() - 1)
    job = dict(encoding_file=str(tmp_path / "enc.srb"), layer_thickness=THICKNESS, contour_file="", printer=0)
    current = ms.apply_filter("make_print_job", output_path=str(tmp_path / "current" / "job.sl1"), **job)
    alone = pymeshlab.MeshSet().apply_filter("make_print_job", mesh_file=str(files[-1]),
                                             output_path=str(tmp_path / "file" / "job.sl1"), **job)
    assert current["reused"] == alone["reused"] == 1 and alone["read_seconds"] > 0
    assert (tmp_path / "current" / "job.sl1").read_bytes() == (tmp_path / "file" / "job.sl1").read_bytes()


def test_a_failing_plate_is_reported_and_the_others_are_made(pymeshlab, make_family, tmp_path):
    """With strict, a plate with a member of another connectivity (no map) fails with the
    filter's message and writes nothing; its MeshSet is kept alive as a failed one (pymeshlab
    writes into it later); every other plate is made, equal to direct slicing."""
    members = make_family("arch", 8)
    other = tmp_path / "ear.ply"  # not of the arch's family
    other.write_bytes(make_family("ear", 2)[1].read_bytes())
    failed_before = len(sr._failed_meshsets)
    r = sr.plates(members[0], [*members[1:], other], out=tmp_path / "out", layer_thickness=THICKNESS,
                  profile={"printer": "method"}, verify=True, strict=True, workers=0)
    assert r["failed"] == 1 and len(r["plates"]) >= 2, r
    bad = next(p for p in r["plates"] if "error" in p)
    assert {"name": "ear.ply"} in bad["members"] and "faces" in bad["error"], bad
    assert not (tmp_path / "out" / Path(bad["output"]).name).exists()
    made = [p for p in r["plates"] if "error" not in p]
    assert all(p["min_similarity"] == 1.0 and p["max_grey_difference"] == 0 for p in made), made
    assert len(sr._failed_meshsets) == failed_before + 1


def test_meshlabserver_reads_member_files_as_it_loads_them(meshlabserver, make_family, tmp_path, monkeypatch):
    """The float host: Make Plate Job reading member_files (the plugin's reader, each coordinate
    rounded to a float as meshlabserver's loader stores it) makes the plates it makes from the
    same members loaded with -i, byte for byte (the members' PLY files hold doubles)."""
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1764000000")
    members = make_family("arch", 5)
    _run(meshlabserver, tmp_path, [members[0]],
         [("slice.mlx", {"layer_thickness": THICKNESS, "contour_file": "", "encoding_file": tmp_path / "s.srb"})])
    common = {"encoding_file": tmp_path / "s.srb", "placements_output": "", "printer": 0}
    for way in ("layers", "files"):
        (tmp_path / way).mkdir()
    (_, loaded), = _run(meshlabserver, tmp_path, members[1:],
                        [("plate_job.mlx", {**common, "output_path": tmp_path / "layers" / "plate.sl1"})])
    (_, read), = _run(meshlabserver, tmp_path, [],
                      [("plate_job.mlx", {**common, "member_files": ";".join(map(str, members[1:])),
                                          "output_path": tmp_path / "files" / "plate.sl1"})])
    assert loaded["plates"] == read["plates"] >= 1 and read["members"] == 4 and read["direct_members"] == 0
    for k in range(1, read["plates"] + 1):
        assert (tmp_path / "layers" / f"plate_{k}.sl1").read_bytes() == (tmp_path / "files" / f"plate_{k}.sl1").read_bytes()


def test_meshlabserver_arranges_then_makes_each_plate_alone(meshlabserver, make_family, tmp_path):
    """The float host: Arrange on Plates writes the placements and layouts without slicing; Make
    Plate Job from them makes every plate at once, and each plate again alone (plate k, only its
    members loaded), with the same masks and layout."""
    members = make_family("arch", 8)
    slice_ = ("slice.mlx", {"layer_thickness": THICKNESS, "contour_file": "", "encoding_file": tmp_path / "s.srb"})
    _run(meshlabserver, tmp_path, [members[0]], [slice_])
    arrange = ("arrange_plates.mlx", {"placements_output": tmp_path / "plates.json",
                                      "output_path": tmp_path / "plate.sl1", "printer": 0})
    every = ("plate_job.mlx", {"encoding_file": tmp_path / "s.srb", "placements_file": tmp_path / "plates.json",
                               "placements_output": "", "output_path": tmp_path / "all.sl1", "printer": 0})
    (_, a), (_, e) = _run(meshlabserver, tmp_path, members[1:], [arrange, every])
    assert a["members"] == e["members"] == 7 and a["plates"] == e["plates"] >= 2  # the method's small display
    assert not (tmp_path / "plate_1.sl1").exists()
    written = json.loads((tmp_path / "plates.json").read_text())
    assert [p["output"] for p in written["plates"]] == [str(tmp_path / f"plate_{k}.sl1")
                                                         for k in range(1, a["plates"] + 1)]
    by_name = {m.name: m for m in members}
    for k, plate in enumerate(written["plates"], 1):
        alone = ("plate_job.mlx", {"encoding_file": tmp_path / "s.srb", "placements_file": tmp_path / "plates.json",
                                   "placements_output": "", "output_path": tmp_path / "one.sl1", "plate": k,
                                   "printer": 0})
        [(_, r)] = _run(meshlabserver, tmp_path, [by_name[m["name"]] for m in plate["members"]], [alone])
        assert r["plates"] == 1 and r["members"] == len(plate["members"]) and r[f"area_used_{k}"] == a[f"area_used_{k}"]
        compare = ("compare.mlx", {"stack_a": tmp_path / f"one_{k}.sl1", "stack_b": tmp_path / f"all_{k}.sl1",
                                   "report_file": ""})
        [(_, c)] = _run(meshlabserver, tmp_path, [members[1]], [compare])
        assert c["min_similarity"] == 1.0 and c["max_grey_difference"] == 0, c
        layout = (tmp_path / f"plate_{k}_layout.png").read_bytes()
        assert layout == (tmp_path / f"one_{k}_layout.png").read_bytes() == (tmp_path / f"all_{k}_layout.png").read_bytes()
        assert_layout_shows(layout, written, plate, by_name)
