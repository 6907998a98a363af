"""The manifest: one JSON object per line, one line per input, written as results arrive.

    {"input": ..., "sha256": ..., "settings": {...}, "output": ..., "status": "ok",
     "triangles": ..., "failed_faces": [...], "unread_faces": [...], "deviation": null, "seconds": ...,
     "worker": "tcp://...", "error": null, "output_bytes": ..., "parts": null}

A run reads the manifest it is about to replace: an input whose last line there says it
was converted ("ok" or "skipped") from a file with the same sha256, with the same
settings, to the same output, and whose output still exists with the size written, is
not converted again ("skipped", its figures carried over). The new manifest replaces
the old one atomically with the skipped lines first, then grows a line per result, so a
driver killed mid-run leaves a manifest the next run resumes from. At the end every
input of the run appears exactly once.
"""
import dataclasses
import hashlib
import json
import os
import pathlib

from .outcome import OK, SKIPPED, Outcome

FIELDS = ("input", "sha256", "settings", "output", "status", "triangles", "failed_faces", "unread_faces",
          "deviation", "seconds", "worker", "error", "output_bytes", "parts")
_HASH_BLOCK = 1 << 20


def sha256_of(path):
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(_HASH_BLOCK), b""):
            digest.update(block)
    return digest.hexdigest()


def record(job, sha256, settings, outcome):
    """The manifest line (a dict in FIELDS order) of `job` converted with `settings`."""
    fields = dataclasses.asdict(outcome)
    line = dict(input=job.input, sha256=sha256, settings=settings.as_dict(), output=job.output)
    line.update({name: fields[name] for name in FIELDS if name in fields})
    return {name: line.get(name) for name in FIELDS}


def read(path):
    """{input: last line about it} of an existing manifest; {} when there is none. A line
    that does not parse (a driver killed while writing it) is ignored."""
    records = {}
    try:
        with open(path, encoding="utf-8") as f:
            for text in f:
                try:
                    line = json.loads(text)
                except json.JSONDecodeError:
                    continue
                if isinstance(line, dict) and "input" in line:
                    records[line["input"]] = line
    except FileNotFoundError:
        pass
    return records


def up_to_date(previous, job, sha256, settings):
    """True when `previous` (a manifest line or None) lets the job be skipped."""
    if not previous or previous.get("status") not in (OK, SKIPPED):
        return False
    if previous.get("sha256") != sha256 or previous.get("settings") != settings.as_dict():
        return False
    if previous.get("output") != job.output:
        return False
    try:
        return os.path.getsize(job.output) == previous.get("output_bytes")
    except OSError:
        return False


def skipped(previous):
    """The outcome of a skipped input: its previous figures, no time, no worker."""
    return Outcome(status=SKIPPED, triangles=previous.get("triangles") or 0,
                   failed_faces=previous.get("failed_faces") or [],
                   unread_faces=previous.get("unread_faces") or [], deviation=previous.get("deviation"),
                   output_bytes=previous.get("output_bytes"), parts=previous.get("parts"))


class Writer:
    """Replaces the manifest at `path` with `first` lines (atomically), then appends a
    line per `write`, flushed at once so that the file follows the run."""

    def __init__(self, path, first=()):
        self.path = pathlib.Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        temporary = self.path.with_name(f".{self.path.name}.{os.getpid()}.tmp")
        with open(temporary, "w", encoding="utf-8") as f:
            for line in first:
                f.write(json.dumps(line, allow_nan=False) + "\n")
        os.replace(temporary, self.path)
        self._file = open(self.path, "a", encoding="utf-8")

    def write(self, line):
        self._file.write(json.dumps(line, allow_nan=False) + "\n")
        self._file.flush()

    def close(self):
        self._file.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
