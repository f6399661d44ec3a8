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
import contextlib
import json
import os
import time
from dataclasses import dataclass
from pathlib import Path

import slicereuse_batch as batch

ROOT = Path(__file__).resolve().parent.parent
PLUGIN = Path(os.environ.get("SLICEREUSE_PLUGIN",
                             ROOT / "build" / "2025" / "plugins" / "libfilter_slicereuse.so"))
PRESETS = ROOT / "common" / "printer" / "presets.json"

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
    # pymeshlab brings numpy, whose OpenBLAS threads the filters never use but which spin for a
    # while after numpy's import, against the plugin's OpenMP threads (3 % of a plate job's CPU):
    # one BLAS thread, unless the caller chose otherwise before numpy was imported.
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    import pymeshlab
    pymeshlab.load_plugin(str(plugin))
    pymeshlab.load_plugin(str(io_plugin))
    _pymeshlab = pymeshlab
    return pymeshlab


def _presets():
    return json.loads(PRESETS.read_text())


def print_file_extensions():
    """The print files the plugins write, by extension (".sl1", ".ctb", ...), as the "formats" of
    common/printer/presets.json list them; "" (a folder of PNG images) is not among them."""
    return [f["extension"] for f in _presets()["formats"]]


def printer_extension(printer=None):
    """The print file a printer's jobs are made into unless told otherwise: its preset's
    "extension" in common/printer/presets.json (one of print_file_extensions(), or "" for a folder
    of PNG images). printer: a preset id; None and "custom" (a display of one's own) take the
    method's."""
    presets = {p["id"]: p for p in _presets()["presets"]}
    preset = "method" if printer in (None, "custom") else printer
    if preset not in presets:
        raise ValueError(f"unknown printer '{printer}': one of {', '.join(presets)}, or custom")
    return presets[preset]["extension"]


def _check_files(paths):
    for path in paths:
        if not Path(path).is_file():
            raise FileNotFoundError(f"mesh file not found: {path}")


@dataclass
class EncodingJob(batch.Job):
    """The source sliced once with encoding, into outputs[0]."""
    mesh: str
    layer_thickness: float
    binary: bool


@dataclass
class SupportPointsJob(batch.Job):
    """The source's support points generated once (generate_support_points, on the planes its
    encoding has), into outputs[0]."""
    mesh: str
    layer_thickness: float


@dataclass
class MemberJob(batch.Job):
    """One member's print job (family()): target made into output by make_print_job; contours
    and check ("" none) its contour file and its direct slicing, compared; supports as
    _support_parameters says."""
    target: str
    output: str
    contours: str
    check: str
    layer_thickness: float
    profile: dict
    details: bool
    strict: bool
    supports: str
    printability: str
    labels: dict
    hollow: dict


@dataclass
class ArrangeJob(batch.Job):
    """The plates' arrangement (plates()): targets arranged by arrange_on_plates, or placed as
    placements ("" none) says, for print files named after output, into outputs[0]."""
    targets: list[str]
    placements: str
    spacing_mm: float
    profile: dict
    output: str
    layer_thickness: float
    z_start: float
    supports: str


@dataclass
class PlateJob(batch.Job):
    """One plate's print file (plates()): plate k of the placements file summary, its members at
    paths, made after plate_output, the plates' pattern; check_output ("" none) the pattern of
    its direct slicing, compared."""
    plate: int
    summary: str
    paths: list[str]
    layer_thickness: float
    z_start: float
    profile: dict
    strict: bool
    plate_output: str
    check_output: str
    supports: str
    printability: str
    labels: dict
    hollow: dict


def _encode_source(source, out, layer_thickness, epoch, resume, binary=True):
    """Slices source once with encoding, as a batch job (complete or absent, recorded); with
    resume, an encoding an earlier run made from the same source and thickness is kept. Returns
    the encoding's path, named as the encoding beside the source's contour file <stem>.srb /
    .ctr would be (docs/formats.md, "File names")."""
    encoding = Path(out) / (Path(source).stem + ("_enc.srb" if binary else ".enc"))
    job = EncodingJob(name=encoding.name, out=str(out), outputs=[str(encoding)], epoch=epoch,
                      base={"mesh": str(source)}, mesh=str(source), binary=binary,
                      layer_thickness=layer_thickness,
                      key=batch.key_of(source=batch.file_identity(source), layer_thickness=layer_thickness,
                                       binary=binary))
    if not (resume and batch.valid_record(job)):
        made = batch.attempt(_make_encoding, job, "", batch.IN_PROCESS)
        if "error" in made:
            raise RuntimeError(f"slicing {source}: {made['error']}")
    return encoding


# supports for family() and plates(): none, generated on every member, or the source's points
# (the file _generate_source_points writes) transferred to every member.
NO_SUPPORTS, GENERATE_SUPPORTS = "", "generate"


def _support_parameters(supports):
    """make_print_job's and make_plate_job's supports parameters for supports: NO_SUPPORTS,
    GENERATE_SUPPORTS, or the absolute path of the source's support-points file (transfer)."""
    mode = 0 if supports == NO_SUPPORTS else 1 if supports == GENERATE_SUPPORTS else 2
    return {"supports": mode, "support_points_file": supports if mode == 2 else ""}


# A member's support figures in the filters' results (per member on a plate: "<key>_<name>").
SUPPORT_KEYS = ("support_points", "kept", "moved", "added", "dropped")
# The jobs' printability figures (make_print_job's and make_plate_job's, and per plate member
# with the member's name after them), as an entry's "printability".
PRINTABILITY_KEYS = ("islands", "overhangs", "resin_traps", "suction_cups", "touching_bounds")


PRINTABILITY = ("check", "require", "off")


def _check_parameters(printability):
    """make_print_job's and make_plate_job's check parameters for printability: "check" (count the
    findings), "require" (also refuse a file with an island, resin trap or suction cup), "off"."""
    if printability not in PRINTABILITY:
        raise ValueError(f"printability must be one of {', '.join(PRINTABILITY)}, not {printability!r}")
    return {"check_printability": printability != "off", "require_printable": printability == "require"}


LABEL_DEPTH_MM, LABEL_MIN_DEPTH_MM = 3.0, 0.5  # the filters' default depth; the least this sets
# The filters' label_side, in its order: the base, or a side seen from above (front -y, back +y,
# left -x, right +x).
LABEL_SIDES = ("base", "front", "back", "left", "right")


def _label_parameters(labels, allow_unlabelled=False, hollow=None, side="base"):
    """make_print_job's and make_plate_job's label parameters for labels: None (no labels),
    "names" (each member's file name without its extension) or the path of a labels file (CSV,
    docs/formats.md "Labels file"); allow_unlabelled prints a member whose label fits nowhere
    without it (else its job fails naming it). 3 mm deep, or with hollow (walls in mm) 1 mm less
    than the walls where that is less, so that the letters keep 1 mm from the cavity. side: one
    of LABEL_SIDES."""
    if side not in LABEL_SIDES:
        raise ValueError(f"label_side must be one of {', '.join(LABEL_SIDES)}, not {side!r}")
    if labels is None:
        if side != "base":
            raise ValueError(f"label_side={side!r} goes with labels")
        return {"labels": False, "labels_file": "", "allow_unlabelled": False}
    if labels != "names" and not Path(labels).is_file():
        raise ValueError(f'labels must be None, "names" or a labels file (CSV), but {labels!r} is no file')
    depth = LABEL_DEPTH_MM
    if hollow is not None:
        if not hollow > 1 + LABEL_MIN_DEPTH_MM:
            raise ValueError(f"labels on hollowed members need walls over {1 + LABEL_MIN_DEPTH_MM:g} mm thick (the "
                             f"letters keep 1 mm from the cavity), not {hollow!r} mm")
        depth = min(depth, hollow - 1)
    parameters = {"labels": True, "labels_file": "" if labels == "names" else str(Path(labels).resolve()),
                  "label_depth_mm": depth, "allow_unlabelled": bool(allow_unlabelled)}
    if side != "base":  # the filter's default otherwise: a batch's resume keys stay as they were
        parameters["label_side"] = LABEL_SIDES.index(side)
    return parameters


def _hollow_parameters(hollow, drain_holes=None, drain_holes_file=None):
    """make_print_job's and make_plate_job's hollowing parameters for hollow: None (solid) or the
    wall thickness in mm (PrusaSlicer's closing distance, 2 mm, kept), drain_holes: None (one
    4 mm hole per cavity), a diameter in mm (0: none), or (diameter, holes per cavity), and
    drain_holes_file: None, or the user's holes (Add Drain Holes' .srp file), which replace the
    automatic ones."""
    if hollow is None:
        if drain_holes is not None or drain_holes_file is not None:
            raise ValueError("drain_holes and drain_holes_file need hollow: a wall thickness in mm")
        return {"hollow_wall_mm": 0.0}
    if not (isinstance(hollow, (int, float)) and hollow > 0):
        raise ValueError(f"hollow must be None (solid) or a wall thickness in mm above 0, not {hollow!r}")
    parameters = {"hollow_wall_mm": float(hollow)}
    if drain_holes_file is not None:
        if not Path(drain_holes_file).is_file():
            raise ValueError(f"drain_holes_file {drain_holes_file} is not a file")
        parameters["drain_holes_file"] = str(Path(drain_holes_file).resolve())
    if drain_holes is None:
        return parameters
    diameter, count = drain_holes if isinstance(drain_holes, (tuple, list)) else (drain_holes, 1)
    if not (isinstance(diameter, (int, float)) and diameter >= 0 and isinstance(count, int) and 1 <= count <= 100):
        raise ValueError(f"drain_holes must be a diameter in mm (0: none) or (diameter, 1 to 100 holes per cavity), "
                         f"not {drain_holes!r}")
    return dict(parameters, drain_hole_mm=float(diameter), drain_holes=count)


def _hollow_identity(parameters):
    """What a batch's resume key holds of its hollowing parameters: the holes file's identity."""
    if "drain_holes_file" not in parameters:
        return dict(parameters)
    return dict(parameters, drain_holes_file=batch.file_identity(parameters["drain_holes_file"]))


def _labels_identity(parameters):
    """What a batch's resume key holds of its label parameters: the labels file's identity."""
    if not parameters["labels_file"]:
        return dict(parameters)
    return dict(parameters, labels_file=batch.file_identity(parameters["labels_file"]))


def _add_cavity(entry, result, suffix="", hollowed=True):
    """The entry with "cavity_mm3" (0: too thin for a cavity) and "drain_holes" when the job hollowed
    its member (a plate member's with suffix)."""
    cavity = result.get(f"cavity_mm3{suffix}")
    if cavity is None or not hollowed:
        return entry
    return dict(entry, cavity_mm3=cavity, drain_holes=result[f"drain_holes{suffix}"])


def _add_label(entry, result, suffix=""):
    """The entry with "label_height_mm", when the job labelled its member (a plate member's with
    suffix)."""
    height = result.get(f"label_height_mm{suffix}", -1)
    return entry if height < 0 else dict(entry, label_height_mm=height)


def _add_printability(entry, result, suffix=""):
    """The entry's "printability" from a checked job's result (a plate member's with suffix)."""
    if result["islands"] < 0:  # not checked
        return entry
    figures = {k: result[k + suffix] for k in PRINTABILITY_KEYS}
    if not suffix:
        figures["trapped_mm3"] = result["trapped_mm3"]
    return dict(entry, printability=figures)


def _generate_source_points(source, out, layer_thickness, epoch, resume):
    """Generates the source's support points once, as a batch job, into out/<source stem>_supports.srp
    (kept with resume when an earlier run made it from the same source and thickness), on the
    planes of its encoding (its lowest vertex, layer_thickness). Returns the file's path."""
    points = Path(out) / (Path(source).stem + "_supports.srp")
    job = SupportPointsJob(name=points.name, out=str(out), outputs=[str(points)], epoch=epoch,
                           base={"mesh": str(source)}, mesh=str(source), layer_thickness=layer_thickness,
                           key=batch.key_of(source=batch.file_identity(source), layer_thickness=layer_thickness))
    if not (resume and batch.valid_record(job)):
        made = batch.attempt(_make_source_points, job, "", batch.IN_PROCESS)
        if "error" in made:
            raise RuntimeError(f"support points of {source}: {made['error']}")
    return points


def _make_source_points(job, _shared):
    with _meshset() as ms:
        r = ms.apply_filter("generate_support_points", mesh_file=job.mesh, layer_thickness=job.layer_thickness,
                            support_points_file=job.outputs[0])
    return {"support_points": r["points"]}


# The filters' z_start for "the lowest vertex" (of the mesh, or of all members).
LOWEST_VERTEX = -1e30


def _lowest_vertex(path):
    """The lowest vertex's z of the mesh at path: where its slicing (and encoding) starts; the
    slicing filter's mesh_z_min, the mesh read straight from its file and cut by a single plane."""
    with _meshset() as ms:
        return ms.apply_filter("slice_mesh_with_encoding", mesh_file=str(path), layer_thickness=1e6, contour_file="",
                               encoding_file="")["mesh_z_min"]


def _supports_identity(supports):
    """supports (as _job_supports gives it) for a job's key: the points file's identity."""
    return supports if supports in (NO_SUPPORTS, GENERATE_SUPPORTS) else batch.file_identity(supports)


def _job_supports(supports, direct, out, source, layer_thickness, epoch, resume):
    """What every member's job does for supports: NO_SUPPORTS without supports; with --direct,
    GENERATE_SUPPORTS on every member; by reuse, the source's points generated once, whose path
    every member's job transfers from."""
    if not supports:
        return NO_SUPPORTS
    if direct:
        return GENERATE_SUPPORTS
    return str(_generate_source_points(source, out, layer_thickness, epoch, resume))


def family(source, targets, layer_thickness, out, profile=None, binary=True, progress=None,
           direct=False, verify=False, keep_contours=False, details=False, extension=None,
           workers=0, scheduler=None, resume=False, send_encoding=False, strict=False, supports=False,
           printability="check", labels=None, allow_unlabelled=False, hollow=None, label_side="base",
           drain_holes=None, drain_holes_file=None):
    """The production pipeline: one print job per family member, out/<member stem><extension>
    (one of print_file_extensions(), or "" for a folder of PNG images; None: the printer's own,
    printer_extension(profile's printer)).

    Default: slices source once with encoding (out/<source stem>_enc.srb), then for each
    target runs make_print_job, which reads it from its file (no MeshLab layer), transfers the
    encoding (kept in memory by the plugin across members) and writes the masks, with no contour
    file in between.
    direct=True: the same outputs from slicing every target directly (the baseline), each
    from its own lowest vertex: the members of a family sit on one build plate (the same lowest
    z, as the source's), which is where transfer puts their layers too.
    verify=True: also slices each target directly into out/<stem>.direct<extension> and compares the
    two stacks (min_similarity, S on the binary threshold, and max_grey_difference, the largest
    difference of a pixel's grey levels: 1 and 0 for identical masks); not counted in the
    target's seconds.
    keep_contours=True: also writes out/<stem>.srb (.ctr when binary is False).
    A member whose slicing cannot be reused (another connectivity, no map) is sliced directly,
    its entry's "method" "direct" and "direct_reason" why; strict=True fails it instead, with
    the reason.
    supports=True: every member is printed on supports: by reuse, the source's support points
    are generated once (out/<source stem>_supports.srp) and every member's job transfers them
    (certified, completed where the member needs more); with direct=True, every member's job
    generates its own. Each entry then says "support_points", "kept", "moved", "added",
    "dropped" (as transfer_support_points; all but support_points 0 when generated) and
    "support_seconds" (the member's points and tree, inside its seconds).
    printability="check" (the default): every print file is checked as it is written (UVtools'
    checks, docs/formats.md "Printability report"), each entry's "printability" counting
    "islands", "overhangs", "resin_traps", "suction_cups", "touching_bounds" and giving
    "trapped_mm3"; "require": also, a member whose file would hold an island, a resin trap or a
    suction cup is not written, and its entry's "error" names each such finding, its layers and
    place; "off": no check (and no "printability").
    labels="names" cuts each member's file name without its extension into its base, a labels
    file (CSV, docs/formats.md "Labels file") its row's label, mirrored to read from below and
    as large as fits up to 7.5 mm; each entry then has "label_height_mm". A label that fits
    nowhere fails the member's job (its "error" names it), or with allow_unlabelled=True leaves
    it off ("label_height_mm" 0); with hollow, the letters are 1 mm less deep than the walls where
    that is less than 3 mm. label_side="front", "back", "left" or "right" (-y, +y, -x, +x seen
    from above) cuts the label upright into that side instead, readable from outside, centred
    along it where it is flat (within half the depth) and solid behind the letters. hollow=WALL_MM hollows every member on its contours with walls
    that thick (make_print_job's hollow_wall_mm, PrusaSlicer's 2 mm closing distance) and a 4 mm
    drain hole under each cavity, through the bottom wall to the base (drain_holes: another
    diameter in mm, 0 for none, or (diameter, count), count holes spread over each cavity's lowest
    layer); drain_holes_file: the user's holes instead (Add Drain Holes' .srp file, made on a member
    with the same faces: each member gets them at the same place on its own surface); each entry
    then has "cavity_mm3" (0: too thin for a cavity) and "drain_holes".

    Where the members are made (slicereuse_batch.py): workers=0 (the default) in this process;
    workers=N an embedded Dask LocalCluster of N worker processes (None: one per two cores, slicereuse_batch.default_workers);
    scheduler="tcp://host:port" an existing Dask cluster whose workers write to out at the same
    path; they read the source's encoding from out, or with send_encoding=True it is sent once
    to each worker. Every member is a task whose outputs
    appear complete or not at all, recorded in
    out/.slicereuse-batch/; resume=True skips members (and the source's slicing) whose outputs
    are complete and valid from an earlier run with the same inputs and parameters. A member
    that fails is reported with its message, and the others are made.

    Returns {"source", "seconds", "source_seconds", "engine", "failed", "targets": [{"mesh", "layers", "points",
    "resliced_layers", "seconds", "output", "method", "worker"[, "min_similarity",
    "max_grey_difference"][, "resumed"]} or {"mesh", "worker", "error"}, ...]} in the order of targets;
    "method" "reuse" or "direct" (the filter's "reused"); a target's
    seconds cover reading it, transferring or slicing it and writing its print file; "worker"
    made it ("in-process", or the Dask worker's name); "resumed": made by an earlier run;
    "source_seconds": of "seconds", slicing the source (0 when kept or direct).
    details=True adds the filter's own "read_seconds" (reading the member's file),
    "slicing_seconds" (transfer or slicing) and "masks_seconds" per target, and "cpu_seconds", the process's CPU time (all threads) for the
    same span as "seconds" (for benchmarks on a shared machine, where CPU time is less disturbed
    than wall time). progress(step, steps, text) is called after each step."""
    _check_files([source, *targets])
    _check_parameters(printability)  # before the source is sliced
    hollow_parameters = _hollow_parameters(hollow, drain_holes, drain_holes_file)
    label_parameters = _label_parameters(labels, allow_unlabelled, hollow, label_side)
    stems = [Path(t).stem for t in targets]
    repeated = {s for s in stems if stems.count(s) > 1}
    if repeated:
        raise ValueError(f"members with the same file name would write the same output: {sorted(repeated)}")
    load()
    # make_print_job's printer parameters (printer by id, or custom values; antialiasing, gamma,
    # offsets); the filter's defaults for the others.
    profile = profile or {}
    extension = printer_extension(profile.get("printer")) if extension is None else extension
    out = Path(out).resolve()
    (out / batch.RECORDS).mkdir(parents=True, exist_ok=True)
    epoch = batch.batch_epoch()
    start = time.perf_counter()
    steps, step = 1 + len(targets), 0

    encoding = ""
    if not direct:
        encoding = _encode_source(source, out, layer_thickness, epoch, resume, binary)
        step += 1
        if progress:
            progress(step, steps, f"sliced {Path(source).name}")
    member_supports = _job_supports(supports, direct, out, source, layer_thickness, epoch, resume)
    source_seconds = time.perf_counter() - start

    parameters = dict(encoding=batch.file_identity(encoding) if encoding else None,
                      layer_thickness=layer_thickness, profile=profile, verify=verify, details=details,
                      strict=strict, supports=_supports_identity(member_supports),
                      printability=printability, labels=_labels_identity(label_parameters), hollow=_hollow_identity(hollow_parameters))
    jobs = []
    for target, stem in zip(targets, stems):
        output = out / f"{stem}{extension}"
        contours = out / (stem + (".srb" if binary else ".ctr")) if keep_contours else None
        check = out / f"{stem}.direct{extension}" if verify else None
        # Workers elsewhere, started in other folders, open the member by its absolute path.
        jobs.append(MemberJob(name=output.name, out=str(out), epoch=epoch, base={"mesh": str(target)},
                              outputs=[str(p) for p in (output, contours, check) if p],
                              key=batch.key_of(target=batch.file_identity(target), **parameters),
                              target=str(Path(target).resolve()), output=str(output), contours=str(contours or ""),
                              check=str(check or ""), layer_thickness=layer_thickness, profile=profile,
                              details=details, strict=strict, supports=member_supports,
                              printability=printability, labels=label_parameters, hollow=hollow_parameters))
    with batch.engine(workers, scheduler, setup=load) as engine:
        targets_out = _run_jobs(engine, jobs, _make_member, encoding, send_encoding, resume, progress, step, steps)
        engine.finish(_free_cached_memory)
    return {"source": str(source), "seconds": time.perf_counter() - start, "source_seconds": source_seconds,
            "engine": engine.description, "failed": sum("error" in e for e in targets_out), "targets": targets_out}


def _run_jobs(engine, jobs, make, encoding, send_encoding, resume, progress, done, steps):
    """family()'s and plates()'s tasks on engine (slicereuse_batch.engine): with resume, the
    jobs an earlier run made (valid_record) are kept, marked "resumed"; make(job, encoding) runs
    the others, sharing encoding ("" none) with them; progress counts on from done. Returns the
    entries in the order of jobs."""
    entries = {}
    if resume:
        for job in jobs:
            kept = batch.valid_record(job)
            if kept:
                entries[job.name] = dict(kept, resumed=True)
    todo = [job for job in jobs if job.name not in entries]
    if todo:
        shared = engine.share(encoding, send_encoding) if encoding else ""
        entries.update(batch.run(engine, make, todo, shared, progress, done=done + len(entries), steps=steps))
    if progress:
        progress(steps, steps, "done")
    return [entries[job.name] for job in jobs]


_failed_meshsets = []

# The members the plates' arrangement loaded in this process, kept for the plates' tasks that
# run here (each then loads none of its members, and gives them back when made):
# {"ms": MeshSet, "ids": {path: mesh id}, "identity": {path: batch.file_identity(path)}}.
@contextlib.contextmanager
def _meshset():
    """A new MeshSet for one job. One whose filter failed is kept alive until the process ends:
    pymeshlab 2025.7.post1 writes into it later otherwise (see README)."""
    ms = _pymeshlab.MeshSet()
    try:
        yield ms
    except Exception as e:
        _failed_meshsets.append(ms)
        if isinstance(e, _pymeshlab.PyMeshLabException):
            # The filter's own message, without pymeshlab's "Failed to apply filter: name\nDetails: ".
            raise RuntimeError(str(e).split("\nDetails: ", 1)[-1]) from None
        raise


def _make_encoding(job, _shared):
    with _meshset() as ms:
        ms.apply_filter("slice_mesh_with_encoding", mesh_file=job.mesh, layer_thickness=job.layer_thickness,
                        contour_file="", encoding_file=job.outputs[0], file_format=int(job.binary))
    return {}


def _make_member(job, encoding):
    """One member's print job (a family() task): make_print_job reads it from its file (no layer)
    and transfers encoding (a path; "" slices it directly); with job.check, also slices it
    directly into that file and compares."""
    with _meshset() as ms:
        t0, c0 = time.perf_counter(), time.process_time()
        # z_start is left at the filter's default: the mesh's lowest vertex.
        supports = _support_parameters(job.supports)
        r = ms.apply_filter("make_print_job", mesh_file=job.target, encoding_file=encoding,
                            layer_thickness=job.layer_thickness, contour_file=job.contours, output_path=job.output,
                            strict=job.strict, **_check_parameters(job.printability), **supports,
                            **job.labels, **job.hollow, **job.profile)
        entry = _add_printability({"layers": r["layers"], "points": r["points"],
                                   "resliced_layers": r["resliced_layers"], "seconds": time.perf_counter() - t0,
                                   "output": job.output, "method": "reuse" if r["reused"] else "direct"}, r)
        entry = _add_cavity(_add_label(entry, r), r, hollowed=job.hollow["hollow_wall_mm"] > 0)
        if job.supports:
            entry.update({k: r[k] for k in SUPPORT_KEYS}, support_seconds=r["support_seconds"])
        if encoding and not r["reused"]:
            entry["direct_reason"] = NOT_OF_THE_FAMILY
        if job.details:
            entry.update(read_seconds=r["read_seconds"], slicing_seconds=r["slicing_seconds"],
                         masks_seconds=r["masks_seconds"],
                         cpu_seconds=time.process_time() - c0)
        if job.check:
            # The same supports (the same points), so that only the layers' making differs.
            ms.apply_filter("make_print_job", mesh_file=job.target, encoding_file="", layer_thickness=job.layer_thickness,
                            contour_file="", output_path=job.check, check_printability=False, **supports,
                            **job.labels, **job.hollow, **job.profile)
            c = ms.apply_filter("compare_mask_stacks", stack_a=job.output, stack_b=job.check, report_file="")
            entry.update(min_similarity=c["min_similarity"], max_grey_difference=c["max_grey_difference"])
    return entry


def _free_cached_memory():
    """The plugin's cached encoding is not needed after a batch's last task."""
    load().MeshSet().apply_filter("free_cached_memory")


def plates(source, targets, layer_thickness, out, profile=None, progress=None, direct=False, verify=False,
           spacing_mm=2.0, placements=None, extension=None, workers=0, scheduler=None, resume=False,
           strict=False, supports=False, printability="check", labels=None, allow_unlabelled=False,
           hollow=None, label_side="base", drain_holes=None, drain_holes_file=None):
    """The lab's job: the targets arranged on build plates of the printer, one print file per
    plate, out/plate_<k><extension> (one of print_file_extensions(), or "" for folders of PNG images;
    None: the printer's own, printer_extension(profile's printer)), its top view
    out/plate_<k>_layout.png, and out/plates.json, the placements (docs/formats.md, "Placements
    file").

    Default: slices source once with encoding (out/<source stem>_enc.srb) and transfers it onto
    every placed target (exact); direct=True slices every target directly instead, from the
    lowest vertex of all targets (the family's members sit on one build plate, the source's).
    First all targets are arranged (arrange_on_plates) or, with placements (a placements file, its
    members named by file name), placed as it says, as a task on the engine; then every plate is
    a task (make_plate_job with that plate only). Both read the members straight from their
    files (the filters' member_files), without a MeshLab layer each. Workers,
    scheduler, resume and strict as for family(). verify=True: also makes each plate by direct
    slicing into out/direct/, under the plate's file name, and compares (min_similarity 1 and
    max_grey_difference 0 mean identical); not counted in a plate's seconds.
    supports=True: every member on supports, as for family() (the source's points generated once
    and transferred, or with direct=True generated on every member); each plate job makes its
    members' supports before placing them (placements then keep the supports' footprints apart),
    and each member of a plate's entry says "support_points", "kept", "moved", "added",
    "dropped"; the plate's entry "support_seconds".
    printability as for family(): every plate checked as it is written, its entry's
    "printability" (as family()'s) and each member's its own counts (a finding goes to the member
    whose footprint holds it); "require": a plate holding an island, a resin trap or a suction cup
    is not written, its entry's "error" naming each such finding, its member and place.
    labels, allow_unlabelled, label_side, hollow, drain_holes and drain_holes_file as for family():
    each plate member's entry has "label_height_mm", "cavity_mm3" and "drain_holes", and the layout
    pictures name the members by their labels.
    Returns {"source", "members", "seconds", "arrange_seconds", "engine", "failed", "plates":
    [{"output", "layout", "members", "area_used", "layers", "points", "seconds", "worker"[,
    "min_similarity", "max_grey_difference"][, "resumed"]} or {"output", "layout", "members",
    "area_used", "worker", "error"}, ...]}; "members" [{"name", "method"}, ...] ({"name"} on a plate
    that failed), "method" "reuse" or "direct" (the filter's "sliced_directly_<name>"); "seconds"
    covers arranging and making every plate (not slicing the source)."""
    _check_files([source, *targets])
    _check_parameters(printability)  # before anything is arranged
    hollow_parameters = _hollow_parameters(hollow, drain_holes, drain_holes_file)
    label_parameters = _label_parameters(labels, allow_unlabelled, hollow, label_side)
    by_name = {Path(t).name: str(Path(t).resolve()) for t in targets}
    if len(by_name) != len(targets):
        names = [Path(t).name for t in targets]
        raise ValueError("members with the same file name would have the same name on a plate: "
                         f"{sorted({n for n in names if names.count(n) > 1})}")
    load()
    profile = profile or {}
    extension = printer_extension(profile.get("printer")) if extension is None else extension
    out = Path(out).resolve()
    (out / batch.RECORDS).mkdir(parents=True, exist_ok=True)
    if verify:
        (out / "direct").mkdir(exist_ok=True)
    epoch = batch.batch_epoch()
    encoding = "" if direct else _encode_source(source, out, layer_thickness, epoch, resume)
    member_supports = _job_supports(supports, direct, out, source, layer_thickness, epoch, resume)
    start = time.perf_counter()

    summary = out / "plates.json"
    placements = str(Path(placements).resolve()) if placements else ""
    # With supports, the arrangement makes them on the plates' planes for the members' footprints:
    # by reuse the encoding's (from the source's lowest vertex), directly the lowest of all members.
    z_start = _lowest_vertex(source) if member_supports and encoding else LOWEST_VERTEX
    arrange = ArrangeJob(name=summary.name, out=str(out), outputs=[str(summary)], epoch=epoch,
                         base={"members": len(targets)}, targets=list(by_name.values()), placements=placements,
                         spacing_mm=spacing_mm, profile=profile, output=str(out / f"plate{extension}"),
                         layer_thickness=layer_thickness, z_start=z_start, supports=member_supports,
                         key=batch.key_of(targets=[batch.file_identity(t) for t in targets], spacing_mm=spacing_mm,
                                          placements=batch.file_identity(placements) if placements else None,
                                          profile=profile, extension=extension, layer_thickness=layer_thickness,
                                          supports=_supports_identity(member_supports)))
    with batch.engine(workers, scheduler, setup=load) as engine:
        arranged = resume and batch.valid_record(arrange)
        if not arranged:
            arranged = next(engine.submit_all(_arrange, [arrange], ""))[1]
            if "error" in arranged:
                engine.finish(_free_cached_memory)
                raise RuntimeError(arranged["error"])
        layout = json.loads(summary.read_text())
        steps = len(layout["plates"]) + 1
        if progress:
            progress(1, steps, f"{len(targets)} members on {len(layout['plates'])} plates")

        parameters = dict(placements=batch.file_identity(summary), encoding=batch.file_identity(encoding)
                          if encoding else None, layer_thickness=layer_thickness, profile=profile, verify=verify,
                          strict=strict, supports=_supports_identity(member_supports),
                          printability=printability, labels=_labels_identity(label_parameters),
                          hollow=_hollow_identity(hollow_parameters))
        jobs = []
        for k, plate in enumerate(layout["plates"], 1):
            output = plate["output"]
            # The direct slicing's pattern has the plates' name in its own folder, so its plate k
            # has plate k's file name.
            check = out / "direct" / Path(output).name if verify else None
            members = [m["name"] for m in plate["members"]]
            jobs.append(PlateJob(name=Path(output).name, out=str(out), epoch=epoch,
                                 base={"output": output, "layout": plate["layout"],
                                       "members": [{"name": m} for m in members], "area_used": plate["area_used"]},
                                 outputs=[str(p) for p in (output, check) if p],
                                 key=batch.key_of(plate=k, **parameters), plate=k, summary=str(summary),
                                 paths=[by_name[m] for m in members], layer_thickness=layer_thickness,
                                 z_start=arranged["z_start"], profile=profile, strict=strict,
                                 plate_output=arrange.output,
                                 check_output=str(out / "direct" / f"plate{extension}") if verify else "",
                                 supports=member_supports, printability=printability,
                                 labels=label_parameters, hollow=hollow_parameters))
        plates_out = _run_jobs(engine, jobs, _make_plate, encoding, False, resume, progress, 1, steps)
        engine.finish(_free_cached_memory)
    return {"source": str(source), "members": arranged["members"], "seconds": time.perf_counter() - start,
            "arrange_seconds": arranged["arrange_seconds"], "engine": engine.description,
            "failed": sum("error" in e for e in plates_out), "plates": plates_out}


def _arrange(job, _shared):
    """The plates' placements (a plates() task, on the engine): every target read from its file,
    arranged by arrange_on_plates or placed as job.placements says, into job.outputs[0] with the
    layout pictures; also the lowest vertex of all targets, where direct slicing of every plate
    starts."""
    with _meshset() as ms:
        r = ms.apply_filter("arrange_on_plates", member_files=";".join(job.targets), spacing_mm=job.spacing_mm,
                            placements_file=job.placements, placements_output=job.outputs[0],
                            output_path=job.output, layer_thickness=job.layer_thickness, z_start=job.z_start,
                            **_support_parameters(job.supports), **job.profile)
    return {"members": r["members"], "arrange_seconds": r["arrange_seconds"], "z_start": r["z_min"]}


# Why a member given the source's encoding was sliced directly. pymeshlab returns the filters'
# numbers only (reused, sliced_directly_<name>); the one cause they report is this one, whose
# details (the two meshes' face counts and hashes) are in the filter's log line.
NOT_OF_THE_FAMILY = ("its faces are not those of the source's mesh (another connectivity, and no map), so it was "
                     "sliced directly")


def _plate_member(member, encoding, result):
    """A plate member's summary entry: its name and method, and why when sliced for want of reuse;
    its support figures when it has supports; its printability."""
    name = member["name"]
    member = _add_printability(
        dict(member, **{k: result[f"{k}_{name}"] for k in SUPPORT_KEYS if f"{k}_{name}" in result}), result,
        f"_{name}")
    member = _add_cavity(_add_label(member, result, f"_{name}"), result, f"_{name}")
    if not encoding:
        return dict(member, method="direct")
    if result.get(f"sliced_directly_{name}"):
        return dict(member, method="direct", direct_reason=NOT_OF_THE_FAMILY)
    return dict(member, method="reuse")


def _make_plate(job, encoding):
    """One plate's print file (a plates() task): its members read from their files by
    make_plate_job (no layer each) and made into that plate by transfer of encoding (a path; ""
    slices directly from job.z_start); with job.check_output, also by direct slicing into that
    pattern's plate, compared. Each member says how it was made: "direct" when there is no
    encoding or the filter could not reuse it."""
    t0 = time.perf_counter()
    with _meshset() as ms:
        common = dict(member_files=";".join(job.paths), layer_thickness=job.layer_thickness, z_start=job.z_start,
                      placements_file=job.summary, plate=job.plate, placements_output="", strict=job.strict,
                      **_support_parameters(job.supports), **job.labels, **job.hollow, **job.profile)
        r = ms.apply_filter("make_plate_job", encoding_file=encoding, output_path=job.plate_output,
                            **_check_parameters(job.printability), **common)
        members = [_plate_member(m, encoding, r) for m in job.base["members"]]
        entry = _add_printability({"members": members, "layers": r["layers"], "points": r["points"],
                                   "seconds": time.perf_counter() - t0}, r)
        if job.supports:
            entry["support_seconds"] = r["support_seconds"]
        if job.check_output:
            ms.apply_filter("make_plate_job", encoding_file="", output_path=job.check_output,
                            check_printability=False, **common)
            c = ms.apply_filter("compare_mask_stacks", stack_a=job.outputs[0], stack_b=job.outputs[1],
                                report_file="")
            entry.update(min_similarity=c["min_similarity"], max_grey_difference=c["max_grey_difference"])
    return entry


if __name__ == "__main__":
    load()
    print(json.dumps({"plugin": str(PLUGIN), "loaded": True}))
