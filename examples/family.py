"""Makes the print jobs of a product family: one print file per member, reusing one member's slicing.

    scripts/python examples/family.py --layer-thickness H --out DIR [--printer ID] [--antialiasing]
                                      [--format EXT] [--direct] [--verify] [--keep-contours]
                                      [--plates [--spacing MM] [--placements FILE]]
                                      [--workers N | --scheduler tcp://HOST:PORT [--send-encoding]]
                                      [--resume] [--strict] [--supports]
                                      [--require-printable | --no-check]
                                      [--labels [FILE.csv] [--allow-unlabelled] [--label-side SIDE]]
                                      [--hollow WALL_MM [--drain-holes D_MM[,COUNT]] [--drain-holes-file FILE.srp]]
                                      MESH0 MESH1 ...

Default: slices MESH0 once with encoding, then for each member MESH1 ...: reads it (STL, PLY or
OBJ, straight into the job: no MeshLab layer), transfers the slicing (exact: the result equals
slicing it) and writes DIR/<member file stem> with the
printer's own print file (its preset's extension in common/printer/presets.json: .sl1, .sl1s,
.goo, .ctb, .pwmx, ..., or a folder of PNG images for the method's display and custom printers;
--format chooses another), all in memory, with no contour file unless --keep-contours.
--direct: the same outputs by slicing every member directly (the baseline). --verify: also
slices each member directly and compares the masks (min_similarity 1 and max_grey_difference 0
mean identical).
A member whose slicing cannot be reused (another connectivity, no map) is sliced directly, its
entry's "method" "direct" and "direct_reason" saying why; --strict fails it instead, with the reason.
--supports: every member is printed on supports (PrusaSlicer's SL1S defaults: raised 5 mm, on a
pad): MESH0's support points are generated once into DIR/<MESH0 stem>_supports.srp and every
member's job transfers them (certified on the member, completed where it needs more); with
--direct every member generates its own. Each member's entry (on --plates, each plate member's)
gains "support_points", "kept", "moved", "added", "dropped", and "support_seconds".
Every print file is checked as it is written, as UVtools checks it: each entry (each plate's, and
each plate member's) has "printability": {"islands", "overhangs", "resin_traps", "suction_cups",
"touching_bounds"[, "trapped_mm3"]}. --require-printable: a member (or plate) whose file would
hold an island, a resin trap or a suction cup is not written; its entry's "error" names each.
--no-check: no check (it adds about two fifths to a member's time; bench/RESULTS.md).
--labels: each member's file stem (or, --labels FILE.csv, its row's label: docs/formats.md,
"Labels file") is cut 3 mm deep into its base, mirrored to read from below, as large as fits up
to 7.5 mm; each member's entry gains "label_height_mm", and the plates' layout pictures name the
members by their labels. A label that fits nowhere fails its member (or plate), naming it, unless
--allow-unlabelled (then it is printed without, "label_height_mm" 0). --label-side front, back,
left or right (-y, +y, -x, +x seen from above) cuts it upright into that side instead, readable
from outside, where the side is flat.
--hollow WALL_MM: every member hollowed on its contours with walls that thick (PrusaSlicer's
hollowing, its 2 mm closing distance), a 4 mm drain hole under each cavity through the bottom
wall to the base; each entry gains "cavity_mm3" (0: too thin for a cavity) and "drain_holes".
--drain-holes D_MM[,COUNT]: the drain holes' diameter (0: none, the cavity sealed) and how many
per cavity (1), spread over its lowest layer. --drain-holes-file FILE.srp: the holes Add Drain
Holes wrote (on a member with the same faces), edited or not, instead: each member gets them at
the same place on its own surface, drilled along the surface's normal into the cavity.
With --labels too, the letters are cut 1 mm less deep than the walls where that is less than 3 mm.
Prints one JSON object: {"source": MESH0, "seconds": total, "source_seconds", "engine",
"failed", "targets": [{"mesh", "layers", "points", "resliced_layers", "seconds", "output",
"method", "worker", "printability"[, "min_similarity", "max_grey_difference"][, "resumed"]}
or {"mesh", "worker", "error"}, ...]}; a member's seconds cover reading it, transferring or
slicing it and writing its print file, "method" is "reuse" or "direct", "worker" says which
worker process made it. A progress bar goes to a terminal's
stderr.

Members are tasks of a Dask cluster (python/slicereuse_batch.py): by default an embedded
LocalCluster of --workers worker processes on this machine (default: one per two cores, each
with two threads, the best measured here, and on two cores or fewer everything in this process, as
with --workers 0: one worker process would only add its start-up); --scheduler an existing cluster (`dask scheduler` and `dask worker`
elsewhere, README "Family batches on a cluster"), whose workers write to DIR at the same path.
Outputs appear complete or not at all; --resume skips members whose outputs an earlier run made
complete and valid (checked by content, with the same inputs and parameters). A member that
fails is reported in its entry as "error" with the message, the others are made, and the exit
status is 1.

--plates: the lab's job instead, many members per print: MESH1 ... are arranged on build plates
of the printer (footprints --spacing mm apart, 2 by default, and from the display's edges,
turned about z where that packs more), one print file per plate DIR/plate_<k> (with the
printer's extension, as above) with its top view DIR/plate_<k>_layout.png, and DIR/plates.json,
the placements (docs/formats.md); --placements FILE places them as that file says instead. By
reuse of MESH0's slicing, or --direct; --verify compares each plate with direct slicing
(DIR/direct/plate_<k>). Prints {"source", "members", "seconds", "arrange_seconds", "plates":
[{"output", "layout", "members": [{"name", "method"}, ...], "area_used"[,
"min_similarity", "max_grey_difference"]}, ...]}.
"""
import argparse
import json
import sys

import slicereuse_pymeshlab as sr


def progress_bar(step, steps, text):
    width = 30
    filled = width * step // max(steps, 1)
    sys.stderr.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {step}/{steps} {text[:50]:<50}")
    if step == steps:
        sys.stderr.write("\n")
    sys.stderr.flush()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--layer-thickness", type=float, required=True, help="layer thickness in mm")
    ap.add_argument("--out", required=True, help="output folder (created if missing)")
    ap.add_argument("--direct", action="store_true", help="slice every member directly (the baseline)")
    ap.add_argument("--verify", action="store_true",
                    help="also slice each member directly and compare the masks "
                         "(min_similarity, max_grey_difference)")
    ap.add_argument("--keep-contours", action="store_true", help="also write each member's contour file")
    presets = [p["id"] for p in json.loads(sr.PRESETS.read_text())["presets"]]
    ap.add_argument("--printer", help=f"printer profile: {', '.join(presets)} (method, the default), or custom (with --width, "
                    "--height, --pixel-um)")
    ap.add_argument("--width", type=int, help="custom printer: display pixels along x")
    ap.add_argument("--height", type=int, help="custom printer: display pixels along y")
    ap.add_argument("--pixel-um", type=float, help="custom printer: pixel size in micrometres")
    ap.add_argument("--antialiasing", action="store_true", help="grey edge pixels from exact coverage")
    ap.add_argument("--gamma", type=float, help="anti-aliasing gamma (PrusaSlicer's gamma_correction; default 1)")
    formats = [e[1:] for e in sr.print_file_extensions()] + ["png"]
    ap.add_argument("--format", choices=formats,
                    help=f"print file: {', '.join(formats)} (png: a folder of PNG images); default: the printer's own "
                         "(common/printer/presets.json)")
    ap.add_argument("--text", action="store_true",
                    help="write text .enc/.ctr instead of binary .srb (encoding, kept contours)")
    ap.add_argument("--plates", action="store_true",
                    help="arrange the members on build plates: one print file per plate, plus plates.json")
    ap.add_argument("--spacing", type=float, default=2.0, help="--plates: spacing between members in mm")
    ap.add_argument("--placements", help="--plates: a placements file to use instead of arranging")
    ap.add_argument("--workers", type=int, help="worker processes of the embedded Dask LocalCluster "
                    "(default: one per two cores; on two cores or fewer, this process); 0: make everything in "
                    "this process")
    ap.add_argument("--scheduler", help="run on this Dask cluster instead (tcp://HOST:PORT)")
    ap.add_argument("--send-encoding", action="store_true",
                    help="send the source's encoding to each worker once, instead of workers reading it from --out "
                         "(for workers elsewhere, when the shared folder is slow)")
    ap.add_argument("--strict", action="store_true",
                    help="fail a member whose slicing cannot be reused instead of slicing it directly")
    ap.add_argument("--supports", action="store_true",
                    help="print every member on supports: MESH0's points transferred to every member "
                         "(--direct: generated on each)")
    checks = ap.add_mutually_exclusive_group()
    checks.add_argument("--require-printable", action="store_const", dest="printability", const="require",
                        default="check",
                        help="do not write a member (or plate) whose print file would hold an island, a resin trap "
                             "or a suction cup; its entry's error names them")
    checks.add_argument("--no-check", action="store_const", dest="printability", const="off",
                        help="do not check the print files' printability")
    ap.add_argument("--labels", nargs="?", const="names", metavar="FILE.csv",
                    help="cut each member's label into its base: its file stem, or its row of FILE.csv "
                         "(member,label)")
    ap.add_argument("--allow-unlabelled", action="store_true",
                    help="--labels: print a member whose label fits nowhere on its base without it")
    ap.add_argument("--label-side", choices=sr.LABEL_SIDES, default="base",
                    help="--labels: the face the label goes into: the base (the default, mirrored to read from "
                         "below) or a side, upright: front (-y), back (+y), left (-x), right (+x)")
    ap.add_argument("--hollow", type=float, metavar="WALL_MM",
                    help="hollow every member, keeping walls this thick (mm; PrusaSlicer's profiles: 3)")
    ap.add_argument("--drain-holes", metavar="D_MM[,COUNT]",
                    help="--hollow: drain holes this wide (mm; 0: none; default 4), COUNT per cavity (default 1)")
    ap.add_argument("--drain-holes-file", metavar="FILE.srp",
                    help="--hollow: the user's drain holes (Add Drain Holes' file) instead of the automatic ones")
    ap.add_argument("--resume", action="store_true",
                    help="skip members whose outputs an earlier run made complete and valid")
    ap.add_argument("meshes", nargs="+", metavar="MESH", help="the sliced mesh, then its family members")
    args = ap.parse_args()
    if args.layer_thickness <= 0:
        ap.error("--layer-thickness must be greater than 0")
    given = {"width_px": args.width, "height_px": args.height,
             "pixel_size_x_um": args.pixel_um, "pixel_size_y_um": args.pixel_um}
    profile = {k: v for k, v in given.items() if v is not None}
    if profile and args.printer not in (None, "custom"):
        ap.error(f"--width, --height and --pixel-um describe a custom printer, not {args.printer}")
    if profile or args.printer:
        profile["printer"] = args.printer or "custom"
    if args.antialiasing:
        profile["antialiasing"] = True
    if args.gamma is not None:
        profile["gamma"] = args.gamma
    if (args.placements or args.spacing != 2.0) and not args.plates:
        ap.error("--spacing and --placements go with --plates")
    if args.plates and args.keep_contours:
        ap.error("--keep-contours is for one print file per member, not --plates")
    if args.workers is not None and args.workers < 0:
        ap.error("--workers must be 0 (this process) or more")
    if args.workers is not None and args.scheduler:
        ap.error("--workers is for the embedded cluster; a --scheduler's cluster has its own workers")
    if args.send_encoding and (args.plates or args.direct):
        ap.error("--send-encoding is for members made by reuse, one print file each")
    if args.strict and args.direct:
        ap.error("--strict is for members made by reuse, not --direct")
    if args.allow_unlabelled and not args.labels:
        ap.error("--allow-unlabelled goes with --labels")
    if args.label_side != "base" and not args.labels:
        ap.error("--label-side goes with --labels")
    if args.hollow is not None and not args.hollow > 0:
        ap.error("--hollow needs a wall thickness above 0 mm")
    drain_holes = None
    if args.drain_holes is not None:
        if args.hollow is None:
            ap.error("--drain-holes goes with --hollow")
        try:
            diameter, _, count = args.drain_holes.partition(",")
            drain_holes = (float(diameter), int(count) if count else 1)
        except ValueError:
            ap.error(f"--drain-holes takes D_MM or D_MM,COUNT (e.g. 4,2), not {args.drain_holes}")
        if not (drain_holes[0] >= 0 and 1 <= drain_holes[1] <= 100):
            ap.error(f"--drain-holes needs a diameter of 0 mm or more and 1 to 100 holes, not {args.drain_holes}")
    if args.drain_holes_file is not None and args.hollow is None:
        ap.error("--drain-holes-file goes with --hollow")
    engine = {"workers": args.workers, "scheduler": args.scheduler, "resume": args.resume}
    if args.send_encoding:
        engine["send_encoding"] = True
    try:
        sr.load()
        bar = progress_bar if sys.stderr.isatty() else None
        extension = None if args.format is None else "" if args.format == "png" else "." + args.format
        if args.plates:
            result = sr.plates(args.meshes[0], args.meshes[1:], args.layer_thickness, args.out, profile=profile,
                               progress=bar, direct=args.direct, verify=args.verify, spacing_mm=args.spacing,
                               placements=args.placements, extension=extension, strict=args.strict,
                               supports=args.supports, printability=args.printability, labels=args.labels,
                               allow_unlabelled=args.allow_unlabelled, label_side=args.label_side,
                               hollow=args.hollow, drain_holes=drain_holes, drain_holes_file=args.drain_holes_file,
                               **engine)
        else:
            result = sr.family(args.meshes[0], args.meshes[1:], args.layer_thickness, args.out,
                               profile=profile, binary=not args.text, extension=extension, progress=bar,
                               direct=args.direct, verify=args.verify, keep_contours=args.keep_contours,
                               strict=args.strict, supports=args.supports,
                               printability=args.printability, labels=args.labels,
                               allow_unlabelled=args.allow_unlabelled, label_side=args.label_side,
                               hollow=args.hollow, drain_holes=drain_holes, drain_holes_file=args.drain_holes_file,
                               **engine)
    except Exception as e:  # pymeshlab.PyMeshLabException, OSError, RuntimeError, ValueError
        if sys.stderr.isatty():
            sys.stderr.write("\n")
        sys.exit(f"family: error: {e}")
    print(json.dumps(result))
    if result["failed"]:
        total = len(result["targets"] if "targets" in result else result["plates"])
        sys.exit(f"family: {result['failed']} of {total} failed; their entries say why")


if __name__ == "__main__":
    main()
