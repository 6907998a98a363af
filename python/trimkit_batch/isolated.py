"""Conversions run in a child process of the worker, so that a file that crashes the
native code (a signal) or runs past --timeout costs the child, not the Dask worker.

One child per worker thread, started on first use and kept between tasks (its imports,
and model_cache's last model, are reused); it is killed when a call overruns its
timeout and started again by the next call. The child exits when its parent dies (a
killed worker): it watches its parent and the pipe. Calls cross as pickles: a function
(by reference, so importable in the child) and its arguments, and back its result.

    python -m trimkit_batch.isolated FD     # the child; FD: its end of the pipe
"""
import importlib.util
import os
import pathlib
import signal
import subprocess
import sys
import threading
import traceback
from multiprocessing.connection import Connection, Pipe

# How often the child checks that its parent is alive, seconds.
PARENT_CHECK_SECONDS = 0.5


class ConversionTimeout(Exception):
    """A call ran longer than its timeout; the child was killed."""


class ChildCrashed(Exception):
    """The child died during a call (a signal, or os._exit in native code)."""


def child_pythonpath():
    """PYTHONPATH for the child: where this package and _trimkit were found, then the
    worker's own PYTHONPATH."""
    folders = [str(pathlib.Path(__file__).resolve().parents[1])]
    spec = importlib.util.find_spec("_trimkit")
    if spec and spec.origin:
        folders.append(str(pathlib.Path(spec.origin).parent))
    inherited = os.environ.get("PYTHONPATH")
    return os.pathsep.join(folders + ([inherited] if inherited else []))


def signal_name(returncode):
    if returncode is not None and returncode < 0:
        try:
            return signal.Signals(-returncode).name
        except ValueError:
            return f"signal {-returncode}"
    return f"exit status {returncode}"


class Runner:
    """Calls functions in a kept child process; not thread-safe (one per thread)."""

    def __init__(self):
        self._process = None
        self._connection = None

    def call(self, function, args, timeout=None):
        """function(*args) in the child. Raises ConversionTimeout after `timeout` seconds
        (None: no limit), ChildCrashed if the child died, RuntimeError with the child's
        traceback if the function raised."""
        self._ensure_child()
        try:
            self._connection.send((function, args))
        except OSError:  # the child died since the last call: once more with a new one
            self._forget()
            self._ensure_child()
            self._connection.send((function, args))
        if not self._connection.poll(timeout):
            self.stop()
            raise ConversionTimeout(f"timed out after {timeout:g} s (the conversion was killed)")
        try:
            ok, value = self._connection.recv()
        except (EOFError, OSError):
            returncode = self._process.wait()
            self._forget()
            raise ChildCrashed(f"the conversion crashed ({signal_name(returncode)})") from None
        if not ok:
            raise RuntimeError(value)
        return value

    def stop(self):
        if self._process is not None:
            self._process.kill()
            self._process.wait()
        self._forget()

    def _forget(self):
        if self._connection is not None:
            self._connection.close()
        self._process = self._connection = None

    def _ensure_child(self):
        if self._process is not None and self._process.poll() is None:
            return
        self._forget()
        mine, theirs = Pipe()
        env = dict(os.environ, PYTHONPATH=child_pythonpath())
        self._process = subprocess.Popen([sys.executable, "-m", __name__, str(theirs.fileno())],
                                         pass_fds=[theirs.fileno()], env=env, stdin=subprocess.DEVNULL)
        theirs.close()
        self._connection = mine


_local = threading.local()


def run_isolated(function, *args, timeout=None):
    """function(*args) in this thread's child process (see Runner.call)."""
    runner = getattr(_local, "runner", None)
    if runner is None:
        runner = _local.runner = Runner()
    return runner.call(function, args, timeout)


def exit_with_parent(parent):
    while True:
        threading.Event().wait(PARENT_CHECK_SECONDS)
        if os.getppid() != parent:
            os._exit(1)


def serve(connection):
    """The child's loop: a (function, args) in, (True, result) or (False, traceback) out,
    until the pipe closes."""
    threading.Thread(target=exit_with_parent, args=(os.getppid(),), daemon=True).start()
    while True:
        try:
            function, args = connection.recv()
        except EOFError:
            return
        try:
            reply = (True, function(*args))
        except Exception:
            reply = (False, traceback.format_exc())
        connection.send(reply)


if __name__ == "__main__":
    serve(Connection(int(sys.argv[1])))
