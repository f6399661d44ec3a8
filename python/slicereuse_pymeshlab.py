"""pymeshlab with the slicereuse filters loaded, plus the family pipeline.

    import slicereuse_pymeshlab as sr
    pymeshlab = sr.load()          # import pymeshlab and load the plugin (idempotent)
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh("a.ply")
    r = ms.apply_filter("slice_mesh_with_encoding", layer_thickness=0.1, encoding_file="a.srb")

The plugin is build/2025/plugins/libfilter_slicereuse.so, or $SLICEREUSE_PLUGIN; the IO plugin
libio_encoding.so next to it is loaded too (load() refuses to go on without it), so that
ms.load_new_mesh("x.ctr") opens a contour file as a layer and ms.save_current_mesh("x.cli")
writes it (also .srb, .slc). Filters loaded late are not MeshSet methods: call them through
ms.apply_filter(name, **params); the result is a dict. Errors raise pymeshlab.PyMeshLabException with the filter's message. After
catching one, keep that MeshSet alive (or run a filter on it that succeeds) before loading meshes
into another: pymeshlab 2025.7.post1 otherwise logs into the freed MeshSet (see README).
"""
import json
import os
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PLUGIN = Path(os.environ.get("SLICEREUSE_PLUGIN",
                             ROOT / "build" / "2025" / "plugins" / "libfilter_slicereuse.so"))

_pymeshlab = None


def load(plugin=None):
    """Imports pymeshlab, loads the slicereuse filter plugin and the IO plugin beside it into it
    once and returns the module. Raises RuntimeError naming a missing plugin file before
    loading either: without the IO plugin, contour files would not open as layers."""
    global _pymeshlab
    if _pymeshlab is not None:
        return _pymeshlab
    plugin = Path(plugin or PLUGIN)
    io_plugin = plugin.parent / "libio_encoding.so"
    for what, path in (("filter plugin", plugin), ("IO plugin (beside the filter plugin)", io_plugin)):
        if not path.is_file():
            raise RuntimeError(f"slicereuse {what} not found: {path}; build both plugins with "
                               f"{ROOT / 'scripts' / 'build'} (into {ROOT / 'build' / '2025' / 'plugins'})")
    import pymeshlab
    pymeshlab.load_plugin(str(plugin))
    pymeshlab.load_plugin(str(io_plugin))
    _pymeshlab = pymeshlab
    return pymeshlab


def _load_mesh(ms, path):
    ms.load_new_mesh(str(path))
    return ms.current_mesh_id()


def _check_files(paths):
    for path in paths:
        if not Path(path).is_file():
            raise FileNotFoundError(f"mesh file not found: {path}")


def _slice_source(pymeshlab, source, out, layer_thickness, binary=True):
    """Slices source once with encoding; returns the encoding's path, named as the encoding
    beside the source's contour file <stem>.srb / .ctr would be (docs/formats.md, "File names")."""
    ms = pymeshlab.MeshSet()
    _load_mesh(ms, source)
    encoding = str(Path(out) / (Path(source).stem + ("_enc.srb" if binary else ".enc")))
    ms.apply_filter("slice_mesh_with_encoding", layer_thickness=layer_thickness,
                    contour_file="", encoding_file=encoding, file_format=int(binary))
    return encoding


def family(source, targets, layer_thickness, out, profile=None, binary=True, progress=None,
           direct=False, verify=False, keep_contours=False, details=False, extension=".sl1"):
    """The production pipeline: one print job per family member, out/<member stem><extension>
    (".sl1", ".sl1s", ".goo", or "" for a folder of PNG images).

    Default: slices source once with encoding (out/<source stem>_enc.srb), then for each
    target loads it and runs make_print_job, which transfers the encoding (kept in memory by
    the plugin across members) and writes the masks, with no contour file in between.
    direct=True: the same outputs from slicing every target directly (the baseline), each
    from its own lowest vertex: the members of a family sit on one build plate (the same lowest
    z, as the source's), which is where transfer puts their layers too.
    verify=True: also slices each target directly into out/<stem>.direct<extension> and compares the
    two stacks (min_similarity, S on the binary threshold, and max_grey_difference, the largest
    difference of a pixel's grey levels: 1 and 0 for identical masks); not counted in the
    target's seconds.
    keep_contours=True: also writes out/<stem>.srb (.ctr when binary is False).
    Returns {"source", "seconds", "targets": [{"mesh", "layers", "points", "resliced_layers",
    "seconds", "output"[, "min_similarity", "max_grey_difference"]}, ...]}; a target's seconds
    cover loading it, transferring or slicing it and writing its print file. details=True adds the
    filter's own "slicing_seconds" (transfer or slicing) and "masks_seconds" per target, and
    "cpu_seconds", the process's CPU time (all threads) for the same span as "seconds" (for
    benchmarks on a shared machine, where CPU time is less disturbed than wall time).
    progress(step, steps, text) is called before each step."""
    _check_files([source, *targets])
    stems = [Path(t).stem for t in targets]
    repeated = {s for s in stems if stems.count(s) > 1}
    if repeated:
        raise ValueError(f"members with the same file name would write the same output: {sorted(repeated)}")
    pymeshlab = load()
    # make_print_job's printer parameters (printer by id, or custom values; antialiasing, gamma,
    # offsets); the filter's defaults for the others.
    profile = profile or {}
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    steps, step = 1 + len(targets) * (2 if verify else 1), 0

    def tick(text):
        nonlocal step
        if progress:
            progress(step, steps, text)
        step += 1

    start = time.perf_counter()
    encoding = ""
    if not direct:
        tick(f"slicing {Path(source).name}")
        encoding = _slice_source(pymeshlab, source, out, layer_thickness, binary)
    else:
        tick("slicing every member directly")

    results = []
    for target, stem in zip(targets, stems):
        name = Path(target).name
        tick(f"{name}: {'slicing' if direct else 'transferring'} and masks")
        t0, c0 = time.perf_counter(), time.process_time()
        ms = pymeshlab.MeshSet()
        _load_mesh(ms, target)
        output = out / f"{stem}{extension}"
        contours = str(out / (stem + (".srb" if binary else ".ctr"))) if keep_contours else ""
        # z_start is left at the filter's default: the mesh's lowest vertex.
        r = ms.apply_filter("make_print_job", encoding_file=encoding, layer_thickness=layer_thickness,
                            contour_file=contours, output_path=str(output), **profile)
        entry = {"mesh": str(target), "layers": r["layers"], "points": r["points"],
                 "resliced_layers": r["resliced_layers"], "seconds": time.perf_counter() - t0,
                 "output": str(output)}
        if details:
            entry.update(slicing_seconds=r["slicing_seconds"], masks_seconds=r["masks_seconds"],
                         cpu_seconds=time.process_time() - c0)
        if verify:
            tick(f"{name}: verifying against direct slicing")
            check = out / f"{stem}.direct{extension}"
            ms.apply_filter("make_print_job", encoding_file="", layer_thickness=layer_thickness,
                            contour_file="", output_path=str(check), **profile)
            c = ms.apply_filter("compare_mask_stacks", stack_a=str(output), stack_b=str(check),
                                report_file="")
            entry.update(min_similarity=c["min_similarity"], max_grey_difference=c["max_grey_difference"])
        results.append(entry)
        del ms
    if not direct:  # the plugin's cached encoding is not needed after the last member
        pymeshlab.MeshSet().apply_filter("free_cached_memory")
    if progress:
        progress(steps, steps, "done")
    return {"source": str(source), "seconds": time.perf_counter() - start, "targets": results}



def plates(source, targets, layer_thickness, out, profile=None, progress=None, direct=False, verify=False,
           spacing_mm=2.0, placements=None, extension=".sl1"):
    """The lab's job: the targets arranged on build plates of the printer (make_plate_job), one
    print file per plate, out/plate_<k><extension> (".sl1", ".sl1s", ".goo", or "" for folders of
    PNG images), its top view out/plate_<k>_layout.png, and out/plates.json, the placements
    (docs/formats.md, "Placements file").

    Default: slices source once with encoding (out/<source stem>_enc.srb) and transfers it onto
    every placed target (exact); direct=True slices every target directly instead, from the
    lowest vertex of all targets (the family's members sit on one build plate, the source's).
    placements: a placements file to use instead of arranging (its members named by file name).
    verify=True: also makes each plate by direct slicing from out/plates.json into
    out/plate.direct_<k><extension> and compares (min_similarity 1 and max_grey_difference 0 mean
    identical); not counted in "seconds".
    Returns {"source", "members", "seconds", "arrange_seconds", "plates": [{"output", "layout",
    "members", "area_used"[, "min_similarity", "max_grey_difference"]}, ...]}; "seconds" covers
    loading the targets, arranging, transferring or slicing and writing every plate (not slicing
    the source)."""
    _check_files([source, *targets])
    pymeshlab = load()
    profile = profile or {}
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    steps, step = 2 + (1 if verify else 0), 0

    def tick(text):
        nonlocal step
        if progress:
            progress(step, steps, text)
        step += 1

    encoding = ""
    if not direct:
        tick(f"slicing {Path(source).name}")
        encoding = _slice_source(pymeshlab, source, out, layer_thickness)
    tick(f"{len(targets)} members onto plates")
    start = time.perf_counter()
    ms = pymeshlab.MeshSet()
    for t in targets:
        _load_mesh(ms, t)
    summary = out / "plates.json"
    r = ms.apply_filter("make_plate_job", encoding_file=encoding, layer_thickness=layer_thickness,
                        spacing_mm=spacing_mm, placements_file=str(placements or ""),
                        placements_output=str(summary), output_path=str(out / f"plate{extension}"), **profile)
    seconds = time.perf_counter() - start
    written = json.loads(summary.read_text())
    result = {"source": str(source), "members": r["members"], "seconds": seconds,
              "arrange_seconds": r["arrange_seconds"], "plates": []}
    for plate in written["plates"]:
        output = plate["output"]
        result["plates"].append({"output": output, "members": [m["name"] for m in plate["members"]],
                                 "area_used": plate["area_used"],
                                 "layout": str(Path(output).with_suffix("")) + "_layout.png"})
    if verify:
        tick("verifying every plate against direct slicing")
        ms.apply_filter("make_plate_job", encoding_file="", layer_thickness=layer_thickness,
                        spacing_mm=spacing_mm, placements_file=str(summary), placements_output="",
                        output_path=str(out / f"plate.direct{extension}"), **profile)
        for k, plate in enumerate(result["plates"], 1):
            check = out / f"plate.direct_{k}{extension}"
            c = ms.apply_filter("compare_mask_stacks", stack_a=plate["output"], stack_b=str(check), report_file="")
            plate.update(min_similarity=c["min_similarity"], max_grey_difference=c["max_grey_difference"])
    del ms
    if not direct:
        pymeshlab.MeshSet().apply_filter("free_cached_memory")
    if progress:
        progress(steps, steps, "done")
    return result

if __name__ == "__main__":
    load()
    print(json.dumps({"plugin": str(PLUGIN), "loaded": True}))
