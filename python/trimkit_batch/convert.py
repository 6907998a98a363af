"""One CAD file to one mesh file (.glb, .ply, .obj, .stl), written as `trimkit mesh`
writes it for the same settings (instances placed, the same tessellation, the same
writer), byte for byte. A .tbp solid is polygonized as `trimkit tbp mesh` does.

Runs where the conversion is isolated (isolated.py): it imports the native module and
returns an Outcome, never raising for a bad file. Each file is meshed on one thread:
the cluster's worker processes are the parallelism.
"""
import math
import pathlib
import time

import _trimkit

from . import model_cache, outputs
from .outcome import OK, Outcome, deviation_figures, failed, failed_face

THREADS_PER_FILE = 1
TBP_SUFFIX = ".tbp"


def tessellation_options(settings, tolerance):
    """Native options at an absolute `tolerance` (model units)."""
    return _trimkit.TessellationOptions(tolerance=tolerance, angle=math.radians(settings.angle),
                                        mode=settings.mode, trim_method=settings.trim_method,
                                        threads=THREADS_PER_FILE)


def absolute_tolerance(model, settings):
    """The tolerance in model units: settings.tolerance, or that fraction of the diagonal
    of the model with its instances placed. ValueError for a relative tolerance of a
    model without faces."""
    if not settings.relative:
        return settings.tolerance
    diagonal = _trimkit.model_diagonal(model)
    if not diagonal > 0.0:
        raise ValueError("a relative tolerance needs a model with faces")
    return settings.tolerance * diagonal


def convert_file(job, sha256, settings):
    """Converts job.input to job.output; the Outcome says what was written or why not."""
    start = time.perf_counter()
    try:
        if pathlib.Path(job.input).suffix.lower() == TBP_SUFFIX:
            outcome = convert_tbp(job, settings)
        else:
            outcome = convert_model(job, sha256, settings)
    except (RuntimeError, ValueError, OSError) as err:
        return failed(err, time.perf_counter() - start)
    outcome.seconds = time.perf_counter() - start
    return outcome


def convert_model(job, sha256, settings):
    model = _trimkit.flatten_instances(model_cache.read(job.input, sha256))
    tolerance = absolute_tolerance(model, settings)
    result = _trimkit.tessellate_model(model, tessellation_options(settings, tolerance))
    size = outputs.write_atomically(job.output, lambda path: _trimkit.write_mesh(path, result.mesh))
    deviation = None
    if settings.check:
        deviation = deviation_figures(_trimkit.measure_deviation(model, result.mesh), result.tolerance)
    return Outcome(status=OK, triangles=result.mesh.triangle_count,
                   failed_faces=[failed_face(f.face, f.reason) for f in result.failed_faces],
                   unread_faces=list(model.unread_faces), deviation=deviation, output_bytes=size)


def convert_tbp(job, settings):
    solid = _trimkit.read_tbp(job.input)
    options = _trimkit.PolygonizeOptions(level=settings.levels, lod=settings.lod, keep_split_normals=True)
    mesh = _trimkit.polygonize(solid, options)
    size = outputs.write_atomically(job.output, lambda path: _trimkit.write_mesh(path, mesh))
    return Outcome(status=OK, triangles=mesh.triangle_count, output_bytes=size)
