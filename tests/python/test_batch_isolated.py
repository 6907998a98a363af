"""trimkit_batch.isolated: the child process a worker converts in. A call past its
timeout kills the child, a crash is reported with its signal, an exception comes back
with its traceback, the next call gets a fresh child, and a child whose parent is
killed (a Dask worker killed mid-task) exits."""
import os
import signal
import subprocess
import sys
import time

import pytest

from trimkit_batch.isolated import ChildCrashed, ConversionTimeout, Runner


def alive(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] not in ("Z", "X")
    except FileNotFoundError:
        return False


@pytest.fixture
def runner():
    r = Runner()
    yield r
    r.stop()


def test_a_call_past_its_timeout_kills_the_child(runner):
    first = runner.call(os.getpid, ())
    start = time.monotonic()
    with pytest.raises(ConversionTimeout, match="timed out after 0.5 s"):
        runner.call(time.sleep, (60,), timeout=0.5)
    assert time.monotonic() - start < 10
    assert not alive(first)
    assert runner.call(os.getpid, ()) != first


def test_a_crash_is_reported_with_its_signal_and_the_next_call_works(runner):
    with pytest.raises(ChildCrashed, match="SIGABRT"):
        runner.call(os.abort, ())
    assert runner.call(sum, ([1, 2, 3],)) == 6


def test_an_exception_comes_back_with_its_traceback(runner):
    with pytest.raises(RuntimeError, match="ValueError: invalid literal"):
        runner.call(int, ("not a number",))
    assert runner.call(int, ("7",)) == 7  # the same child carries on


def test_the_child_exits_when_its_parent_is_killed():
    # The parent keeps its Runner: a temporary one would be collected after the call,
    # closing the pipe, and the child would exit on EOF before it is checked.
    parent = subprocess.Popen(
        [sys.executable, "-c", "import os, time\nfrom trimkit_batch.isolated import Runner\n"
         "runner = Runner()\nprint(runner.call(os.getpid, ()), flush=True)\ntime.sleep(60)"],
        stdout=subprocess.PIPE, text=True, env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    child = int(parent.stdout.readline())
    assert alive(child)
    parent.send_signal(signal.SIGKILL)
    parent.wait()
    deadline = time.monotonic() + 10
    while alive(child) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not alive(child)
