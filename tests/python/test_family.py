"""The production family pipeline on the pymeshlab host (slicereuse_pymeshlab.family and
examples/family.py): one .sl1 per member, by transfer (default) or direct slicing (--direct),
with identical outputs; --verify compares against direct slicing (S = 1)."""
import json
import re
import subprocess
import zipfile

import pytest

import slicereuse_batch as batch
import slicereuse_pymeshlab as sr
from conftest import ROOT, THICKNESS, raises_filter_error
from test_batch import family_py

SHAPES = ["arch", "ear", "handle", "box", "sphere", "torus"]
TARGET_KEYS = {"mesh", "layers", "points", "resliced_layers", "seconds", "output", "method", "worker",
               "printability"}
CASES = [(shape, z) for z in (None, "band") for shape in SHAPES] + [("arch", "everywhere")]


def layer_pngs(sl1):
    """The layer images of an .sl1 archive by name (config.ini carries a time stamp): the PNGs at
    its root (the thumbnails are in thumbnail/)."""
    with zipfile.ZipFile(sl1) as z:
        return {n: z.read(n) for n in z.namelist() if n.endswith(".png") and "/" not in n}


@pytest.mark.parametrize("shape, z_change", CASES, ids=[f"{s}-{z or 'xy'}" for s, z in CASES])
def test_reuse_and_direct_write_identical_print_jobs(make_family, tmp_path, shape, z_change):
    """The default pipeline (transfer) and --direct write the same .sl1 layer images byte for
    byte, --verify reports S = 1, and the layer counts show the path taken: x-y members transfer
    every layer; a z change within one band re-slices that band and transfers most; a z change
    everywhere fails most certificates, so the member is sliced directly."""
    members = make_family(shape, 3, z_change=z_change)
    reused = sr.family(members[0], members[1:], THICKNESS, tmp_path / "reuse", verify=True, extension=".sl1")
    direct = sr.family(members[0], members[1:], THICKNESS, tmp_path / "direct", direct=True, extension=".sl1")
    assert reused["source"] == direct["source"] == str(members[0])
    for r, d, member in zip(reused["targets"], direct["targets"], members[1:]):
        assert r["mesh"] == d["mesh"] == str(member)
        assert r["worker"] == d["worker"] == "in-process"
        assert set(r) == TARGET_KEYS | {"min_similarity", "max_grey_difference"} and set(d) == TARGET_KEYS
        assert r["output"] == str(tmp_path / "reuse" / f"{member.stem}.sl1")
        assert r["method"] == "reuse" and d["method"] == "direct"
        assert r["points"] == d["points"] > 0, (r, d)
        assert r["layers"] == d["layers"], (r, d)
        # x-y and band members keep the base's height: 8 mm at 0.1 mm.
        assert r["layers"] == (80 if z_change != "everywhere" else pytest.approx(80, abs=3)), r
        assert d["resliced_layers"] == d["layers"], d
        assert r["min_similarity"] == 1.0 and r["max_grey_difference"] == 0, r
        images = layer_pngs(r["output"])
        assert len(images) == r["layers"]
        assert images == layer_pngs(d["output"])
        transferred = r["layers"] - r["resliced_layers"]
        if z_change is None:
            assert r["resliced_layers"] == 0, r
        elif z_change == "band":
            assert r["resliced_layers"] > 0 and transferred > 2 * r["resliced_layers"], r
        else:
            assert transferred == 0, r
    # No contour files in between: the encoding and the .sl1 archives only (and the batch's records).
    names = sorted(p.name for p in (tmp_path / "reuse").iterdir() if p.name != ".slicereuse-batch")
    stems = [m.stem for m in members[1:]]
    assert names == sorted([f"{members[0].stem}_enc.srb"] + [f"{s}.sl1" for s in stems] +
                           [f"{s}.direct.sl1" for s in stems])
    assert sorted(p.name for p in (tmp_path / "direct").iterdir()) == sorted([".slicereuse-batch"] +
                                                                             [f"{s}.sl1" for s in stems])


@pytest.mark.parametrize("printer, extension", [("prusa_sl1s_speed", ".sl1s"), ("prusa_sl1", ".sl1"),
                                                ("anycubic_photon_mono_x", ".sl1")])
def test_anti_aliased_print_jobs_of_a_printer_by_reuse_equal_direct_slicing(make_family, tmp_path, printer,
                                                                            extension):
    """A real printer's anti-aliased print files by reuse equal direct slicing's byte for byte on
    every layer, and carry grey levels."""
    members = make_family("arch", 3)
    profile = {"printer": printer, "antialiasing": True}
    reused = sr.family(members[0], members[1:], THICKNESS, tmp_path / "reuse", profile=profile, verify=True,
                       extension=extension)
    direct = sr.family(members[0], members[1:], THICKNESS, tmp_path / "direct", profile=profile, direct=True,
                       extension=extension)
    for r, d in zip(reused["targets"], direct["targets"]):
        assert r["output"].endswith(extension)
        assert r["min_similarity"] == 1.0 and r["max_grey_difference"] == 0, r
        images = layer_pngs(r["output"])
        assert len(images) == r["layers"] == 80
        assert images == layer_pngs(d["output"])
        middle = images[sorted(images)[40]]
        assert middle[24:26] == bytes([8, 0])  # 8-bit grey
        model = next(p["job"]["model"] for p in json.loads(sr.PRESETS.read_text())["presets"] if p["id"] == printer)
        with zipfile.ZipFile(r["output"]) as z:
            assert f"printer_model = {model}\n" in z.read("prusaslicer.ini").decode()


def test_keep_contours_writes_each_members_contour_file(pymeshlab, make_family, tmp_path):
    members = make_family("arch", 3)
    result = sr.family(members[0], members[1:], THICKNESS, tmp_path, keep_contours=True, extension=".sl1")
    for t, member in zip(result["targets"], members[1:]):
        ms = pymeshlab.MeshSet()
        ms.load_new_mesh(str(member))
        # The kept contour file gives the same masks through Export Mask Images.
        ms.apply_filter("export_mask_images", contour_file=str(tmp_path / f"{member.stem}.srb"),
                        output_path=str(tmp_path / f"{member.stem}.again.sl1"))
        assert layer_pngs(tmp_path / f"{member.stem}.again.sl1").keys() == {
            n.replace(member.stem, f"{member.stem}.again") for n in layer_pngs(t["output"])}
        c = ms.apply_filter("compare_mask_stacks", stack_a=t["output"],
                            stack_b=str(tmp_path / f"{member.stem}.again.sl1"), report_file="")
        assert c["min_similarity"] == 1.0 and c["max_grey_difference"] == 0 and c["layers"] == t["layers"]


def test_cli_prints_one_json_object(make_family, tmp_path):
    members = make_family("arch", 3)
    out = subprocess.run([str(ROOT / "scripts" / "python"), str(ROOT / "examples" / "family.py"),
                          "--layer-thickness", str(THICKNESS), "--out", str(tmp_path / "out"),
                          "--verify", *map(str, members)], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    result = json.loads(out.stdout)
    assert set(result) == {"source", "seconds", "source_seconds", "engine", "failed", "targets"}
    # The default engine: this process where one worker process would be all (2 cores or fewer).
    n = batch.default_workers()
    engine = batch.IN_PROCESS if n == 1 else f"LocalCluster of {n} worker processes"
    assert result["failed"] == 0 and result["engine"] == engine
    assert len(result["targets"]) == 2
    for t in result["targets"]:
        assert set(t) == TARGET_KEYS | {"min_similarity", "max_grey_difference"}
        assert isinstance(t["layers"], int) and isinstance(t["points"], int)
        assert t["resliced_layers"] == 0
        assert 0 < t["seconds"] < result["seconds"]
        assert t["min_similarity"] == 1.0 and t["max_grey_difference"] == 0
    # 8 mm at 0.1 mm: layers whose bottom is below the top, z in [0, 8].
    assert result["targets"][0]["layers"] == 80
    assert out.stderr == ""  # no progress bar when stderr is not a terminal


PRESETS = json.loads(sr.PRESETS.read_text())["presets"]
# Each preset by id, a custom printer (the method's display given by its values) and none.
PRINTERS = [(p["id"], ["--printer", p["id"]], p["extension"], p["job"]["model"]) for p in PRESETS] + [
    ("custom", ["--printer", "custom", "--width", "1024", "--height", "768", "--pixel-um", "75"], "", ""),
    ("none", [], "", "")]


@pytest.mark.parametrize("args, extension, model", [p[1:] for p in PRINTERS], ids=[p[0] for p in PRINTERS])
def test_family_py_makes_the_printers_own_print_file(make_family, tmp_path, args, extension, model):
    """Without --format, family.py makes the print file the printer's preset lists in
    common/printer/presets.json (a folder of PNG images for custom printers and none): an .sl1s
    for the SL1S that says it is for one, which its firmware lists."""
    members = make_family("arch", 2)
    run = family_py("--workers", "0", "--layer-thickness", "0.5", *args, *members, out=tmp_path)
    result = json.loads(run.stdout)
    (member,) = result["targets"]
    output = tmp_path / f"{members[1].stem}{extension}"
    assert member["output"] == str(output) and member["layers"] == 16, member
    if extension in (".sl1", ".sl1s"):
        with zipfile.ZipFile(output) as z:
            assert f"printerModel = {model}\n" in z.read("config.ini").decode()
        assert len(layer_pngs(output)) == 16
        assert (model == "SL1S") == (extension == ".sl1s")
    elif extension == ".goo":
        assert output.read_bytes()[:4] == b"V3.0"
    elif extension == ".ctb":  # Chitubox's magic number, little-endian: version 3's, or version 4's
        version = int.from_bytes(output.read_bytes()[4:8], "little")
        assert output.read_bytes()[:4] == bytes([0x86 if version == 3 else 0x06, 0x00 if version == 3 else 0x01,
                                                 0xFD, 0x12]), version
    elif extension in (".pwmx", ".pwma", ".pwmb", ".pm4n", ".pm5", ".pm5s"):  # Photon Workshop's files
        assert output.read_bytes()[:12] == b"ANYCUBIC\0\0\0\0"
    else:
        assert extension == "", extension
        assert sorted(p.name for p in output.iterdir()) == [f"layer{k:05d}.png" for k in range(16)]


@pytest.mark.parametrize("args, message", [
    (["--layer-thickness", "0"], "--layer-thickness must be greater than 0"),
    (["--layer-thickness", "0.1", "--printer", "nonesuch"],
     "family: error: unknown printer 'nonesuch': one of method, prusa_sl1, prusa_sl1s_speed, "
     "anycubic_photon_mono_x, elegoo_saturn_3_ultra, elegoo_mars_2_pro, phrozen_sonic_mighty_4k, "
     "anycubic_photon_mono_x_6k, anycubic_photon_mono_4, anycubic_photon_mono_m5s, or custom"),
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


def test_a_member_that_cannot_be_reused_is_sliced_directly_unless_strict(make_family, tmp_path):
    """A member of other connectivity (the same surface, its vertices and faces renumbered: no
    map from the source) is sliced directly, its entry saying so, equal to direct slicing, while
    the others are reused; on a plate, that member says so; with strict, it fails saying why."""
    members = make_family("arch", 3)
    renumbered = tmp_path / "renumbered.ply"
    renumbered.write_bytes(make_family("arch", 3, shuffle=True)[2].read_bytes())
    r = sr.family(members[0], [members[1], renumbered], THICKNESS, tmp_path / "family", verify=True)
    reused, direct = r["targets"]
    assert r["failed"] == 0 and reused["method"] == "reuse" and direct["method"] == "direct", r
    assert "direct_reason" not in reused and direct["direct_reason"] == sr.NOT_OF_THE_FAMILY, direct
    assert direct["min_similarity"] == 1.0 and direct["max_grey_difference"] == 0, direct
    (plate,) = sr.plates(members[0], [members[1], renumbered], THICKNESS, tmp_path / "plates", verify=True)["plates"]
    # Arches stand on the plate, with no cavity (their steep walls leave single-pixel islands).
    checked = [m.pop("printability") for m in plate["members"]]
    assert all(c["resin_traps"] == c["suction_cups"] == 0 for c in checked), checked
    assert sorted(plate["members"], key=lambda m: m["name"]) == [
        {"name": members[1].name, "method": "reuse"},
        {"name": "renumbered.ply", "method": "direct", "direct_reason": sr.NOT_OF_THE_FAMILY}]
    assert plate["min_similarity"] == 1.0 and plate["max_grey_difference"] == 0, plate
    strict = sr.family(members[0], [members[1], renumbered], THICKNESS, tmp_path / "strict", strict=True)
    assert strict["failed"] == 1, strict
    assert re.fullmatch(r"Make Print Job: renumbered\.ply cannot be made by reuse: its faces differ from those of "
                        r"the mesh the encoding was made from \(encoding: 3008 faces, hash [0-9a-f]{16}; target: 3008 "
                        r"faces, hash [0-9a-f]{16}\) \(strict is on; off, it would be sliced directly\)",
                        strict["targets"][1]["error"]), strict


def test_members_with_the_same_file_name_are_refused(make_family, tmp_path):
    members = make_family("arch", 3)
    with pytest.raises(ValueError, match="same file name"):
        sr.family(members[0], [members[1], members[1]], THICKNESS, tmp_path)


def test_print_job_reads_the_encoding_once(pymeshlab, make_family, tmp_path):
    """make_print_job keeps the last encoding in memory: read for the first member, reused for
    the next and when the same bytes are written again, read again when the file is rewritten
    with another content or another file is named."""
    members = make_family("arch", 4)
    encoding = tmp_path / "source.srb"

    def slice_source(thickness=THICKNESS):
        ms = pymeshlab.MeshSet()
        ms.load_new_mesh(str(members[0]))
        ms.apply_filter("slice_mesh_with_encoding", layer_thickness=thickness, contour_file="",
                        encoding_file=str(encoding), file_format=1)

    def job(member, enc=encoding):
        ms = pymeshlab.MeshSet()
        ms.load_new_mesh(str(member))
        return ms.apply_filter("make_print_job", encoding_file=str(enc),
                               output_path=str(tmp_path / f"{member.stem}.sl1"))

    slice_source()
    first, second = job(members[1]), job(members[2])
    assert (first["encoding_cached"], second["encoding_cached"]) == (0, 1)
    assert first["transferred_layers"] == second["transferred_layers"] == 80
    slice_source()  # the same bytes written again
    assert job(members[3])["encoding_cached"] == 1
    slice_source(2 * THICKNESS)  # another encoding under the same name
    rewritten = job(members[3])
    assert rewritten["encoding_cached"] == 0 and rewritten["transferred_layers"] == 40
    encoding.rename(tmp_path / "moved.srb")
    assert job(members[1], tmp_path / "moved.srb")["encoding_cached"] == 0


def test_free_cached_memory_gives_back_the_encoding(pymeshlab, make_family, tmp_path):
    """free_cached_memory drops the encoding that make_print_job kept (its bytes reported), and
    the next print job reads the file again."""
    members = make_family("arch", 2)
    encoding = tmp_path / "source.srb"
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(members[0]))
    ms.apply_filter("slice_mesh_with_encoding", layer_thickness=THICKNESS, contour_file="",
                    encoding_file=str(encoding), file_format=1)
    ms.load_new_mesh(str(members[1]))
    job = ms.apply_filter("make_print_job", encoding_file=str(encoding), output_path=str(tmp_path / "m1.sl1"))
    freed = ms.apply_filter("free_cached_memory")
    # The cache holds the encoding (face, edge, t: 13 bytes per point) and its edge ends (8).
    assert freed["encoding_bytes"] >= 21 * job["points"]
    assert freed["freed_bytes"] >= freed["encoding_bytes"]
    assert ms.apply_filter("free_cached_memory")["encoding_bytes"] == 0
    again = ms.apply_filter("make_print_job", encoding_file=str(encoding), output_path=str(tmp_path / "m1b.sl1"))
    assert again["encoding_cached"] == 0 and again["transferred_layers"] == job["transferred_layers"] == 80


def test_print_job_within_a_memory_limit_slices_a_range_at_a_time(pymeshlab, make_family, tmp_path, monkeypatch):
    """A direct print job whose contours would take more than a quarter of the memory it may use
    (here capped by SLICEREUSE_MEMORY_LIMIT) is sliced and exported a range of layers at a time;
    the archive equals the one made from the whole stack: the same layer images byte for byte and
    the same resin volume."""
    member = make_family("arch", 1)[0]
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(member))
    whole = ms.apply_filter("make_print_job", layer_thickness=THICKNESS, output_path=str(tmp_path / "whole.sl1"))
    assert whole["layer_ranges"] == 1 and whole["layers"] == 80
    stack_bytes = 24 * whole["points"]
    monkeypatch.setenv("SLICEREUSE_MEMORY_LIMIT", str(4 * stack_bytes // 3))  # a quarter: 1/3 of the stack
    ranged = ms.apply_filter("make_print_job", layer_thickness=THICKNESS, output_path=str(tmp_path / "ranged.sl1"))
    assert 3 <= ranged["layer_ranges"] <= 5, ranged
    assert (ranged["layers"], ranged["points"], ranged["resliced_layers"]) == (80, whole["points"], 80)
    images = lambda sl1: [png for _, png in sorted(layer_pngs(sl1).items())]  # names carry the job's name
    assert images(tmp_path / "ranged.sl1") == images(tmp_path / "whole.sl1")

    def used_material(sl1):
        with zipfile.ZipFile(sl1) as z:
            return [l for l in z.read("config.ini").decode().splitlines() if l.startswith("usedMaterial")]

    assert used_material(tmp_path / "ranged.sl1") == used_material(tmp_path / "whole.sl1") != []
    # A contour file needs the whole stack: it is sliced whole (it fits the 4/3 of the stack).
    kept = ms.apply_filter("make_print_job", layer_thickness=THICKNESS, output_path=str(tmp_path / "kept.sl1"),
                           contour_file=str(tmp_path / "kept.srb"))
    assert kept["layer_ranges"] == 1 and (tmp_path / "kept.srb").exists()
    # Below the stack itself, slicing it whole is refused with the figures; nothing is written.
    monkeypatch.setenv("SLICEREUSE_MEMORY_LIMIT", str(stack_bytes // 2))
    raises_filter_error(pymeshlab, ms, "make_print_job", "GB of memory, but only", layer_thickness=THICKNESS,
                        output_path=str(tmp_path / "no.sl1"), contour_file=str(tmp_path / "no.srb"))
    assert not (tmp_path / "no.sl1").exists() and not (tmp_path / "no.srb").exists()
    monkeypatch.setenv("SLICEREUSE_MEMORY_LIMIT", "plenty")
    raises_filter_error(pymeshlab, ms, "make_print_job", "SLICEREUSE_MEMORY_LIMIT is 'plenty'",
                        layer_thickness=THICKNESS, output_path=str(tmp_path / "no.sl1"))
