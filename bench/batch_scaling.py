"""trimkit-batch on a local Dask cluster: 1 against 2 worker processes on the shared CAD
files (the speed-up), and what a task costs beyond its conversion (the overhead).

    PYTHONPATH=build/python /usr/bin/python3.11 bench/batch_scaling.py [--cad ../shared/data/cad]
        [--repeat 3] [--tasks 2000]

Conversions: every file under CAD/{iges,step,brep} to .glb at 0.1 % of its diagonal
(trimkit-batch's default), into a fresh folder each time (nothing skipped), timed from
the first submission to the last manifest line on a cluster already started; cluster
start-up is reported on its own. Overhead, on the 2-worker cluster:
  - throughput: N no-op tasks submitted at once and gathered, wall time / N;
  - round trip: one no-op task submitted and waited for, repeated, per task;
  - isolated: the same round trip through the worker's child process (tasks.isolated),
    the path every conversion takes.
The load average is printed: the machine may be shared.
"""
import argparse
import os
import pathlib
import statistics
import sys
import tempfile
import time

from distributed import Client, LocalCluster

from trimkit_batch import inputs, tasks
from trimkit_batch.driver import Run
from trimkit_batch.progress import Progress
from trimkit_batch.settings import Settings

ROOT = pathlib.Path(__file__).resolve().parents[1]
ROUND_TRIPS = 200


def noop(x):
    return x


def isolated_noop(x):
    return tasks.isolated(os.getpid)


def convert_all(client, jobs_of, settings):
    with tempfile.TemporaryDirectory(prefix="trimkit-bench-") as out, open(os.devnull, "w") as quiet:
        jobs = jobs_of(out)
        start = time.perf_counter()
        lines = Run(lambda: client, jobs, settings, os.path.join(out, "manifest.jsonl"),
                    progress=Progress(len(jobs), quiet)).run()
        wall = time.perf_counter() - start
    work = sum(line["seconds"] or 0.0 for line in lines)
    return wall, work, lines


def per_task(seconds, count):
    return 1e3 * seconds / count


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--cad", default=str(ROOT.parent / "shared" / "data" / "cad"))
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--tasks", type=int, default=2000)
    args = p.parse_args()
    folders = [pathlib.Path(args.cad) / kind for kind in ("iges", "step", "brep")]
    folders = [f for f in folders if f.is_dir()]
    if not folders:
        sys.exit(f"no CAD folders under {args.cad}")
    settings = Settings()
    jobs_of = lambda out: inputs.discover(folders, out, settings.suffix)
    print(f"load average at start: {os.getloadavg()[0]:.2f}; {os.cpu_count()} cores")

    walls = {}
    for workers in (1, 2):
        start = time.perf_counter()
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True)
        client = Client(cluster)
        started = time.perf_counter() - start
        runs = [convert_all(client, jobs_of, settings) for _ in range(args.repeat)]
        walls[workers] = [wall for wall, _, _ in runs]
        lines = runs[-1][2]
        ok = sum(line["status"] == "ok" for line in lines)
        work = statistics.median(work for _, work, _ in runs)
        busy = work / workers / statistics.median(walls[workers])
        longest = max(line["seconds"] or 0.0 for line in lines)
        print(f"{workers} worker(s): cluster start {started:.1f} s; {len(lines)} files ({ok} ok, "
              f"{len(lines) - ok} failed); wall {', '.join(f'{w:.2f}' for w in walls[workers])} s "
              f"(median {statistics.median(walls[workers]):.2f} s); summed task seconds {work:.2f} s "
              f"(workers busy {100 * busy:.0f} % of the wall time; longest file {longest:.2f} s)")
        if workers == 2:
            client.submit(noop, 0, pure=False).result()  # warm
            start = time.perf_counter()
            client.gather(client.map(noop, range(args.tasks), pure=False))
            throughput = per_task(time.perf_counter() - start, args.tasks)
            start = time.perf_counter()
            for i in range(ROUND_TRIPS):
                client.submit(noop, i, pure=False).result()
            round_trip = per_task(time.perf_counter() - start, ROUND_TRIPS)
            client.gather(client.map(isolated_noop, range(4), pure=False))  # children started
            start = time.perf_counter()
            for i in range(ROUND_TRIPS):
                client.submit(isolated_noop, i, pure=False).result()
            isolated = per_task(time.perf_counter() - start, ROUND_TRIPS)
            print(f"overhead per task (2 workers): throughput {throughput:.2f} ms ({args.tasks} no-op tasks at once), "
                  f"round trip {round_trip:.2f} ms, round trip through the isolated child {isolated:.2f} ms")
        client.close()
        cluster.close()
    one, two = statistics.median(walls[1]), statistics.median(walls[2])
    print(f"speed-up 1 -> 2 workers: {one / two:.2f}x (median wall {one:.2f} s -> {two:.2f} s)")
    print(f"load average at end: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
