"""Family batches on Dask (issue #18): members per hour of the family pipeline in this process, on
embedded LocalClusters of 1, 2, ... worker processes, and the engine's own cost per task; one run
of each, on one family.

    scripts/python bench/bench_batch.py [--faces 545000] [--thickness 0.001] [--members 8]
                                        [--max-workers 3] [--out DIR]

Workload: gen_family's arch (14.484 mm tall), member 0 the source, --members members that differ
in x-y; binary masks on the method's profile into one .sl1 per member, by reuse (sr.family, as
family.py runs it). Per configuration: the batch's wall seconds without slicing the source (the
same for all: "source_seconds"), members per hour from them, the median member's own seconds, and
the wall seconds the engine adds per member (batch wall over members, minus the median member's
seconds over the worker count). Then the scheduler's cost per task alone (2,000 empty tasks
through a LocalCluster of one worker) and the time to start the default LocalCluster with the
plugins loaded. Prints a table and writes it to DIR/bench_batch.md. Needs scripts/setup and
scripts/build first. (A file, not a heredoc: Dask's worker processes start by importing the
main module.)
"""
import argparse
import os
import statistics
import subprocess
import time
from pathlib import Path

import slicereuse_batch as batch
import slicereuse_pymeshlab as sr

ROOT = Path(__file__).resolve().parent.parent


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--faces", type=int, default=545000)
    ap.add_argument("--thickness", type=float, default=0.001)
    ap.add_argument("--members", type=int, default=8)
    ap.add_argument("--max-workers", type=int, default=3)
    ap.add_argument("--out", type=Path, default=ROOT / "out" / "bench_batch")
    a = ap.parse_args()
    subprocess.run(["rm", "-rf", str(a.out)], check=True)
    subprocess.run([str(ROOT / "build" / "2020" / "tools" / "gen_family"), "--shape", "arch", "--faces", str(a.faces),
                    "--members", str(a.members + 1), "--height", "14.484", "--seed", "1",
                    "--out", str(a.out / "family")], check=True, stdout=subprocess.DEVNULL)
    meshes = sorted((a.out / "family").glob("member_*.ply"))
    rows = []
    for workers in range(0, a.max_workers + 1):
        r = sr.family(meshes[0], meshes[1:], a.thickness, a.out / f"workers_{workers}", extension=".sl1",
                      workers=workers)
        assert r["failed"] == 0, r
        n = len(r["targets"])
        wall = r["seconds"] - r["source_seconds"]
        member = statistics.median(t["seconds"] for t in r["targets"])
        size = statistics.median(Path(t["output"]).stat().st_size for t in r["targets"]) / 1e6
        rows.append((r["engine"], wall, 3600 * n / wall, member, wall / n - member / max(workers, 1), size))
        for t in r["targets"]:
            Path(t["output"]).unlink()  # disk: one configuration's outputs at a time

    from distributed import Client, LocalCluster
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None) as c, \
            Client(c) as client:
        client.gather(client.map(abs, range(100)))  # warm-up
        t0 = time.perf_counter()
        client.gather(client.map(abs, range(100, 2100)))
        per_task = (time.perf_counter() - t0) / 2000
    t0 = time.perf_counter()
    with batch.engine(setup=sr.load) as engine:  # the setup has run on every worker when it returns
        start_seconds = time.perf_counter() - t0
        started = engine.description
    encoding = (a.out / "workers_0" / "member_000_enc.srb").stat().st_size / 1e6

    base = rows[0][2]
    lines = [f"Family batch: arch {a.faces} faces at {a.thickness} mm, {len(meshes) - 1} members by reuse, binary "
             f".sl1 on the method's profile, {os.cpu_count()} cores; one run each", "",
             "| engine | members/hour | vs in-process | batch s (no source) | median member s | engine s/member | "
             "MB/member |", "|---|---|---|---|---|---|---|"]
    for engine, wall, per_hour, member, added, size in rows:
        lines.append(f"| {engine} | {per_hour:,.0f} | {per_hour / base:.2f}x | {wall:.2f} | {member:.3f} | "
                     f"{added:.3f} | {size:.1f} |")
    lines += ["", f"Scheduler cost per task (2,000 empty tasks, one worker): {per_task * 1e3:.2f} ms. "
              f"The default, {started}, started with the plugins loaded: {start_seconds:.2f} s. "
              f"The source's encoding: {encoding:.0f} MB (sent once to each worker without a shared disk)."]
    text = "\n".join(lines)
    print(text)
    (a.out / "bench_batch.md").write_text(text + "\n")


if __name__ == "__main__":
    main()
