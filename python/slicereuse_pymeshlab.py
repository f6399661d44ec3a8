"""pymeshlab with the slicereuse filters loaded, plus the family pipeline.

    import slicereuse_pymeshlab as sr
    pymeshlab = sr.load()          # import pymeshlab and load the plugin (idempotent)
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh("a.ply")
    r = ms.apply_filter("slice_mesh_with_encoding", layer_thickness=0.1, encoding_file="a.srb")

The plugin is build/2025/plugins/libfilter_slicereuse.so, or $SLICEREUSE_PLUGIN; the IO plugin
libio_encoding.so next to it is loaded too, so that ms.load_new_mesh("x.ctr") opens a contour
file as a layer and ms.save_current_mesh("x.cli") writes it (also .srb, .slc). Filters
loaded late are not MeshSet methods: call them through ms.apply_filter(name, **params); the
result is a dict. Errors raise pymeshlab.PyMeshLabException with the filter's message. After
catching one, keep that MeshSet alive (or run a filter on it that succeeds) before loading meshes
into another: pymeshlab 2025.7.post1 otherwise logs into the freed MeshSet (see README).
"""
import json
import os
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PLUGIN = Path(os.environ.get("SLICEREUSE_PLUGIN",
                             ROOT / "build" / "2025" / "plugins" / "libfilter_slicereuse.so"))

_pymeshlab = None


def load(plugin=None):
    """Imports pymeshlab, loads the slicereuse plugin into it once and returns the module."""
    global _pymeshlab
    if _pymeshlab is not None:
        return _pymeshlab
    plugin = Path(plugin or PLUGIN)
    if not plugin.is_file():
        raise RuntimeError(f"slicereuse plugin not found: {plugin}; build it with "
                           f"cmake -S {ROOT} -B {ROOT}/build/2025 -G Ninja "
                           f"-DSLICEREUSE_MESHLAB_API=2025 && cmake --build {ROOT}/build/2025")
    import pymeshlab
    pymeshlab.load_plugin(str(plugin))
    io_plugin = plugin.parent / "libio_encoding.so"
    if io_plugin.is_file():
        pymeshlab.load_plugin(str(io_plugin))
    _pymeshlab = pymeshlab
    return pymeshlab


DEFAULT_PROFILE = {"width_px": 1024, "height_px": 768, "pixel_size_x_um": 75.0, "pixel_size_y_um": 75.0}


def _load_mesh(ms, path):
    ms.load_new_mesh(str(path))
    return ms.current_mesh_id()


def family(source, targets, layer_thickness, out, profile=None, binary=True, progress=None):
    """Slices source with encoding, then for each target: transfers the slicing, slices it
    directly, writes both mask stacks and compares them. Returns
    {"source": str, "targets": [{"mesh", "layers", "points", "direct_points", "resliced_layers",
    "transfer_seconds", "direct_seconds", "transfer_total_seconds", "direct_total_seconds",
    "min_similarity"}, ...]}.
    progress(step, steps, text) is called before each step."""
    for path in [source, *targets]:
        if not Path(path).is_file():
            raise FileNotFoundError(f"mesh file not found: {path}")
    pymeshlab = load()
    profile = dict(DEFAULT_PROFILE, **(profile or {}))
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    ext = ".srb" if binary else ".ctr"
    steps, step = 1 + 6 * len(targets), 0

    def tick(text):
        nonlocal step
        if progress:
            progress(step, steps, text)
        step += 1

    tick(f"slicing {Path(source).name}")
    ms = pymeshlab.MeshSet()
    _load_mesh(ms, source)
    encoding = out / ("source_encoding.srb" if binary else "source.enc")
    ms.apply_filter("slice_mesh_with_encoding", layer_thickness=layer_thickness,
                    contour_file=str(out / f"source{ext}"), encoding_file=str(encoding),
                    file_format=int(binary))
    del ms

    results = []
    for i, target in enumerate(targets, start=1):
        name = Path(target).name
        folder = out / f"{i:03d}_{Path(target).stem}"
        folder.mkdir(exist_ok=True)
        ms = pymeshlab.MeshSet()
        tick(f"{name}: loading")
        mesh_id = _load_mesh(ms, target)
        tick(f"{name}: transferring")
        t = ms.apply_filter("transfer_slicing_to_mesh", encoding_file=str(encoding),
                            target_mesh=mesh_id, mode=0,
                            contour_file=str(folder / f"transfer{ext}"))
        tick(f"{name}: masks (transfer)")
        ms.apply_filter("export_mask_images", contour_file=str(folder / f"transfer{ext}"),
                        output_path=str(folder / "masks_transfer"), **profile)
        tick(f"{name}: slicing directly")
        ms.set_current_mesh(mesh_id)
        d = ms.apply_filter("slice_mesh_with_encoding", layer_thickness=layer_thickness,
                            contour_file=str(folder / f"direct{ext}"), encoding_file="",
                            file_format=int(binary))
        tick(f"{name}: masks (direct)")
        ms.apply_filter("export_mask_images", contour_file=str(folder / f"direct{ext}"),
                        output_path=str(folder / "masks_direct"), **profile)
        tick(f"{name}: comparing")
        c = ms.apply_filter("compare_mask_stacks", stack_a=str(folder / "masks_transfer"),
                            stack_b=str(folder / "masks_direct"),
                            report_file=str(folder / "compare.csv"))
        # *_seconds: transfer versus slicing in memory; *_total_seconds add reading and
        # writing the files.
        results.append({"mesh": str(target), "layers": t["layers"], "points": t["points"],
                        "direct_points": d["points"], "resliced_layers": t["resliced_layers"],
                        "transfer_seconds": t["transfer_seconds"], "direct_seconds": d["slicing_seconds"],
                        "transfer_total_seconds": t["seconds"], "direct_total_seconds": d["seconds"],
                        "min_similarity": c["min_similarity"]})
    if progress:
        progress(steps, steps, "done")
    return {"source": str(source), "targets": results}


if __name__ == "__main__":
    load()
    print(json.dumps({"plugin": str(PLUGIN), "loaded": True}))
