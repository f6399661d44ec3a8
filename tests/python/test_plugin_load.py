"""The plugin loads into pymeshlab the way third-party plugins are loaded, in a fresh process;
slicereuse_pymeshlab.load() refuses to go on without either plugin, naming the missing file."""
import os
import shutil
import subprocess
import sys

import pytest

import slicereuse_pymeshlab as sr


def test_plain_load_plugin_after_importing_pymeshlab():
    code = ("import pymeshlab, sys\n"
            "pymeshlab.load_plugin(sys.argv[1])\n"
            "ms = pymeshlab.MeshSet()\n"
            "ms.create_cube()\n"
            "r = ms.apply_filter('slice_mesh_with_encoding', layer_thickness=0.25,\n"
            "                    contour_file='', encoding_file='')\n"
            "print(r['layers'], r['points'])\n")
    out = subprocess.run([sys.executable, "-c", code, str(sr.PLUGIN)], capture_output=True,
                         text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    layers, points = map(int, out.stdout.split()[-2:])
    # pymeshlab's cube is [-0.5, 0.5]^3 with 12 triangles: each section crosses the 4 vertical
    # edges and the 4 side diagonals.
    assert (layers, points) == (4, 32)


def _load_in_fresh_process(plugin):
    """Runs slicereuse_pymeshlab.load() with SLICEREUSE_PLUGIN=plugin in a new interpreter."""
    env = dict(os.environ, SLICEREUSE_PLUGIN=str(plugin),
               PYTHONPATH=os.pathsep.join([str(sr.ROOT / "python"), os.environ.get("PYTHONPATH", "")]))
    return subprocess.run([sys.executable, "-c", "import slicereuse_pymeshlab as sr; sr.load()"],
                          capture_output=True, text=True, timeout=120, env=env)


@pytest.mark.parametrize("missing", ["io", "filter"])
def test_load_refuses_a_missing_plugin_naming_it(tmp_path, missing):
    """The filter plugin copied alone into a folder: load() names the IO plugin it lacks there
    (contour files would silently not open); or no filter plugin at all."""
    plugin = tmp_path / sr.PLUGIN.name
    if missing == "io":
        shutil.copy(sr.PLUGIN, plugin)
        absent, what = tmp_path / "libio_encoding.so", "IO plugin (beside the filter plugin)"
    else:
        absent, what = plugin, "filter plugin"
    out = _load_in_fresh_process(plugin)
    assert out.returncode != 0
    assert (f"RuntimeError: slicereuse {what} not found: {absent}; build both plugins with "
            f"{sr.ROOT / 'scripts' / 'build'}") in out.stderr, out.stderr
