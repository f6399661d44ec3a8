"""Reuses one mesh's slicing for a family of customized meshes and checks the result.

    scripts/python examples/family.py --layer-thickness 0.1 --out DIR MESH0 MESH1 ...

Slices MESH0 with encoding, then for every other mesh: transfers the slicing, writes its masks,
slices it directly, writes those masks and compares the two stacks. Prints one JSON object:
{"source": MESH0, "targets": [{"mesh", "layers", "points", "resliced_layers",
"transfer_seconds", "direct_seconds", "min_similarity"}, ...]}; min_similarity 1 means the
transferred masks equal the directly sliced ones. Files go to DIR (see slicereuse_pymeshlab.family).
"""
import argparse
import json
import sys

import slicereuse_pymeshlab as sr

KEYS = ("mesh", "layers", "points", "resliced_layers", "transfer_seconds", "direct_seconds",
        "transfer_total_seconds", "direct_total_seconds",
        "min_similarity")


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
    ap.add_argument("--width", type=int, default=1024, help="mask width in pixels (1024)")
    ap.add_argument("--height", type=int, default=768, help="mask height in pixels (768)")
    ap.add_argument("--pixel-um", type=float, default=75, help="pixel size in micrometres (75)")
    ap.add_argument("--text", action="store_true", help="write text .ctr/.enc instead of binary .srb")
    ap.add_argument("meshes", nargs="+", metavar="MESH", help="the sliced mesh, then its family members")
    args = ap.parse_args()
    if args.layer_thickness <= 0:
        ap.error("--layer-thickness must be greater than 0")
    profile = {"width_px": args.width, "height_px": args.height,
               "pixel_size_x_um": args.pixel_um, "pixel_size_y_um": args.pixel_um}
    try:
        sr.load()
        result = sr.family(args.meshes[0], args.meshes[1:], args.layer_thickness, args.out,
                           profile=profile, binary=not args.text,
                           progress=progress_bar if sys.stderr.isatty() else None)
    except Exception as e:  # pymeshlab.PyMeshLabException, OSError, RuntimeError
        if sys.stderr.isatty():
            sys.stderr.write("\n")
        sys.exit(f"family: error: {e}")
    result["targets"] = [{k: t[k] for k in KEYS} for t in result["targets"]]
    print(json.dumps(result))


if __name__ == "__main__":
    main()
