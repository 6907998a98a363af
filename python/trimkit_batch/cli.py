"""trimkit-batch: the command line.

    trimkit-batch INPUT... --out DIR [--format glb|ply|obj|stl|blend] [--tolerance T] [--relative]
                  [--angle DEG] [--mode guaranteed|approximate] [--trim-method bezier3d|yang|param]
                  [--check] [--split files|parts] [--workers N | --scheduler tcp://HOST:PORT]
                  [--timeout S] [--chunk K] [--manifest FILE]

Without --scheduler a local Dask cluster of N worker processes (one thread each) is
started and stopped. The manifest defaults to DIR/manifest.jsonl. Exit status: 0 when
every input was converted or skipped, 1 when any failed (its manifest line says why),
2 for a bad command line (nothing converted).
"""
import argparse
import contextlib
import logging
import os
import sys

from . import inputs
from .settings import DEFAULT_RELATIVE_TOLERANCE, FORMATS, MODES, SPLITS, TRIM_METHODS, Settings

# Seconds to reach a scheduler given with --scheduler.
CONNECT_SECONDS = 30
EXIT_FAILED, EXIT_USAGE = 1, 2


def parser():
    p = argparse.ArgumentParser(
        prog="trimkit-batch",
        description="Convert CAD files (IGES, STEP, .brep, .tbp) to meshes or .blend files on a Dask cluster; "
                    "resumable through a JSON-lines manifest.")
    p.add_argument("inputs", nargs="+", metavar="INPUT", help="CAD files, or folders searched for them")
    p.add_argument("--out", required=True, metavar="DIR", help="output folder (a folder input's tree is kept)")
    p.add_argument("--format", choices=FORMATS, default="glb")
    p.add_argument("--tolerance", type=float, metavar="T",
                   help="in the files' units; with --relative a fraction of each model's diagonal "
                        f"(default: --relative {DEFAULT_RELATIVE_TOLERANCE})")
    p.add_argument("--relative", action="store_true")
    p.add_argument("--angle", type=float, default=30.0, metavar="DEG", help="sharp-edge angle (default 30)")
    p.add_argument("--mode", choices=MODES, default="guaranteed")
    p.add_argument("--trim-method", choices=TRIM_METHODS, default="bezier3d")
    p.add_argument("--levels", type=int, default=2, metavar="L", help=".tbp inputs: hierarchy level (default 2)")
    p.add_argument("--lod", type=int, default=3, metavar="K", help=".tbp inputs: lod (default 3)")
    p.add_argument("--check", action="store_true", help="measure each mesh's deviation (as trimkit check)")
    p.add_argument("--split", choices=SPLITS, default="files",
                   help="parts: an assembly's unique parts meshed as separate tasks")
    cluster = p.add_mutually_exclusive_group()
    cluster.add_argument("--workers", type=int, metavar="N",
                         help="local cluster of N worker processes (default: the number of cores)")
    cluster.add_argument("--scheduler", metavar="tcp://HOST:PORT", help="an existing Dask scheduler")
    p.add_argument("--timeout", type=float, metavar="S", help="seconds per file (or part) before it fails")
    p.add_argument("--chunk", type=int, metavar="K", help="--format blend: files per Blender start")
    p.add_argument("--manifest", metavar="FILE", help="default: DIR/manifest.jsonl")
    return p


def settings_of(args):
    relative = args.relative or args.tolerance is None
    tolerance = DEFAULT_RELATIVE_TOLERANCE if args.tolerance is None else args.tolerance
    return Settings(format=args.format, tolerance=tolerance, relative=relative, angle=args.angle, mode=args.mode,
                    trim_method=args.trim_method, split=args.split, check=args.check, levels=args.levels,
                    lod=args.lod)


def check_arguments(args):
    for name in ("workers", "timeout", "chunk"):
        value = getattr(args, name)
        if value is not None and not value > 0:
            raise ValueError(f"--{name} must be > 0 (got {value:g})")


def connect(args):
    """(client, local cluster or None)."""
    from distributed import Client, LocalCluster
    if args.scheduler:
        return Client(args.scheduler, timeout=CONNECT_SECONDS), None
    cluster = LocalCluster(n_workers=args.workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                           silence_logs=logging.ERROR)
    return Client(cluster), cluster


def dashboard_line(client):
    try:
        link = client.dashboard_link
    except Exception:  # a scheduler started without a dashboard
        return "trimkit-batch: no dashboard"
    try:
        import bokeh  # noqa: F401  (the dashboard's pages need it)
        return f"trimkit-batch: dashboard {link}"
    except ImportError:
        base = link.rsplit("/", 1)[0]
        return (f"trimkit-batch: dashboard {link} (needs Bokeh, which Debian 12 does not package; "
                f"workers and tasks: {base}/info/main/workers.html)")


def check_workers(client):
    """Every worker can import the tasks and the native module; names the one that cannot."""
    import importlib

    def importable():
        for module in ("_trimkit", "trimkit_batch.tasks"):
            importlib.import_module(module)
        return True

    try:
        client.run(importable)
    except ImportError as err:
        raise RuntimeError(f"a worker cannot import trimkit ({err}); start workers with "
                           "PYTHONPATH=<trimkit>/build/python (README: trimkit-batch)") from None


def open_cluster(args, stack, inputs_count):
    """The Client of --scheduler or of a new local cluster (closed by `stack`), its
    address and dashboard printed, its workers able to import trimkit."""
    try:
        client, cluster = connect(args)
    except OSError as err:
        raise RuntimeError(f"cannot reach the scheduler {args.scheduler}: {err}") from None
    if cluster is not None:
        stack.callback(cluster.close)
    stack.callback(client.close)  # first: callbacks run last in, first out
    print(f"trimkit-batch: {inputs_count} inputs, scheduler {client.scheduler.address}", file=sys.stderr)
    print(dashboard_line(client), file=sys.stderr)
    if args.scheduler and not client.scheduler_info()["workers"]:
        print(f"trimkit-batch: waiting for a worker (dask worker {args.scheduler})", file=sys.stderr)
        client.wait_for_workers(1)
    check_workers(client)
    return client


def main(argv=None):
    args = parser().parse_args(argv)
    try:
        check_arguments(args)
        settings = settings_of(args)
        jobs = inputs.discover(args.inputs, args.out, settings.suffix)
    except ValueError as err:
        print(f"trimkit-batch: {err}", file=sys.stderr)
        return EXIT_USAGE
    manifest_path = args.manifest or os.path.join(args.out, "manifest.jsonl")

    from .driver import Run, failures
    try:
        with contextlib.ExitStack() as stack:
            lines = Run(lambda: open_cluster(args, stack, len(jobs)), jobs, settings, manifest_path,
                        timeout=args.timeout, chunk=args.chunk).run()
    except RuntimeError as err:
        print(f"trimkit-batch: {err}", file=sys.stderr)
        return EXIT_FAILED
    except KeyboardInterrupt:
        print(f"\ntrimkit-batch: interrupted; {manifest_path} holds what finished, rerun to resume",
              file=sys.stderr)
        return 130
    counts = {status: sum(line["status"] == status for line in lines) for status in ("ok", "skipped", "failed")}
    print(f"trimkit-batch: {counts['ok']} converted, {counts['skipped']} skipped, {counts['failed']} failed; "
          f"manifest {manifest_path}", file=sys.stderr)
    return EXIT_FAILED if failures(lines) else 0
