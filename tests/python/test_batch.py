"""Family batches beyond one process (issue #18, python/slicereuse_batch.py): family.py on a real
Dask cluster (a `dask scheduler` and two `dask worker` processes on localhost) and on its embedded
LocalCluster makes the same bytes as the in-process pipeline; a worker killed while it holds a
task loses nothing and leaves no partial file; --resume after an interrupted run makes only what
is missing or no longer valid; a failing member is reported while the others are made."""
import dataclasses
import json
import os
import signal
import socket
import subprocess
import tempfile
import time
from pathlib import Path

import pytest

import slicereuse_batch as batch
from conftest import ROOT

FAMILY = [str(ROOT / "scripts" / "python"), str(ROOT / "examples" / "family.py")]
EPOCH = "1764000000"  # every run here records this creation time, so whole files compare equal
# Members that take about half a second each (anti-aliased 3840x2400 masks, 2000 layers), so a
# worker can be caught holding one.
SLOW = ["--layer-thickness", "0.004", "--printer", "anycubic_photon_mono_x", "--format", "sl1", "--antialiasing"]


def family_py(*args, out, env=None, check=True):
    run = subprocess.run([*FAMILY, "--out", str(out), *map(str, args)], capture_output=True, text=True,
                         env=dict(os.environ, SOURCE_DATE_EPOCH=EPOCH, **(env or {})))
    if check:
        assert run.returncode == 0, run.stderr
    return run


def files(folder):
    """The outputs of a folder and its subfolders (PNG folders, plates' direct/), by path in it, with
    their bytes (the batch records aside)."""
    folder = Path(folder)
    return {str(p.relative_to(folder)): p.read_bytes() for p in folder.rglob("*")
            if p.is_file() and batch.RECORDS not in p.relative_to(folder).parts}


def partial_files(folder):
    return sorted(str(p) for p in Path(folder).rglob("*.tmp-*"))


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Cluster:
    """A `dask scheduler` and named `dask worker` processes on localhost, stopped at the end."""

    def __init__(self, workers):
        self.port = free_port()
        self.address = f"tcp://127.0.0.1:{self.port}"
        env = dict(os.environ, PYTHONPATH=str(ROOT / "python"))
        dask = str(ROOT / ".venv" / "bin" / "dask")
        quiet = dict(stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
        self.scheduler = subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port", str(self.port),
                                           "--no-dashboard"], **quiet)
        # No nanny: a worker is one process, so killing it is losing the worker.
        self.workers = {name: subprocess.Popen([dask, "worker", self.address, "--name", name, "--nthreads", "1",
                                                "--no-nanny", "--no-dashboard"], **quiet)
                        for name in workers}
        from distributed import Client
        self.client = Client(self.address, timeout="30s")
        self.client.wait_for_workers(len(workers), timeout=60)

    def executing(self):
        """{worker name: keys of the tasks it is running right now}."""
        running = self.client.run(lambda dask_worker: [str(t.key) for t in dask_worker.state.executing])
        names = {a: w["name"] for a, w in self.client.scheduler_info()["workers"].items()}
        return {names[a]: keys for a, keys in running.items() if a in names}

    def stop(self):
        self.client.close()
        for p in [*self.workers.values(), self.scheduler]:
            p.terminate()
        for p in [*self.workers.values(), self.scheduler]:
            try:
                p.wait(timeout=20)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()


@pytest.fixture
def cluster():
    c = Cluster(["w1", "w2"])
    yield c
    c.stop()


def test_a_dask_cluster_makes_the_same_bytes_as_this_process(make_family, tmp_path, cluster):
    """family.py --scheduler on a real scheduler with two workers (the encoding by path, and sent
    to each worker) and on the embedded LocalCluster (of one worker) writes the in-process run's
    files byte for byte; each member says which worker made it."""
    members = make_family("arch", 6)
    args = ["--layer-thickness", "0.1", "--format", "sl1", "--verify", *members]
    family_py("--workers", "0", *args, out=tmp_path / "here")
    reference = files(tmp_path / "here")
    assert sorted(reference) == sorted(["member_000_enc.srb"] + [f"member_00{k}{s}.sl1" for k in range(1, 6)
                                                                  for s in ("", ".direct")])
    for name, extra in [("cluster", ["--scheduler", cluster.address]),
                        ("sent", ["--scheduler", cluster.address, "--send-encoding"]),
                        ("local", ["--workers", "1"])]:
        result = json.loads(family_py(*extra, *args, out=tmp_path / name).stdout)
        assert files(tmp_path / name) == reference, name
        assert result["failed"] == 0 and len(result["targets"]) == 5
        assert all(t["min_similarity"] == 1.0 and t["max_grey_difference"] == 0 for t in result["targets"])
        if name == "local":
            assert result["engine"] == "LocalCluster of 1 worker process"
        else:
            assert result["engine"] == f"Dask scheduler {cluster.address}"
            assert {t["worker"] for t in result["targets"]} <= {"w1", "w2"}, result
    # The workers keep no copy of the sent encoding once the batch is over.
    assert not list(Path(tempfile.gettempdir(), "slicereuse-shared").glob("*.srb"))


def test_plates_on_a_dask_cluster_are_the_same_bytes_and_resume(make_family, tmp_path, cluster):
    """family.py --plates: the arrangement is made once, then every plate is a task; on the
    cluster the plates' print files, layouts and placements are the in-process run's, byte for
    byte, and each equals direct slicing; --resume keeps every plate of a complete run."""
    members = make_family("arch", 8)
    args = ["--plates", "--verify", "--layer-thickness", "0.1", "--printer", "method", "--format", "sl1", *members]
    here = json.loads(family_py("--workers", "0", *args, out=tmp_path / "here").stdout)
    assert len(here["plates"]) >= 2 and here["members"] == 7  # the method's small display
    there = json.loads(family_py("--scheduler", cluster.address, *args, out=tmp_path / "cluster").stdout)

    def made(folder):  # the placements name each plate's print file by its path
        f = files(tmp_path / folder)
        return dict(f, **{"plates.json": f["plates.json"].replace(str(tmp_path / folder).encode(), b"OUT")})
    assert made("cluster") == made("here")
    assert there["failed"] == 0 and {p["worker"] for p in there["plates"]} <= {"w1", "w2"}
    assert all(p["min_similarity"] == 1.0 and p["max_grey_difference"] == 0 for p in there["plates"])
    again = json.loads(family_py("--resume", "--workers", "0", *args, out=tmp_path / "here").stdout)
    assert all(p.get("resumed") for p in again["plates"]), again
    assert made("here") == made("cluster")


def test_a_worker_killed_while_it_holds_a_task_loses_nothing(make_family, tmp_path, cluster):
    """One of two workers is killed (SIGKILL) while it runs a member: the batch completes, its task
    made again on the other worker, every output complete and equal to the in-process run's, and
    no partial file stays."""
    members = make_family("arch", 5, faces=60000)
    run = subprocess.Popen([*FAMILY, "--out", str(tmp_path / "cluster"), "--scheduler", cluster.address, *SLOW,
                            *map(str, members)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           env=dict(os.environ, SOURCE_DATE_EPOCH=EPOCH))
    victim, deadline = None, time.monotonic() + 120
    while victim is None and time.monotonic() < deadline and run.poll() is None:
        victim = next((name for name, keys in cluster.executing().items() if keys), None)
        time.sleep(0.02)
    assert victim, "no worker was seen running a member"
    held = cluster.executing()[victim]
    cluster.workers[victim].send_signal(signal.SIGKILL)
    stdout, stderr = run.communicate(timeout=300)
    assert run.returncode == 0, stderr
    result = json.loads(stdout)
    survivor = ({"w1", "w2"} - {victim}).pop()
    held_member = next(t for t in result["targets"] if any(Path(t["output"]).name in k for k in held))
    assert held_member["worker"] == survivor, (held, result)
    assert result["failed"] == 0
    family_py("--workers", "0", *SLOW, *members, out=tmp_path / "here")
    assert files(tmp_path / "cluster") == files(tmp_path / "here")
    assert partial_files(tmp_path / "cluster") == []


def test_resume_after_an_interrupted_run_makes_only_what_is_missing(make_family, tmp_path):
    """A run killed after some members: --resume keeps the members whose outputs are complete
    and valid, makes the rest and one whose file was damaged since, and ends with the files of an
    uninterrupted run; --resume with another parameter makes everything again."""
    members = make_family("arch", 7, faces=60000)
    out = tmp_path / "out"
    run = subprocess.Popen([*FAMILY, "--out", str(out), "--workers", "0", *SLOW, *map(str, members)],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                           env=dict(os.environ, SOURCE_DATE_EPOCH=EPOCH))
    records = out / batch.RECORDS
    deadline = time.monotonic() + 120
    while len(list(records.glob("member_*.sl1.json"))) < 3 and time.monotonic() < deadline:
        time.sleep(0.01)
    run.send_signal(signal.SIGKILL)
    run.wait()
    done = sorted(p.name[:-len(".json")] for p in records.glob("member_*.sl1.json"))
    assert 3 <= len(done) < 6, done
    damaged = out / done[0]
    data = bytearray(damaged.read_bytes())
    data[len(data) // 2] ^= 1  # the same size, one bit changed
    damaged.write_bytes(data)

    result = json.loads(family_py("--resume", *SLOW, *members, out=out).stdout)
    resumed = sorted(Path(t["output"]).name for t in result["targets"] if t.get("resumed"))
    assert resumed == done[1:]
    assert result["failed"] == 0 and partial_files(out) == []
    family_py("--workers", "0", *SLOW, *members, out=tmp_path / "whole")
    assert files(out) == files(tmp_path / "whole")

    other = json.loads(family_py("--resume", *SLOW[:-1], *members, out=out).stdout)  # binary masks now
    assert not any(t.get("resumed") for t in other["targets"])


def test_a_failing_member_is_reported_and_the_others_are_made(make_family, tmp_path):
    """With --strict, a member that cannot be reused (another mesh's connectivity, no map) fails
    with the filter's message in its entry; the others are made; the exit status says that some
    failed."""
    members = make_family("arch", 4)
    other = tmp_path / "ear.ply"  # not of the arch's family
    other.write_bytes(make_family("ear", 2)[1].read_bytes())
    run = family_py("--strict", "--layer-thickness", "0.1", "--format", "sl1", members[0], members[1], other,
                    members[2], out=tmp_path / "out", check=False)
    assert run.returncode == 1
    assert run.stderr.strip().endswith("family: 1 of 3 failed; their entries say why")
    result = json.loads(run.stdout)
    assert result["failed"] == 1
    bad = result["targets"][1]
    assert set(bad) == {"mesh", "error", "worker"} and bad["mesh"] == str(other)
    assert "faces" in bad["error"], bad
    assert [Path(t["output"]).name for t in result["targets"] if "error" not in t] == \
        ["member_001.sl1", "member_002.sl1"]
    assert not (tmp_path / "out" / "ear.sl1").exists() and partial_files(tmp_path) == []


def test_a_batch_refuses_a_malformed_creation_time(monkeypatch):
    """batch_epoch: SOURCE_DATE_EPOCH as the print files' writers read it, refused in their words."""
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1764000000")
    assert batch.batch_epoch() == 1764000000
    for bad in ["yesterday", "-5", "1.5", "1e9", "1234567890123"]:
        monkeypatch.setenv("SOURCE_DATE_EPOCH", bad)
        with pytest.raises(ValueError) as e:
            batch.batch_epoch()
        assert str(e.value) == (f"SOURCE_DATE_EPOCH is '{bad}': it must be the creation time as a whole number of "
                                "seconds since 1970-01-01 UTC, or unset")


def test_a_record_proves_its_outputs_by_content(tmp_path):
    """valid_record: the job's key and every output's size and content; a worker that does not see
    the output folder says so."""
    (tmp_path / batch.RECORDS).mkdir()
    out = tmp_path / "a.sl1"
    job = batch.Job(name="a.sl1", out=str(tmp_path), outputs=[str(out)], epoch=0, base={"mesh": "a.ply"},
                    key=batch.key_of(x=1))
    entry = batch.attempt(lambda j, _: out.write_bytes(b"made") and {}, job, "", "here")
    assert entry["worker"] == "here" and batch.valid_record(job) == entry
    assert batch.valid_record(dataclasses.replace(job, key=batch.key_of(x=2))) is None
    out.write_bytes(b"mad!")
    assert batch.valid_record(job) is None
    out.unlink()
    assert batch.valid_record(job) is None
    elsewhere = dataclasses.replace(job, out=str(tmp_path / "not_here"))
    assert batch.attempt(lambda j, _: {}, elsewhere, "", "w9")["error"].startswith(
        f"the output folder {tmp_path / 'not_here'} is not on this machine's disk")
