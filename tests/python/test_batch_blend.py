"""trimkit-batch --format blend: Blender in background converts a chunk of files through
the add-on's batch.convert, started once per chunk; a damaged file in the chunk fails
alone with its reason. Without Blender, a stand-in that hangs or crashes on given files:
each such file fails with the reason and a new Blender carries on with the rest."""
import os
import pathlib
import shutil
import sys

import pytest

from batch_support import copy_inputs, mesh_reference, read_manifest, run_batch, write_damaged
from conftest import ROOT

pytest.importorskip("distributed")


def test_one_blender_per_chunk_and_a_damaged_file_fails_alone(tmp_path, monkeypatch):
    blender = shutil.which("blender")
    if not blender:
        pytest.skip("blender not on PATH")
    starts = tmp_path / "starts.log"
    wrapper = tmp_path / "blender"
    wrapper.write_text(f"#!/bin/sh\necho start >> {starts}\nexec {blender} \"$@\"\n")
    wrapper.chmod(0o755)
    monkeypatch.setenv("TRIMKIT_BLENDER", str(wrapper))
    folder = tmp_path / "in"
    good = copy_inputs([ROOT / "samples" / "bracket.igs"], folder, 2)
    write_damaged(folder / "damaged.igs")
    out = tmp_path / "out"
    run = run_batch(folder, "--out", out, "--format", "blend", "--tolerance", "0.05", "--workers", "1",
                    "--chunk", "3")
    assert run.returncode == 1, run.stderr
    assert starts.read_text().split() == ["start"], "one Blender for the chunk of three files"
    lines = {pathlib.Path(line["input"]).name: line for line in read_manifest(out / "manifest.jsonl")}
    assert lines["damaged.igs"]["status"] == "failed" and "file truncated" in lines["damaged.igs"]["error"]
    triangles = mesh_reference(good[0], tmp_path / "reference.ply", "--tolerance", "0.05")["triangles"]
    for path in good:
        line = lines[path.name]
        blend = out / (path.stem + ".blend")
        assert line["status"] == "ok" and line["triangles"] == triangles, line
        assert blend.read_bytes()[:7] == b"BLENDER" and line["output_bytes"] == blend.stat().st_size
    assert not [p for p in os.listdir(out) if ".partial-" in p]


FAKE_BLENDER = """#!{python}
# Stands in for Blender: speaks blender_chunk.py's protocol, hangs on *hang*, aborts on *crash*.
import json, os, pathlib, sys, time
argv = sys.argv[sys.argv.index("--") + 1:]
request = json.loads(pathlib.Path(argv[0]).read_text())
with open({starts!r}, "a") as f:
    f.write(" ".join(pathlib.Path(job["input"]).name for job in request["jobs"]) + "\\n")
results = open(argv[1], "a")
def say(message):
    results.write(json.dumps(message) + "\\n")
    results.flush()
say("ready")
for job in request["jobs"]:
    name = pathlib.Path(job["input"]).name
    if "hang" in name:
        time.sleep(600)
    if "crash" in name:
        os.abort()
    pathlib.Path(job["output"]).write_bytes(b"BLENDER-fake")
    say({{"input": job["input"], "status": "ok", "triangles": 7, "output_bytes": 12}})
"""


def test_a_hung_or_crashed_blender_fails_its_file_and_a_new_one_takes_the_rest(tmp_path, monkeypatch):
    starts = tmp_path / "starts.log"
    fake = tmp_path / "blender"
    fake.write_text(FAKE_BLENDER.format(python=sys.executable, starts=str(starts)))
    fake.chmod(0o755)
    monkeypatch.setenv("TRIMKIT_BLENDER", str(fake))
    folder = tmp_path / "in"
    names = ["a.igs", "b_hang.igs", "c.igs", "d_crash.igs", "e.igs"]  # equal sizes: submitted in this order
    for name in names:
        copy_inputs([ROOT / "samples" / "bracket.igs"], folder, 1)[0].rename(folder / name)
    out = tmp_path / "out"
    run = run_batch(folder, "--out", out, "--format", "blend", "--workers", "1", "--chunk", "5", "--timeout", "2")
    assert run.returncode == 1, run.stderr
    assert starts.read_text().splitlines() == [" ".join(names), "c.igs d_crash.igs e.igs", "e.igs"]
    lines = {pathlib.Path(line["input"]).name: line for line in read_manifest(out / "manifest.jsonl")}
    assert {name: line["status"] for name, line in lines.items()} == {
        "a.igs": "ok", "b_hang.igs": "failed", "c.igs": "ok", "d_crash.igs": "failed", "e.igs": "ok"}
    assert lines["b_hang.igs"]["error"] == "b_hang.igs: timed out after 2 s (Blender was killed)"
    assert lines["d_crash.igs"]["error"].startswith("d_crash.igs: Blender exited (SIGABRT) before this file")
    assert lines["a.igs"]["triangles"] == 7 and (out / "e.blend").read_bytes() == b"BLENDER-fake"
