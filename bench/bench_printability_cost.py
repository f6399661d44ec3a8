"""What checking printability costs the lab's jobs (issue #35): the product's own filters, run as
the batch runs them (pymeshlab, members read from STL files), with check_printability on and off,
alternately, on the Prusa SL1S SPEED at 0.05 mm, anti-aliased.

    scripts/python bench/bench_printability_cost.py [--runs 15] [--plate-members 11] [--out DIR]

- member: make_print_job of an arch member of 208k faces by reuse (the encoding in memory), its
  seconds as the filter reports them (reading, transfer, masks and .sl1s);
- plates: make_plate_job of --plate-members such members, on as many plates as they need (the
  SL1S holds 3 or 4 arches); the check per plate is the job's divided by its plates.
Prints the medians and the check's share: the median of the differences of each run with the check
on and the run with it off just before (paired, so that the machine's drift cancels), over the
median with it off. Figures go into bench/RESULTS.md.
"""
import argparse
import statistics
import tempfile
from pathlib import Path

import slicereuse_pymeshlab as sr
from bench_end_to_end import ARCH, PRESET, family_stls

PROFILE = {"printer": PRESET, "antialiasing": True}


def timed(ms, filter_name, runs, **params):
    """Median seconds of the filter with the check off and on, alternating, the median of the
    paired differences (on - off), and the last result on."""
    seconds = {False: [], True: []}
    result = None
    for _ in range(runs):
        for check in (False, True):
            r = ms.apply_filter(filter_name, check_printability=check, **params, **PROFILE)
            seconds[check].append(r["seconds"])
            result = r if check else result
    check = statistics.median(on - off for off, on in zip(seconds[False], seconds[True]))
    return statistics.median(seconds[False]), statistics.median(seconds[True]), check, result


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=15)
    ap.add_argument("--plate-members", type=int, default=11)
    ap.add_argument("--thickness", type=float, default=0.05)
    ap.add_argument("--out", type=Path)
    a = ap.parse_args()
    out = a.out or Path(tempfile.mkdtemp(prefix="bench_printability_"))
    out.mkdir(parents=True, exist_ok=True)
    stls = family_stls(out, "arch", ARCH, a.plate_members, seed=3)
    ms = sr.load().MeshSet()
    encoding = str(out / "source.srb")
    ms.apply_filter("slice_mesh_with_encoding", mesh_file=stls[0], layer_thickness=a.thickness, contour_file="",
                    encoding_file=encoding, file_format=1)
    rows = []
    off, on, check, r = timed(ms, "make_print_job", a.runs, mesh_file=stls[1], encoding_file=encoding,
                              output_path=str(out / "member.sl1s"))
    rows.append(("member (208k faces)", r["layers"], 1, off, on, check))
    off, on, check, r = timed(ms, "make_plate_job", a.runs, member_files=";".join(stls[1:]), encoding_file=encoding,
                              output_path=str(out / "plate.sl1s"))
    rows.append((f"{a.plate_members} members on plates", r["layers"], r["plates"], off, on, check))
    print(f"median of {a.runs} runs each, check off and on alternating (the check: the median of the pairs' "
          f"differences); SL1S SPEED at {a.thickness} mm, anti-aliased")
    print(f"| job | layers | plates | check off (s) | check on (s) | the check (s) | per plate (s) | share |")
    print("|---|---|---|---|---|---|---|---|")
    for name, layers, plates, off, on, check in rows:
        print(f"| {name} | {layers} | {plates} | {off:.3f} | {on:.3f} | {check:.3f} | {check / plates:.3f} | "
              f"{100 * check / off:.1f} % |")


if __name__ == "__main__":
    main()
