"""Hollowing's filters and flags through pymeshlab (#36): Hollow Mesh shows the cavity, Add Drain
Holes the holes as a point layer the jobs take back (drain_points_layer), family.py's
--drain-holes D_MM,COUNT; each drained cavity floods (no resin trap), by reuse as directly."""
import json
import subprocess

import pytest
from conftest import ROOT, THICKNESS, box_triangles, write_stl


def family_py(*args):
    return subprocess.run([str(ROOT / "scripts" / "python"), str(ROOT / "examples" / "family.py"),
                           "--layer-thickness", str(THICKNESS), "--printer", "prusa_sl1s_speed", *map(str, args)],
                          capture_output=True, text=True)


def write_box(path, size):
    path.parent.mkdir(parents=True, exist_ok=True)
    write_stl(path, box_triangles([0, 0, 0], size))
    return str(path)


def test_hollow_mesh_and_the_users_drain_holes(pymeshlab, tmp_path):
    box = write_box(tmp_path / "box.stl", [30, 15, 15])
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(box)
    shown = ms.apply_filter("hollow_mesh", layer_thickness=THICKNESS, hollow_wall_mm=3, hollow_closing_mm=0)
    assert shown["cavity_mm3"] == pytest.approx(24 * 9 * 9, rel=1e-9)  # the box less 3 mm walls
    assert shown["saved_percent"] == pytest.approx(100 * 24 * 9 * 9 / (30 * 15 * 15), rel=1e-9)
    assert ms.mesh_number() == 2
    ms.set_current_mesh(0)
    holes = ms.apply_filter("add_drain_holes", layer_thickness=THICKNESS, hollow_wall_mm=3, hollow_closing_mm=0,
                            drain_holes=2)
    assert holes["drain_holes"] == 2
    assert ms.mesh_number() == 3
    points = ms.mesh(2)
    assert points.vertex_number() == 2 and points.face_number() == 0
    assert list(points.vertex_matrix()[:, 2]) == [0, 0]  # where the holes open: the base
    ms.set_current_mesh(0)
    job = ms.apply_filter("make_print_job", layer_thickness=THICKNESS, hollow_wall_mm=3, hollow_closing_mm=0,
                          drain_points_layer=2, output_path=str(tmp_path / "job.sl1s"), printer="prusa_sl1s_speed")
    assert job["drain_holes"] == 2 and job["resin_traps"] == 0 and job["suction_cups"] == 0, job
    sealed = ms.apply_filter("make_print_job", layer_thickness=THICKNESS, hollow_wall_mm=3, hollow_closing_mm=0,
                             drain_hole_mm=0, output_path=str(tmp_path / "sealed.sl1s"), printer="prusa_sl1s_speed")
    assert sealed["resin_traps"] == 1, sealed


def test_family_drains_each_cavity_through_count_holes(pymeshlab, tmp_path):
    source = write_box(tmp_path / "parts" / "src.stl", [30, 15, 15])
    member = write_box(tmp_path / "parts" / "m1.stl", [32, 16, 15])
    run = family_py("--hollow", 3, "--drain-holes", "3,2", "--verify", "--out", tmp_path / "out", source, member)
    assert run.returncode == 0, run.stderr
    [entry] = json.loads(run.stdout)["targets"]
    assert entry["method"] == "reuse" and entry["min_similarity"] == 1 and entry["max_grey_difference"] == 0, entry
    assert entry["drain_holes"] == 2 and entry["printability"]["resin_traps"] == 0, entry
    bad = family_py("--drain-holes", "4", "--out", tmp_path / "bad", source, member)
    assert bad.returncode == 2 and "--drain-holes goes with --hollow" in bad.stderr, bad.stderr
    bad = family_py("--hollow", 3, "--drain-holes", "4,0", "--out", tmp_path / "bad", source, member)
    assert bad.returncode == 2 and "1 to 100 holes" in bad.stderr, bad.stderr
    assert not (tmp_path / "bad").exists()


def test_family_drills_the_users_holes_on_every_member(pymeshlab, tmp_path):
    """Add Drain Holes' file of the source given to family.py: each member (the same 12 triangles,
    longer) gets the hole at the same place on its own base, by reuse as directly, and its cavity
    floods."""
    source = write_box(tmp_path / "parts" / "src.stl", [30, 15, 15])
    member = write_box(tmp_path / "parts" / "m1.stl", [36, 15, 15])
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(source)
    holes = tmp_path / "holes.srp"
    ms.apply_filter("add_drain_holes", layer_thickness=THICKNESS, hollow_wall_mm=3, drain_holes_file=str(holes))
    run = family_py("--hollow", 3, "--drain-holes-file", holes, "--verify", "--out", tmp_path / "out", source, member)
    assert run.returncode == 0, run.stderr
    [entry] = json.loads(run.stdout)["targets"]
    assert entry["method"] == "reuse" and entry["min_similarity"] == 1 and entry["max_grey_difference"] == 0, entry
    assert entry["drain_holes"] == 1 and entry["printability"]["resin_traps"] == 0, entry
    bad = family_py("--drain-holes-file", holes, "--out", tmp_path / "bad", source, member)
    assert bad.returncode == 2 and "--drain-holes-file goes with --hollow" in bad.stderr, bad.stderr
