"""Long work off Blender's main thread, with a progress bar, status bar text and Esc.

ModalWork is a mixin for operators: start_work(context, work, finish) runs
work(limits) in a thread (it must not touch bpy: it reads and meshes through the
native module, which releases the GIL), then finish(context, value) on the main
thread, where the scene is changed. Esc sets limits.cancel: the native reader and
tessellator stop at their next check, work raises limits.Cancelled and finish is never
called, so the scene is unchanged. In background mode (no window, no events) the work
runs in place, synchronously, and so does work started from a script (modal=False:
bpy.ops called with EXEC_DEFAULT expects {'FINISHED'} when it returns)."""
import threading
import time

import bpy

from . import io, limits as limits_module

# Seconds between the modal timer's looks at the working thread.
POLL_SECONDS = 0.1
# The limits of the work running modally now (tests/blender/modal_import.py cancels through them).
ACTIVE = []
STAGE_NAMES = {"read": "reading", "mesh": "meshing", "check": "checking", "objects": "making objects"}
# Where each stage starts on the progress bar, and its share of it.
STAGE_SPANS = {"read": (0.0, 0.5), "mesh": (0.5, 0.5)}


def overall(stage, fraction):
    """The progress bar's position for `fraction` of `stage`."""
    start, share = STAGE_SPANS.get(stage, (0.0, 1.0))
    return start + share * fraction


class WorkThread(threading.Thread):
    """work(limits) in a daemon thread; `value` or `error` once it has ended."""

    def __init__(self, work, limits):
        super().__init__(daemon=True, name="trimkit work")
        self.work, self.limits = work, limits
        self.value = self.error = None

    def run(self):
        try:
            self.value = self.work(self.limits)
        except BaseException as err:  # handed to the main thread, which reports it
            self.error = err


def new_limits(read_timeout=120.0, face_timeout=30.0):
    return limits_module.Limits(read_timeout=read_timeout, face_timeout=face_timeout,
                                cancel=io.native().CancelFlag())


def status_text(label, limits, started):
    stage, fraction = limits.state()
    name = STAGE_NAMES.get(stage, stage)
    return (f"trimkit: {label}: {name} {100.0 * fraction:.0f} % ({time.perf_counter() - started:.1f} s)"
            f"  -  Esc to cancel")


class ModalWork:
    """Mixin: start_work() from execute(); modal() drives the bar and Esc."""
    _thread = None

    def start_work(self, context, label, work, finish, limits, modal=True):
        """Returns what execute() returns: {'RUNNING_MODAL'}, or (in place) finish's result."""
        self._label, self._finish, self._limits = label, finish, limits
        self._started = time.perf_counter()
        if not modal or bpy.app.background or context.window is None:
            return self.end_work(context, *run_in_place(work, limits))
        ACTIVE.append(limits)
        self._thread = WorkThread(work, limits)
        self._thread.start()
        wm = context.window_manager
        wm.progress_begin(0.0, 1.0)
        self._timer = wm.event_timer_add(POLL_SECONDS, window=context.window)
        wm.modal_handler_add(self)
        return {'RUNNING_MODAL'}

    def modal(self, context, event):
        if event.type == 'ESC' and event.value == 'PRESS':
            self._limits.cancel.set()
            return {'RUNNING_MODAL'}
        if event.type != 'TIMER':
            return {'PASS_THROUGH'}
        if self._thread.is_alive():
            context.window_manager.progress_update(overall(*self._limits.state()))
            context.workspace.status_text_set(status_text(self._label, self._limits, self._started))
            return {'RUNNING_MODAL'}
        wm = context.window_manager
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        context.workspace.status_text_set(None)
        ACTIVE.remove(self._limits)
        return self.end_work(context, self._thread.value, self._thread.error)

    def end_work(self, context, value, error):
        if isinstance(error, limits_module.Cancelled) or (error is None and self._limits.cancelled):
            self.report({'WARNING'}, f"{self._label}: cancelled; nothing was changed")
            return {'CANCELLED'}
        if isinstance(error, (RuntimeError, ValueError, OSError, ImportError)):
            self.report({'ERROR'}, str(error))
            return {'CANCELLED'}
        if error is not None:
            raise error
        return self._finish(context, value)


def run_in_place(work, limits):
    """(value, error) of work(limits) run on this thread."""
    try:
        return work(limits), None
    except (limits_module.Cancelled, RuntimeError, ValueError, OSError, ImportError) as err:
        return None, err
