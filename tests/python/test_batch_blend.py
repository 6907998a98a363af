"""trimkit-batch --format blend: Blender in background converts a chunk of files through
the add-on's batch.convert, started once per chunk; a damaged file in the chunk fails
alone with its reason."""
import os
import pathlib
import shutil

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
