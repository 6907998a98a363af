"""The driver side of a run: hashes the inputs, decides what a rerun may skip, submits
the rest to the Dask cluster and writes each result into the manifest as it arrives.

Tasks (tasks.py, blend.py), one per file, keyed "<kind>-<run>-<n>" with n the input's
position in the run (the dashboard groups them by kind):
  convert-…      one file to one mesh file
  plan-…         --split parts: reads an assembly, returns its parts (or none: then a
                 convert-… task follows)
  part-…-k       --split parts: one unique part
  assemble-…     --split parts: the placed parts written (depends on the part tasks)
  blend-…        --format blend: a chunk of files in one Blender
Larger files are submitted with a higher priority (the long ones start first). A task
whose worker dies is run again on another worker by Dask (at most
distributed.scheduler.allowed-failures times, then the file fails with KilledWorker).
"""
import concurrent.futures
import math
import uuid

from distributed import as_completed

from . import manifest, outputs, tasks
from .blend import blend_chunk_task
from .outcome import FAILED, Outcome, failed
from .parts import Plan
from .progress import Progress

# Threads hashing inputs on the driver (reading files, not CPU bound).
HASH_THREADS = 4
# --format blend without --chunk: about two chunks per worker, at most this many files each.
MAX_BLEND_CHUNK = 16


def hash_inputs(jobs):
    with concurrent.futures.ThreadPoolExecutor(HASH_THREADS) as pool:
        return dict(zip((job.input for job in jobs), pool.map(manifest.sha256_of, (job.input for job in jobs))))


def blend_chunk_size(count, workers):
    return max(1, min(MAX_BLEND_CHUNK, math.ceil(count / max(1, 2 * workers))))


class Run:
    """One batch run. `open_client()` gives the Dask Client, called only when something
    is left to convert (a rerun that skips everything starts no cluster). `run()` returns
    the manifest lines written, one per job."""

    def __init__(self, open_client, jobs, settings, manifest_path, timeout=None, chunk=None, progress=None):
        self.open_client = open_client
        self.client = None
        self.jobs = jobs
        self.settings = settings
        self.manifest_path = manifest_path
        self.timeout = timeout
        self.chunk = chunk
        self.progress = progress or Progress(len(jobs))
        self.token = uuid.uuid4().hex[:8]
        self.index = {job.input: n for n, job in enumerate(jobs)}
        self.sha = {}    # input -> sha256
        self.lines = {}  # input -> its manifest line
        self._pending = {}  # future -> (kind, task arguments)

    def run(self):
        self.sha = hash_inputs(self.jobs)
        previous = manifest.read(self.manifest_path)
        todo, first = [], []
        for job in self.jobs:
            old = previous.get(job.input)
            if manifest.up_to_date(old, job, self.sha[job.input], self.settings):
                line = manifest.record(job, self.sha[job.input], self.settings, manifest.skipped(old))
                first.append(line)
                self.lines[job.input] = line
                self.progress.file_done(job, manifest.skipped(old))
            else:
                todo.append(job)
        self.writer = manifest.Writer(self.manifest_path, first)
        try:
            if todo:
                self.client = self.open_client()
                self.collect(self.submit(todo))
        finally:
            self.writer.close()
        for job in todo:
            outputs.remove_partials(job.output)
        self.progress.finish()
        return [self.lines[job.input] for job in self.jobs]

    # -- submitting ----------------------------------------------------------------

    def key(self, kind, job, *extra):
        return "-".join([kind, self.token, str(self.index[job.input]), *map(str, extra)])

    def submit_task(self, kind, function, *args, key, priority):
        future = self.client.submit(function, *args, key=key, priority=priority)
        self._pending[future] = kind, args
        return future

    def submit(self, jobs):
        by_size = sorted(jobs, key=lambda job: job.size, reverse=True)
        priority = {job.input: len(jobs) - rank for rank, job in enumerate(by_size)}
        if self.settings.format == "blend":
            return self.submit_blend(by_size, priority)
        futures = []
        for job in jobs:
            if self.settings.split == "parts":
                futures.append(self.submit_task("plan", tasks.plan_task, job, self.sha[job.input], self.settings,
                                                self.timeout, key=self.key("plan", job),
                                                priority=priority[job.input]))
            else:
                futures.append(self.submit_convert(job, priority[job.input]))
        return futures

    def submit_convert(self, job, priority):
        return self.submit_task("convert", tasks.convert_task, job, self.sha[job.input], self.settings,
                                self.timeout, key=self.key("convert", job), priority=priority)

    def submit_blend(self, by_size, priority):
        workers = max(1, len(self.client.scheduler_info()["workers"]))
        size = self.chunk or blend_chunk_size(len(by_size), workers)
        futures = []
        for start in range(0, len(by_size), size):
            chunk = by_size[start:start + size]
            futures.append(self.submit_task("blend", blend_chunk_task, chunk, self.settings, self.timeout,
                                            key=self.key("blend", chunk[0]), priority=priority[chunk[0].input]))
        return futures

    def submit_parts(self, job, plan):
        """The task that writes an assembly, then the part tasks it depends on."""
        priority = len(self.jobs) + 1  # an assembly already started goes before new files
        meshes = [self.submit_task("part", tasks.part_task, job, self.sha[job.input], self.settings, part,
                                   self.timeout, key=self.key("part", job, k), priority=priority)
                  for k, part in enumerate(plan.parts)]
        self.progress.parts_planned(len(meshes))
        assembly = self.submit_task("assemble", tasks.assembly_task, job, self.settings, plan, meshes, self.timeout,
                                    key=self.key("assemble", job), priority=priority)
        return [assembly] + meshes

    # -- collecting ----------------------------------------------------------------

    def collect(self, futures):
        results = as_completed(futures)
        for future in results:
            kind, args = self._pending.pop(future)
            if kind == "part":  # its mesh stays on the cluster for the assemble task
                self.progress.part_done()
                continue
            try:
                value = future.result()
            except Exception as err:  # the task itself failed: KilledWorker, a cluster error
                value = failed(f"{type(err).__name__}: {err}")
            if kind == "blend":
                chunk = args[0]
                if isinstance(value, Outcome):  # the whole chunk task failed
                    value = [(job.input, value) for job in chunk]
                jobs = {job.input: job for job in chunk}
                for path, outcome in value:
                    self.record(jobs[path], outcome)
            elif kind == "plan" and isinstance(value, Plan):
                job = args[0]
                if value.parts:
                    results.update(self.submit_parts(job, value))
                else:
                    results.add(self.submit_convert(job, len(self.jobs) + 1))
            else:
                self.record(args[0], value)

    def record(self, job, outcome):
        line = manifest.record(job, self.sha[job.input], self.settings, outcome)
        self.writer.write(line)
        self.lines[job.input] = line
        self.progress.file_done(job, outcome)


def failures(lines):
    return [line for line in lines if line["status"] == FAILED]

