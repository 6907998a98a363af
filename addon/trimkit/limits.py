"""Time limits, progress and cancel of one piece of work (an import, a re-mesh), without
bpy. The working thread calls the native readers and the tessellator with them; the
operator's thread sets `cancel` (Esc) and reads `stage` / `fraction` for its progress bar.
A cancelled job raises Cancelled before anything is added to the scene."""
import dataclasses
import threading


class Cancelled(Exception):
    """The work was cancelled (Esc): nothing was changed."""


@dataclasses.dataclass
class Limits:
    read_timeout: float = 120.0   # seconds for reading one file; 0: no limit
    face_timeout: float = 30.0    # seconds per CAD face; a slower face fails ("timeout")
    cancel: object = None         # a _trimkit.CancelFlag, set from any thread; None: not cancellable
    stage: str = ""               # "read", "mesh", ... (what `fraction` is of)
    fraction: float = 0.0         # of the current stage
    on_progress: object = None    # optional callable(stage, fraction), from the working thread
    _lock: threading.Lock = dataclasses.field(default_factory=threading.Lock, repr=False)

    def begin(self, stage):
        self.report(stage, 0.0)

    def report(self, stage, fraction):
        with self._lock:
            self.stage, self.fraction = stage, float(fraction)
        if self.on_progress:
            self.on_progress(stage, fraction)

    def progress(self, stage):
        """A callable(fraction) reporting `stage` (what the native code calls)."""
        return lambda fraction: self.report(stage, fraction)

    def state(self):
        with self._lock:
            return self.stage, self.fraction

    @property
    def cancelled(self):
        return self.cancel is not None and self.cancel.is_set()

    def check(self):
        """Raises Cancelled once cancel is set (between steps of the work)."""
        if self.cancelled:
            raise Cancelled("cancelled")


def read_arguments(limits, stage="read"):
    """Keyword arguments of the native readers for `limits` (None: the defaults)."""
    if limits is None:
        return {}
    return dict(read_timeout=limits.read_timeout, progress=limits.progress(stage), cancel=limits.cancel)


def apply(options, limits, stage="mesh"):
    """Sets face_timeout, cancel and progress of a _trimkit.TessellationOptions."""
    if limits is None:
        return options
    options.face_timeout = limits.face_timeout
    if limits.cancel is not None:
        options.cancel = limits.cancel
    options.progress = limits.progress(stage)
    return options


def cancelled_error(err, limits, name):
    """Cancelled for a native ReadStopped / TessellationCancelled caused by `limits`'
    cancel flag, else None (a timeout stays the RuntimeError it is)."""
    if limits is not None and limits.cancelled:
        return Cancelled(f"{name}: cancelled")
    return None
