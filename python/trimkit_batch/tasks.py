"""The functions Dask runs on workers, one task each: they run the conversion in the
worker thread's isolated child (isolated.py), turn a timeout or a crash into a failed
Outcome for that input (not a Dask error, which would be retried), and name the worker.

Every task is idempotent: it reads its input and writes its output under a temporary
name renamed into place, so when a worker dies mid-task Dask runs it again elsewhere
and the result is the same file.
"""
from . import convert, parts
from .isolated import ChildCrashed, ConversionTimeout, run_isolated
from .outcome import Outcome, failed


def worker_address():
    try:
        from distributed import get_worker
        return get_worker().address
    except (ImportError, ValueError):  # not on a Dask worker (a direct call)
        return None


def isolated(function, *args, timeout=None):
    """function(*args) in the child; its result, or a failed Outcome on timeout or crash.
    An Outcome gets this worker's address."""
    try:
        result = run_isolated(function, *args, timeout=timeout)
    except ConversionTimeout as err:
        result = failed(err, timeout)
    except ChildCrashed as err:
        result = failed(err)
    if isinstance(result, Outcome):
        result.worker = worker_address()
    return result


def convert_task(job, sha256, settings, timeout):
    """Outcome of converting one file."""
    return isolated(convert.convert_file, job, sha256, settings, timeout=timeout)


def plan_task(job, sha256, settings, timeout):
    """parts.Plan of an assembly (empty parts: convert it whole), or a failed Outcome."""
    return isolated(parts.plan_parts, job, sha256, settings, timeout=timeout)


def part_task(job, sha256, settings, part, timeout):
    """parts.PartMesh of one unique part, or a failed Outcome."""
    return isolated(parts.mesh_part, job, sha256, settings, part, timeout=timeout)


def assembly_task(job, settings, plan, meshes, timeout):
    """Outcome of writing the placed parts (`meshes`: part_task results, in plan order)."""
    return isolated(parts.write_assembly, job, settings, plan, meshes, timeout=timeout)
