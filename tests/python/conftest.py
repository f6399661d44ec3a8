"""Fixtures for the pymeshlab (MeshLab 2025.07, double) host tests.

Run: scripts/python -m pytest tests/python
Needs the 2025 plugin (build/2025, or $SLICEREUSE_PLUGIN) and the family generator gen_family
($SLICEREUSE_GEN_FAMILY, else build/2020/tools/gen_family, else any build/*/tools/gen_family).
A missing gen_family is an error, not a skip: scripts/build builds it.
"""
import os
import struct
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "python"))
import slicereuse_pymeshlab as sr  # noqa: E402

THICKNESS = 0.1
HEIGHT = 8.0  # mm: every shape then fits the default 76.8 x 57.6 mm mask area


def _built_tool(name, folder, env_variable):
    """A tool of the C++ build: $env_variable, else build/2020/folder/name, else the newest
    build/*/folder/name; None when there is none."""
    env = os.environ.get(env_variable)
    candidates = [Path(env)] if env else []
    candidates.append(ROOT / "build" / "2020" / folder / name)
    candidates += sorted((ROOT / "build").glob(f"*/{folder}/{name}"), key=lambda p: -p.stat().st_mtime)
    for c in candidates:
        if c.is_file() and os.access(c, os.X_OK):
            return c
    return None


@pytest.fixture(scope="session")
def pymeshlab():
    return sr.load()


Z_CHANGE_FLAGS = {None: [], "band": ["--z-band"], "everywhere": ["--z-change"]}


@pytest.fixture(scope="session")
def make_family(tmp_path_factory):
    """make_family(shape, members, z_change=None, faces=3000, seed=1, height=HEIGHT) -> [member paths].
    z_change: None (members differ in x-y only), "band" (z also changes within one band of
    heights) or "everywhere" (z changes at every height); see tools/family/family.h.
    shuffle: members other than the base get renumbered vertices and faces (gen_family --shuffle),
    the same surfaces with other connectivity."""
    binary = _built_tool("gen_family", "tools", "SLICEREUSE_GEN_FAMILY")
    if binary is None:
        pytest.fail("gen_family not built: cmake --build build/2020 --target gen_family "
                    "(or set SLICEREUSE_GEN_FAMILY)")
    cache = {}

    def make(shape, members, z_change=None, faces=3000, seed=1, shuffle=False, height=HEIGHT):
        key = (shape, members, z_change, faces, seed, shuffle, height)
        if key not in cache:
            out = tmp_path_factory.mktemp(f"{shape}_{z_change or 'xy'}{'_shuffled' if shuffle else ''}")
            cmd = [str(binary), "--shape", shape, "--faces", str(faces), "--members", str(members),
                   "--height", str(height), "--seed", str(seed), "--out", str(out)]
            cmd += Z_CHANGE_FLAGS[z_change] + (["--shuffle"] if shuffle else [])
            subprocess.run(cmd, check=True, capture_output=True, text=True)
            cache[key] = [out / f"member_{m:03d}.ply" for m in range(members)]
        return cache[key]

    return make


def read_text_contours(path):
    """Parses a text contour file into (header dict, [(layer_z, [(open, [(x, y, z), ...]), ...])])."""
    header, layers = {}, []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "#":
                header[w[1]] = w[2:]
            elif w[0] == "layer":
                layers.append((float(w[2]), []))
            else:
                is_open = w[0] == "open"
                v = [float(x) for x in (w[1:] if is_open else w)]
                layers[-1][1].append((is_open, [tuple(v[i:i + 3]) for i in range(0, len(v), 3)]))
    return header, layers


# pymeshlab 2025.7.post1 bug (reproduced with built-in filters alone, under valgrind): after a
# filter raises, pymeshlab keeps logging into that MeshSet's log until a filter succeeds again;
# once that MeshSet is destroyed, loading a mesh into another one writes into freed memory
# (seen as std::bad_alloc in later tests). MeshSets that saw an error are kept alive here.
FAILED_MESH_SETS = []


def raises_filter_error(pymeshlab, ms, filter_name, message, **params):
    """Applies a filter that must fail with `message` in its error (a tuple: every part of it,
    for a message with figures between them), keeping ms alive."""
    FAILED_MESH_SETS.append(ms)
    with pytest.raises(pymeshlab.PyMeshLabException) as e:
        ms.apply_filter(filter_name, **params)
    for part in message if isinstance(message, tuple) else (message,):
        assert part in str(e.value), str(e.value)


def write_stl(path, triangles):
    """A binary STL of triangles (n x 3 x 3, counter-clockwise seen from outside)."""
    with open(path, "wb") as f:
        f.write(b"\0" * 80 + struct.pack("<I", len(triangles)))
        for t in triangles:
            n = np.cross(t[1] - t[0], t[2] - t[0])
            f.write(struct.pack("<12fH", *(n / np.linalg.norm(n)), *t[0], *t[1], *t[2], 0))


def box_triangles(lo, hi, inside_out=False):
    """The 12 triangles of the box [lo, hi] (3 coordinates each), facing out, or in (a cavity)."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    corner = lambda i: np.where([i & 1, i & 2, i & 4], hi, lo)  # noqa: E731
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    triangles = []
    for a, b, c, d in quads:
        for t in ((a, b, c), (a, c, d)):
            triangles.append([corner(i) for i in (t if not inside_out else t[::-1])])
    return np.array(triangles)


def cup_boxes(lo, hi, w, shared_corners=False):
    """A cup in [lo, hi] with walls w thick, open at the top, as overlapping boxes (a floor and four
    walls): apart, or sharing corners (an STL file then shares their vertices, and edges between
    four faces), the same union."""
    if shared_corners:
        return [(lo, [hi[0], hi[1], w]), (lo, [w, hi[1], hi[2]]), ([hi[0] - w, 0, 0], hi), (lo, [hi[0], w, hi[2]]),
                ([0, hi[1] - w, 0], hi)]
    return [(lo, [hi[0], hi[1], w]), ([0, 0, 1], [w, hi[1], hi[2]]), ([hi[0] - w, 0, 1], hi),
            ([1, 0, 1], [hi[0] - 1, w, hi[2]]), ([1, hi[1] - w, 1], [hi[0] - 1, hi[1], hi[2]])]


def write_printability_parts(folder):
    """Three 10 x 10 x 6 mm parts as binary STL files in folder, walls 2 mm: hollow.stl (a sealed
    cavity: a resin trap), cup.stl (open at the top: a suction cup as it prints) and solid.stl."""
    folder.mkdir(parents=True, exist_ok=True)
    lo, hi, w = np.array([0, 0, 0.0]), np.array([10, 10, 6.0]), 2.0
    write_stl(folder / "hollow.stl", np.concatenate([box_triangles(lo, hi), box_triangles(lo + w, hi - w, True)]))
    write_stl(folder / "cup.stl", np.concatenate([box_triangles(a, b) for a, b in cup_boxes(lo, hi, w)]))
    write_stl(folder / "solid.stl", box_triangles(lo, hi))
    return [folder / n for n in ("hollow.stl", "cup.stl", "solid.stl")]
