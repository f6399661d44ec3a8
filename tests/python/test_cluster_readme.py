"""The README's commands for an existing cluster ("Family batches on a cluster"), run as written: a
`dask scheduler` and a `dask worker` started from .venv with no PYTHONPATH import the installed
package, and family.py on them writes the printer's own print files, the in-process pipeline's
bytes, each made on that worker."""
import json
import os
import shutil
import signal
import socket
import subprocess

import pytest

from conftest import ROOT
from test_batch import EPOCH, family_py, files

MARKER = "<!-- cluster-commands:"
PORT = 8786  # the README's


def readme_commands():
    """The lines of the code block right after the marker in README.md."""
    lines = (ROOT / "README.md").read_text().splitlines()
    start = next((i for i, line in enumerate(lines) if line.startswith(MARKER)), None)
    assert start is not None, f"README.md has no line starting with {MARKER}"
    assert lines[start + 1] == "```sh", "the marker must be followed by a ```sh block"
    return lines[start + 2:lines.index("```", start + 2)]


def stop(process):
    """Ends the process group started for one README line (bash, the command, its children)."""
    for sig, wait in ((signal.SIGTERM, 30), (signal.SIGKILL, 10)):
        try:
            os.killpg(process.pid, sig)
        except ProcessLookupError:
            return
        try:
            process.wait(timeout=wait)
            return
        except subprocess.TimeoutExpired:
            pass


def test_the_readme_cluster_commands_run_as_written(make_family, tmp_path):
    scheduler_line, worker_line, family_line = readme_commands()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env.update(REPO=str(ROOT), SCHEDULER="127.0.0.1", OUT=str(tmp_path / "out"), SOURCE_DATE_EPOCH=EPOCH)
    installed = subprocess.run([str(ROOT / ".venv" / "bin" / "python"), "-c",
                                "import slicereuse_pymeshlab as sr; print(sr.ROOT)"],
                               cwd="/", env=env, capture_output=True, text=True, timeout=60)
    assert installed.stdout.strip() == str(ROOT.resolve()), \
        f"the venv's slicereuse package is not this checkout's ({installed.stdout}{installed.stderr}): " \
        "run scripts/setup"
    with socket.socket() as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)  # as the scheduler binds: past connections aside
        try:
            s.bind(("", PORT))
        except OSError:
            pytest.fail(f"port {PORT}, which the README's scheduler takes, is in use")

    here = tmp_path / "here"  # the family line's folder, with the members
    here.mkdir()
    members = make_family("arch", 3)
    for k, member in enumerate(members):
        shutil.copy(member, here / f"m{k}.ply")
    elsewhere = tmp_path / "elsewhere"  # where the scheduler and the worker start: not the members' folder
    elsewhere.mkdir()
    logs, started, client = {}, [], None
    try:
        for name, line in (("scheduler", scheduler_line), ("worker", worker_line)):
            logs[name] = open(tmp_path / f"{name}.log", "w")
            started.append(subprocess.Popen(["bash", "-c", line], cwd=elsewhere, env=env, stdout=logs[name],
                                            stderr=subprocess.STDOUT, start_new_session=True))
        from distributed import Client
        client = Client(f"tcp://127.0.0.1:{PORT}", timeout="60s")
        client.wait_for_workers(1, timeout=120)
        (worker,) = [w["name"] for w in client.scheduler_info()["workers"].values()]

        run = subprocess.run(["bash", "-c", family_line], cwd=here, env=env, capture_output=True, text=True,
                             timeout=600)
        assert run.returncode == 0, run.stderr
        result = json.loads(run.stdout)
        assert result["failed"] == 0 and result["engine"] == f"Dask scheduler tcp://127.0.0.1:{PORT}", result
        assert [(t["mesh"], t["output"], t["worker"]) for t in result["targets"]] == \
            [(f"m{k}.ply", str(tmp_path / "out" / f"m{k}.sl1s"), worker) for k in (1, 2)], result
    finally:
        if client is not None:
            client.close()
        for process in reversed(started):
            stop(process)
        for log in logs.values():
            log.close()
    made = files(tmp_path / "out")
    assert sorted(made) == ["m0_enc.srb", "m1.sl1s", "m2.sl1s"]
    family_py("--workers", "0", "--printer", "prusa_sl1s_speed", "--layer-thickness", "0.05",
              *(here / f"m{k}.ply" for k in range(3)), out=tmp_path / "in_process")
    assert made == files(tmp_path / "in_process")
