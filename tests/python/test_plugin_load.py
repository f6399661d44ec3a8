"""The plugin loads into pymeshlab the way third-party plugins are loaded, in a fresh process."""
import subprocess
import sys

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
