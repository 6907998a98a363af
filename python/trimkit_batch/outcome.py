"""What a task reports about one input: the half of a manifest line the worker knows.

status: "ok" (output written), "failed" (no output written; `error` says why) or
"skipped" (a rerun found the output up to date). failed_faces: [{"face", "reason"}]
with `face` numbered as `trimkit mesh` numbers them (instances placed). unread_faces:
the reasons of the faces the reader left out (Model.unread_faces), missing from the
output as failed faces are. deviation:
None, or (with --check) the two-sided distances in model units as `trimkit check`
measures them. seconds: the conversion's own time on its worker, not the wait in the
queue (with --split parts the parts' times and the assembly's, summed). Non-finite
figures become None (the manifest is strict JSON).
"""
import dataclasses
import math
import re

OK, FAILED, SKIPPED = "ok", "failed", "skipped"

# The reason of a failed face starts "face N: " with N as its own meshing numbered it.
_FACE_PREFIX = re.compile(r"^face \d+: ")


@dataclasses.dataclass
class Outcome:
    status: str
    triangles: int = 0
    failed_faces: list = dataclasses.field(default_factory=list)
    unread_faces: list = dataclasses.field(default_factory=list)
    deviation: dict = None
    seconds: float = 0.0
    error: str = None
    output_bytes: int = None
    parts: int = None             # --split parts: unique parts meshed (None: the file whole)
    worker: str = None            # Dask worker address that produced the output


def failed(error, seconds=0.0):
    return Outcome(status=FAILED, error=str(error), seconds=seconds)


def finite(x):
    """x as a float, or None when it is NaN or infinite."""
    x = float(x)
    return x if math.isfinite(x) else None


def failed_face(face, reason):
    return {"face": int(face), "reason": _FACE_PREFIX.sub("", reason)}


def deviation_figures(report, tolerance, scale=1.0):
    """The figures of a native DeviationReport, lengths multiplied by `scale`."""
    return {"mesh_to_surface": finite(report.mesh_to_surface * scale),
            "surface_to_mesh": finite(report.surface_to_mesh * scale),
            "area_ratio": finite(report.area_ratio),
            "open_edges": int(report.open_edges),
            "tolerance": finite(tolerance * scale)}
