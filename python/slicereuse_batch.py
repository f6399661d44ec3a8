"""Family batches as independent tasks, in this process or on a Dask cluster: resumable, nothing
lost and nothing made twice (issue #18).

    import slicereuse_batch as batch
    with batch.engine(workers=2) as engine:             # an embedded LocalCluster
        ...                                             # or workers=0: this process
    with batch.engine(scheduler="tcp://host:8786") as engine:   # an existing Dask cluster
        ...
    entries = batch.run(engine, make, jobs, shared, progress)   # {job name: entry}

A job is a Job (a dataclass, pickled to the workers): its name (unique in its folder), out (the
output folder), outputs (the paths it makes, under out), key (a digest of everything its outputs
depend on: inputs' identities, parameters), epoch (the batch's creation time) and base (what its
entry says of it also when it fails, e.g. {"mesh": path}); a pipeline's jobs are subclasses with
the fields make(job, shared_path) needs. make returns the job's entry, a JSON-able dict, or raises
with a message. What makes each output durable and
checkable:
- The C++ writers stage every output next to its final path (PATH.tmp-XXXXXX) and rename it
  there when complete; a task first removes what a killed earlier attempt may have staged, and
  run() removes any that remain once every task has ended, so no partial file stays.
- After its outputs are complete, a task writes a record, OUT/.slicereuse-batch/<name>.json:
  the job's key, each output's size and SHA-256, and the job's result entry. valid_record() is
  the resume check: the record is there, its key is the job's, and every output is there with
  that size and content (checked, not just present).
- Print files record $SOURCE_DATE_EPOCH as their creation time; every task of a batch runs with
  the batch's (job.epoch), so a task run again elsewhere makes the same bytes.

On Dask every worker process runs setup() once when it starts (loading pymeshlab and the plugins:
engine(..., setup=sr.load)), and gets
the shared input once: the source's encoding by its path in the output folder, which every
worker sees, or, when asked (send), sent once to each worker (scattered with broadcast) and kept
in a file of the worker's own until the batch ends; the plugin keeps the encoding in memory
across tasks. A
worker that dies while it holds a task loses nothing: the scheduler runs the task again
elsewhere (after 3 deaths of workers running it, the job fails with that said). The output
folder must be one every worker writes to at the same path (a shared file system); a worker that
does not see it fails its jobs saying so.
"""
import contextlib
import hashlib
import json
import os
import shutil
import socket
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

RECORDS = ".slicereuse-batch"
_RECORD_VERSION = 1
IN_PROCESS = "in-process"


@dataclass
class Job:
    """One task of a batch: what every job has (the module's docstring says what each field is)."""
    name: str
    out: str
    outputs: list[str]
    key: str
    epoch: int
    base: dict


# ---- Records: what makes an output complete and valid ----

def key_of(**parts):
    """A job's key: a digest of everything its outputs depend on (JSON-able values)."""
    return hashlib.sha256(json.dumps(parts, sort_keys=True).encode()).hexdigest()


def file_identity(path):
    """An input's identity for a job's key: its path, size and modification time (make's rule;
    outputs are checked by content instead)."""
    st = Path(path).stat()
    return [str(path), st.st_size, st.st_mtime_ns]


def _digest(path):
    """SHA-256 of a file, or of a folder's files (names and contents, in name order)."""
    path = Path(path)
    h = hashlib.sha256()
    if path.is_dir():
        for f in sorted(p for p in path.rglob("*") if p.is_file()):
            h.update(str(f.relative_to(path)).encode() + b"\0")
            with open(f, "rb") as s:
                h.update(hashlib.file_digest(s, "sha256").digest())
        return h.hexdigest()
    with open(path, "rb") as s:
        return hashlib.file_digest(s, "sha256").hexdigest()


def _size(path):
    path = Path(path)
    return sum(p.stat().st_size for p in path.rglob("*") if p.is_file()) if path.is_dir() else path.stat().st_size


def record_path(job):
    return Path(job.out) / RECORDS / (job.name + ".json")


def _write_atomically(path, text):
    tmp = path.with_name(path.name + f".tmp-{os.getpid()}")
    with open(tmp, "w") as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def write_record(job, entry):
    """Records job's outputs as complete (after they are), with its result entry."""
    files = {str(o): {"size": _size(o), "sha256": _digest(o)} for o in job.outputs}
    record = {"version": _RECORD_VERSION, "key": job.key, "files": files, "entry": entry}
    _write_atomically(record_path(job), json.dumps(record, indent=1))


def valid_record(job):
    """The job's result entry if its record says its outputs are complete and they still are
    (same key, every output there with the recorded size and content), else None."""
    try:
        record = json.loads(record_path(job).read_text())
        if record.get("version") != _RECORD_VERSION or record.get("key") != job.key:
            return None
        files = record["files"]
        if sorted(files) != sorted(str(o) for o in job.outputs):
            return None
        for o, f in files.items():
            if not Path(o).exists() or _size(o) != f["size"] or _digest(o) != f["sha256"]:
                return None
        return record["entry"]
    except (OSError, ValueError, KeyError, TypeError):
        return None


def _remove(path):
    path = Path(path)
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path)
    elif path.exists() or path.is_symlink():
        path.unlink()


def remove_partial(job):
    """Removes what an attempt at job may have staged and not committed (PATH.tmp-*)."""
    for o in job.outputs:
        o = Path(o)
        for staged in o.parent.glob(o.name + ".tmp-*"):
            _remove(staged)


def prepare(job):
    """Before making job: its outputs folder must be reachable (a worker elsewhere must share the
    disk), an old record goes, and so does whatever an earlier attempt left."""
    records = Path(job.out) / RECORDS
    if not records.is_dir():
        raise RuntimeError(f"the output folder {job.out} is not on this machine's disk ({socket.gethostname()}): "
                           "every worker must write to the output folder at the same path (a shared file system)")
    record_path(job).unlink(missing_ok=True)
    remove_partial(job)
    for o in job.outputs:
        if Path(o).is_dir():  # a PNG folder made again replaces the whole folder in one rename
            _remove(o)


@contextlib.contextmanager
def creation_time(epoch):
    """Print files made inside record epoch (seconds since 1970) as their creation time."""
    before = os.environ.get("SOURCE_DATE_EPOCH")
    os.environ["SOURCE_DATE_EPOCH"] = str(epoch)
    try:
        yield
    finally:
        if before is None:
            del os.environ["SOURCE_DATE_EPOCH"]
        else:
            os.environ["SOURCE_DATE_EPOCH"] = before


def batch_epoch():
    """The creation time every file of a batch records: $SOURCE_DATE_EPOCH, else now. Refuses a
    value that is not a whole number of seconds as the print files' writers do (util/format.h)."""
    given = os.environ.get("SOURCE_DATE_EPOCH")
    if not given:
        return int(time.time())
    if not (given.isascii() and given.isdigit() and len(given) <= 12):
        raise ValueError(f"SOURCE_DATE_EPOCH is '{given}': it must be the creation time as a whole number of "
                         "seconds since 1970-01-01 UTC, or unset")
    return int(given)


# ---- The shared input, sent once to each worker ----

@dataclass
class SharedFile:
    """A file's bytes sent to workers once (scattered with broadcast): name for its suffix, digest
    so that a worker names its copy without hashing it again."""
    name: str
    digest: str
    data: bytes


_local_copies = {}


def local_path(shared):
    """The path of the shared input in this process: a path as it is, or SharedFile's bytes in a
    file of this machine's own, written once per process (atomically, so a second process on the
    machine reuses a complete copy)."""
    if not isinstance(shared, SharedFile):
        return shared
    if shared.digest not in _local_copies:
        folder = Path(tempfile.gettempdir()) / "slicereuse-shared"
        folder.mkdir(exist_ok=True)
        path = folder / (shared.digest + Path(shared.name).suffix)
        if not (path.is_file() and path.stat().st_size == len(shared.data)):
            tmp = path.with_name(path.name + f".tmp-{os.getpid()}")
            tmp.write_bytes(shared.data)
            os.replace(tmp, path)
        _local_copies[shared.digest] = str(path)
    return _local_copies[shared.digest]


def _forget_shared(release):
    """After a batch, in a process that ran its jobs: drops the local copies, then release()."""
    for path in _local_copies.values():
        Path(path).unlink(missing_ok=True)
    _local_copies.clear()
    if release:
        release()


# ---- Engines ----

def attempt(make, job, shared, worker):
    """One attempt at job, wherever it runs: made from a clean start with the batch's creation
    time, recorded once complete. Failures (a bad mesh, a refused parameter) become the entry's
    "error", with the filter's message."""
    start = time.perf_counter()
    try:
        prepare(job)
        with creation_time(job.epoch):
            entry = make(job, local_path(shared))
        entry = dict(job.base, **entry, worker=worker)
        entry.setdefault("seconds", time.perf_counter() - start)
        write_record(job, entry)
        return entry
    except Exception as e:  # pymeshlab.PyMeshLabException, OSError, RuntimeError, ValueError
        return dict(failed_entry(job, str(e) or type(e).__name__), worker=worker)


class InProcess:
    """Runs jobs one after another in this process."""
    description = IN_PROCESS

    def share(self, path, send=False):
        return str(path)

    def submit_all(self, make, jobs, shared):
        for job in jobs:
            yield job, attempt(make, job, shared, IN_PROCESS)

    def finish(self, release):
        _forget_shared(release)


def _setup_plugin(setup):
    """A Dask worker plugin that runs setup() once in each worker process, when it starts.
    distributed is imported only here and where a cluster is used: importing it costs a job
    made in this process 0.2 s."""
    from distributed import WorkerPlugin

    class Setup(WorkerPlugin):
        name = "slicereuse-setup"

        def setup(self, worker):
            setup()

    return Setup()


class OnDask:
    """Runs jobs as tasks of a Dask cluster through client."""

    def __init__(self, client, description, setup):
        self.client = client
        self.description = description
        if setup:
            client.register_plugin(_setup_plugin(setup))

    def share(self, path, send=False):
        """path for the tasks: every worker sees the output folder, so it reads the file there
        (once, then cached by the plugin); with send, its bytes, sent once to each worker."""
        if not send:
            return str(path)
        data = Path(path).read_bytes()
        shared = SharedFile(Path(path).name, hashlib.sha256(data).hexdigest(), data)
        return self.client.scatter(shared, broadcast=True, hash=False)

    def submit_all(self, make, jobs, shared):
        from distributed import as_completed
        futures = {}
        for job in jobs:
            f = self.client.submit(_on_worker, make, job, shared, key=f"{job.name}-{job.key[:16]}", pure=False)
            futures[f] = job
        for f in as_completed(futures):
            job = futures[f]
            if f.status == "finished":
                yield job, f.result()
            else:
                yield job, dict(failed_entry(job, _task_error(f.exception())), worker=None)

    def finish(self, release):
        self.client.run(_forget_shared, release)


def _on_worker(make, job, shared):
    from distributed import get_worker
    worker = get_worker()
    return attempt(make, job, shared, worker.name if isinstance(worker.name, str) else worker.address)


def _task_error(e):
    from distributed.scheduler import KilledWorker
    if isinstance(e, KilledWorker):
        return ("every worker that ran it died while it ran (killed, or out of memory), "
                "as many times as the scheduler allows (distributed.scheduler.allowed-failures)")
    return str(e) or type(e).__name__


def failed_entry(job, message):
    return dict(job.base, error=message)


@contextlib.contextmanager
def engine(workers=None, scheduler=None, setup=None):
    """The engine jobs run on: scheduler (an address, "tcp://host:port"): that Dask cluster;
    else workers == 0: this process; else an embedded LocalCluster of workers worker processes
    (None: default_workers(), and this process when that is one: a single worker process would
    only add its start-up, about a second, to the job). setup: run once in each worker process
    when it starts."""
    if scheduler:
        from distributed import Client
        with Client(scheduler, timeout="30s") as client:
            yield OnDask(client, f"Dask scheduler {scheduler}", setup)
        return
    if workers == 0 or (workers is None and default_workers() == 1):
        yield InProcess()
        return
    import logging
    import dask
    from distributed import Client, LocalCluster
    n = workers or default_workers()
    # One task thread per worker process: pymeshlab is not thread safe. The plugin's kernels are
    # OpenMP-parallel: the machine's cores are shared among the workers (Dask's nanny would set
    # OMP_NUM_THREADS=1 in this process and the worker's; the nanny's env= comes before that and
    # before this process's own variables in the worker, set before the plugin loads OpenMP).
    # Dask's MALLOC_TRIM_THRESHOLD_ is not set: it turns off glibc's adaptive mmap threshold, so
    # every member's large buffers would be mapped and faulted in afresh.
    threads = str(worker_threads(n))
    with dask.config.set({"distributed.nanny.pre-spawn-environ.OMP_NUM_THREADS": threads,
                          "distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None}), \
            LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None,
                         silence_logs=logging.ERROR, env={"OMP_NUM_THREADS": threads}) as cluster, \
            Client(cluster) as client:
        yield OnDask(client, f"LocalCluster of {n} worker process{'es' if n > 1 else ''}", setup)


def worker_threads(workers):
    """The OpenMP threads of each of workers worker processes on this machine."""
    return max(1, (os.cpu_count() or 1) // workers)


def default_workers():
    """Worker processes of the embedded LocalCluster: one per two cores, each with two OpenMP
    threads. bench/bench_batch.py on 2 cores: 1 and 2 workers tie (2,276 and 2,248 members an
    hour), 3 lose (1,957); a member's kernels scale 1.9x on 2 threads, so more processes pay
    only where threads stop scaling, and each holds its own copy of the encoding."""
    return max(1, (os.cpu_count() or 1) // 2)


def run(engine_, make, jobs, shared, progress=None, done=0, steps=None):
    """Runs attempt(make, job, shared, worker) for every job on engine_, partial files removed at
    the end; progress(step, steps, text) after each, counting from done. Returns {job name:
    entry}, each entry with "worker", and "seconds" or "error"."""
    steps = steps if steps is not None else done + len(jobs)
    entries = {}
    try:
        for job, entry in engine_.submit_all(make, jobs, shared):
            entries[job.name] = entry
            done += 1
            if progress:
                state = f"failed: {entry['error']}" if "error" in entry else f"done on {entry['worker']}"
                progress(done, steps, f"{job.name} {state}")
    finally:
        for job in jobs:
            remove_partial(job)
    return entries
