"""What the trimkit-batch tests share: the programs of the build whose module is on the
path (PYTHONPATH=BUILD/python), runs of trimkit-batch and `trimkit mesh`, the manifest,
and a real Dask scheduler with workers as separate processes on 127.0.0.1."""
import json
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import time

import _trimkit
from conftest import ROOT

BUILD = pathlib.Path(_trimkit.__file__).resolve().parents[1]
TRIMKIT = str(BUILD / "bin" / "trimkit")
BATCH = str(BUILD / "bin" / "trimkit-batch")
PYTHON = "/usr/bin/python3.11" if os.path.exists("/usr/bin/python3.11") else sys.executable
# Seconds a scheduler or worker may take to start on a busy 2-core machine.
START_SECONDS = 60


def env():
    return dict(os.environ, PYTHONPATH=str(BUILD / "python"))


def run_batch(*args, timeout=300):
    return subprocess.run([BATCH, *map(str, args)], capture_output=True, text=True, timeout=timeout, env=env())


def start_batch(*args, log):
    return subprocess.Popen([BATCH, *map(str, args)], stdout=log, stderr=subprocess.STDOUT, text=True, env=env())


def read_manifest(path):
    with open(path, encoding="utf-8") as f:
        return [json.loads(line) for line in f]


def mesh_reference(source, output, *args):
    """`trimkit mesh SOURCE -o OUTPUT ARGS --json`: its JSON (triangles, failed faces...)."""
    pathlib.Path(output).parent.mkdir(parents=True, exist_ok=True)
    result = subprocess.run([TRIMKIT, "mesh", str(source), "-o", str(output), *map(str, args), "--json"],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def tbp_reference(source, output):
    """`trimkit tbp mesh SOURCE -o OUTPUT --json` (levels 2, lod 3: trimkit-batch's defaults)."""
    result = subprocess.run([TRIMKIT, "tbp", "mesh", str(source), "-o", str(output), "--json"],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def write_cube_tbp(path):
    """A closed solid of 12 cubic PN-triangle patches over a unit cube's triangles."""
    import numpy as np
    corners = np.array([(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)], np.float64)
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    triangles = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))], np.int32)
    _trimkit.write_tbp(_trimkit.pn_triangles(_trimkit.Mesh(corners, triangles)), str(path))
    return path


def write_damaged(path):
    """samples/bracket.igs without its parameter section (a file cut short)."""
    text = (ROOT / "samples" / "bracket.igs").read_text().splitlines(keepends=True)
    path.write_text("".join(line for line in text if line[72:73] in ("S", "G", "D")))
    return path


def copy_inputs(sources, folder, count):
    """`count` copies of `sources` (cycled) in `folder`, named copy_NN_<name>; sorted."""
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for n in range(count):
        source = pathlib.Path(sources[n % len(sources)])
        paths.append(folder / f"copy_{n:02d}_{source.name}")
        shutil.copyfile(source, paths[-1])
    return paths


def partial_files(folder):
    return sorted(p.name for p in pathlib.Path(folder).rglob("*.partial-*"))


class DaskCluster:
    """`python3.11 -m distributed.cli.dask_scheduler` and workers (no nanny, one thread
    each, named w0, w1, ...), each its own process; `client` watches them."""

    def __init__(self, folder, workers):
        from distributed import Client
        self.folder = pathlib.Path(folder)
        self.file = self.folder / "scheduler.json"
        self.logs = []
        self.scheduler = self._start("distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port", "0",
                                     "--no-dashboard", "--scheduler-file", self.file, name="scheduler")
        self.workers = {}
        for k in range(workers):
            name = f"w{k}"
            self.workers[name] = self._start("distributed.cli.dask_worker", "--scheduler-file", self.file,
                                             "--nthreads", "1", "--no-nanny", "--host", "127.0.0.1",
                                             "--local-directory", self.folder / name, "--name", name, name=name)
        deadline = time.monotonic() + START_SECONDS
        while not self.file.exists():
            assert time.monotonic() < deadline and self.scheduler.poll() is None, self.log("scheduler")
            time.sleep(0.1)
        self.client = Client(scheduler_file=str(self.file), timeout=START_SECONDS)
        self.client.wait_for_workers(workers, timeout=START_SECONDS)
        self.address = self.client.scheduler.address

    def _start(self, module, *args, name):
        log = open(self.folder / f"{name}.log", "w")
        self.logs.append(log)
        return subprocess.Popen([PYTHON, "-m", module, *map(str, args)], stdout=log, stderr=subprocess.STDOUT,
                                env=env())

    def log(self, name):
        return (self.folder / f"{name}.log").read_text()

    def worker_address(self, name):
        return next(addr for addr, w in self.client.scheduler_info()["workers"].items() if w["name"] == name)

    def kill(self, name):
        self.workers[name].send_signal(signal.SIGKILL)
        self.workers[name].wait()

    def close(self):
        self.client.close()
        for process in [*self.workers.values(), self.scheduler]:
            if process.poll() is None:
                process.terminate()
        for process in [*self.workers.values(), self.scheduler]:
            try:
                process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
        for log in self.logs:
            log.close()
