"""--format blend: Blender in background converts a chunk of files, one Blender start
per chunk, through the add-on's batch.convert (blender_chunk.py is the script it runs).

Blender reports each file as it finishes (a JSON line in a results file). --timeout
applies to each file: when Blender makes no progress for that long, or dies, the file
it was on fails with the reason, and a new Blender carries on with the rest of the
chunk. Blender: $TRIMKIT_BLENDER, else `blender` on PATH.
"""
import dataclasses
import importlib.util
import json
import math
import os
import pathlib
import shutil
import subprocess
import tempfile
import time

from .isolated import signal_name
from .outcome import Outcome, failed
from .tasks import worker_address

# Seconds Blender may take to start and load the add-on before the first file's clock runs.
BLENDER_START_SECONDS = 120.0
# How often the results file and Blender are looked at, seconds.
POLL_SECONDS = 0.2
# Lines of Blender's output quoted in a failure.
LOG_TAIL_LINES = 5

SCRIPT = pathlib.Path(__file__).with_name("blender_chunk.py")
ADDON_FOLDER = pathlib.Path(__file__).resolve().parents[2] / "addon"  # holds the trimkit add-on package
READY = "ready"


def blender_binary():
    return os.environ.get("TRIMKIT_BLENDER") or shutil.which("blender") or "blender"


def search_path():
    """Folders Blender's Python needs: this package's parent, the add-on's parent and the
    native module's folder."""
    folders = [str(pathlib.Path(__file__).resolve().parents[1]), str(ADDON_FOLDER)]
    spec = importlib.util.find_spec("_trimkit")
    if spec and spec.origin:
        folders.append(str(pathlib.Path(spec.origin).parent))
    return folders


def blend_chunk_task(jobs, settings, timeout):
    """Converts jobs to .blend files; returns [(input, Outcome)] in order."""
    outcomes = {}
    pending = list(jobs)
    while pending:
        reported, stopped = run_blender(pending, settings, timeout)
        outcomes.update(reported)
        pending = [job for job in pending if job.input not in outcomes]
        if pending:  # Blender stopped on the first file it did not report
            job = pending.pop(0)
            outcomes[job.input] = failed(f"{job.name}: {stopped}")
    address = worker_address()
    for outcome in outcomes.values():
        outcome.worker = address
    return [(job.input, outcomes[job.input]) for job in jobs]


def run_blender(jobs, settings, timeout):
    """One Blender on `jobs`: ({input: Outcome} reported, why it stopped early or None)."""
    with tempfile.TemporaryDirectory(prefix="trimkit-blend-") as folder:
        folder = pathlib.Path(folder)
        request = folder / "chunk.json"
        results = folder / "results.jsonl"
        log = folder / "blender.log"
        request.write_text(json.dumps({
            "path": search_path(), "settings": settings.as_dict(),
            "jobs": [{"input": job.input, "output": job.output} for job in jobs]}))
        results.touch()
        command = [blender_binary(), "-b", "--factory-startup", "--python-exit-code", "1",
                   "-P", str(SCRIPT), "--", str(request), str(results)]
        with open(log, "wb") as out:
            try:
                process = subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
            except OSError as err:
                return {}, f"cannot start Blender ({command[0]}): {err}"
        reported, stopped = watch(process, results, timeout)
        if stopped is None and len(reported) < len(jobs):
            stopped = f"Blender exited ({signal_name(process.returncode)}) before this file: {log_tail(log)}"
        return reported, stopped


def watch(process, results, timeout):
    """Reads results as Blender writes them; kills Blender when the current file
    overruns `timeout`. Returns ({input: Outcome}, why it was killed, or None)."""
    reported, offset, ready = {}, 0, False
    deadline = time.monotonic() + BLENDER_START_SECONDS
    while True:
        exited = process.poll() is not None  # before reading: every line written before the exit is read
        messages, offset = new_lines(results, offset)
        for message in messages:
            ready = True
            if message != READY:
                reported[message["input"]] = outcome_of(message)
            deadline = time.monotonic() + timeout if timeout else math.inf
        if exited:
            return reported, None
        if time.monotonic() > deadline:
            process.kill()
            process.wait()
            if ready:
                return reported, f"timed out after {timeout:g} s (Blender was killed)"
            return reported, f"Blender did not start within {BLENDER_START_SECONDS:g} s"
        time.sleep(POLL_SECONDS)


def new_lines(path, offset):
    """(JSON messages of the complete lines after byte `offset`, the new offset)."""
    with open(path, "rb") as f:
        f.seek(offset)
        data = f.read()
    complete = data[:data.rfind(b"\n") + 1]
    return [json.loads(line) for line in complete.splitlines()], offset + len(complete)


def outcome_of(message):
    names = {field.name for field in dataclasses.fields(Outcome)}
    return Outcome(**{k: v for k, v in message.items() if k in names})


def log_tail(log):
    lines = [line for line in log.read_text(errors="replace").splitlines() if line.strip()]
    return " | ".join(lines[-LOG_TAIL_LINES:]) or "no output"
