"""trimkit-batch end to end (issue 14's acceptance): 20 inputs on a real scheduler with two
workers as separate processes, one worker killed mid-task; every output byte-identical
to `trimkit mesh`'s (the serial run), the manifest listing each input once; a rerun
converting nothing. And a damaged input among good ones: its line says why, the others
succeed, the exit status is 1, and a rerun tries it again while skipping the rest."""
import os
import pathlib
import time

import pytest

from batch_support import (DaskCluster, copy_inputs, mesh_reference, partial_files, read_manifest, run_batch,
                           start_batch, tbp_reference, write_cube_tbp, write_damaged)
from conftest import CAD, ROOT

pytest.importorskip("distributed")
# The test's own Client on Debian's tornado 6.2.
pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")

# Inputs meshing in about 0.2-1 s each (a task must outlast the moment the test kills a
# worker): small shared IGES files with the built-in sample at 0.02 % of each diagonal,
# or without ../shared the built-in sample alone at 2e-5 % (13k triangles).
SHARED_IGES = ["hammer.iges", "occ22470.igs", "bug22566_test_Bad.igs", "BUC50025.igs", "OCC17026-1.igs"]
INPUTS = 20


def sources():
    """(files, the tolerance arguments)."""
    found = [CAD / "iges" / name for name in SHARED_IGES if (CAD / "iges" / name).exists()]
    if found:
        return [ROOT / "samples" / "bracket.igs"] + found, ("--tolerance", "0.0002", "--relative")
    return [ROOT / "samples" / "bracket.igs"], ("--tolerance", "2e-07", "--relative")


def wait_for(condition, seconds, what):
    deadline = time.monotonic() + seconds
    while not condition():
        assert time.monotonic() < deadline, f"timed out waiting for {what}"
        time.sleep(0.05)


def manifest_lines(path):
    try:
        return read_manifest(path)
    except (FileNotFoundError, ValueError):  # not written yet, or a line being written
        return []


def test_killed_worker_loses_nothing_and_a_rerun_skips_everything(tmp_path):
    files, tolerance = sources()
    inputs = copy_inputs(files, tmp_path / "in", INPUTS)
    reference = {}
    for path in inputs:
        reference[path.name] = mesh_reference(path, tmp_path / "serial" / (path.stem + ".glb"), *tolerance)
    out, manifest = tmp_path / "out", tmp_path / "out" / "manifest.jsonl"
    cluster = DaskCluster(tmp_path, workers=2)
    try:
        victim, survivor = cluster.worker_address("w0"), cluster.worker_address("w1")
        with open(tmp_path / "batch.log", "w") as log:
            batch = start_batch(tmp_path / "in", "--out", out, "--scheduler", cluster.address, *tolerance, log=log)

            def victim_busy():  # converting, a few results in
                return len(manifest_lines(manifest)) >= 4 and cluster.client.processing(workers=[victim])[victim]

            wait_for(victim_busy, 120, "the run to get under way")
            in_flight = cluster.client.processing(workers=[victim])[victim]
            cluster.kill("w0")
            status = batch.wait(timeout=300)
        output = (tmp_path / "batch.log").read_text()
        assert status == 0, output
        assert "dashboard" in output

        lines = read_manifest(manifest)
        assert sorted(pathlib.Path(line["input"]).name for line in lines) == sorted(p.name for p in inputs)
        for line in lines:
            name = pathlib.Path(line["input"]).name
            assert line["status"] == "ok", line
            assert line["triangles"] == reference[name]["triangles"] > 0
            assert line["failed_faces"] == [] and line["error"] is None
            assert line["worker"] in (victim, survivor)
            assert line["settings"]["tolerance"] == float(tolerance[1]) and line["settings"]["relative"] is True
            written = pathlib.Path(line["output"])
            assert written == out / (pathlib.Path(name).stem + ".glb")
            assert written.read_bytes() == (tmp_path / "serial" / written.name).read_bytes(), name
            assert line["output_bytes"] == written.stat().st_size
        # The tasks the killed worker held (keys convert-<run>-<n>, n the input's position)
        # finished on the other worker.
        names = sorted(p.name for p in inputs)
        rerun = [names[int(key.split("-")[2])] for key in in_flight]
        by_name = {pathlib.Path(line["input"]).name: line for line in lines}
        assert rerun and any(by_name[name]["worker"] == survivor for name in rerun), (in_flight, lines)
        print(f"killed w0 holding {rerun}; {sum(l['worker'] == victim for l in lines)} of {INPUTS} converted by w0")
        assert partial_files(out) == []

        mtimes = {p: p.stat().st_mtime_ns for p in out.glob("*.glb")}
        again = run_batch(tmp_path / "in", "--out", out, "--scheduler", cluster.address, *tolerance)
        assert again.returncode == 0, again.stderr
        assert "0 converted, 20 skipped, 0 failed" in again.stderr
        assert "scheduler tcp://" not in again.stderr  # nothing to convert: no cluster contacted
        second = read_manifest(manifest)
        assert len(second) == INPUTS and all(line["status"] == "skipped" for line in second)
        assert {line["input"]: line["triangles"] for line in second} == {l["input"]: l["triangles"] for l in lines}
        assert {p: p.stat().st_mtime_ns for p in out.glob("*.glb")} == mtimes
    finally:
        cluster.close()


def test_damaged_input_fails_alone_with_its_reason(tmp_path):
    folder = tmp_path / "in"
    good = copy_inputs([ROOT / "samples" / "bracket.igs"], folder, 2)
    damaged = write_damaged(folder / "damaged.igs")
    cube = write_cube_tbp(folder / "cube.tbp")
    out = tmp_path / "out"
    run = run_batch(folder, "--out", out, "--workers", "2", "--format", "ply", "--tolerance", "0.05")
    assert run.returncode == 1, run.stderr
    lines = {pathlib.Path(line["input"]).name: line for line in read_manifest(out / "manifest.jsonl")}
    assert sorted(lines) == sorted([p.name for p in good] + ["damaged.igs", "cube.tbp"])
    bad = lines["damaged.igs"]
    assert bad["status"] == "failed" and bad["output_bytes"] is None
    assert bad["error"].startswith(f"{damaged}:") and "file truncated" in bad["error"], bad  # the reader's FILE:LINE: reason
    assert f"trimkit-batch: {bad['error']}\n" in run.stderr  # and a line of its own on the terminal
    assert not (out / "damaged.ply").exists()
    for path in good:
        line = lines[path.name]
        reference = mesh_reference(path, tmp_path / (path.stem + ".ply"), "--tolerance", "0.05")
        assert line["status"] == "ok" and line["triangles"] == reference["triangles"]
        assert (out / (path.stem + ".ply")).read_bytes() == (tmp_path / (path.stem + ".ply")).read_bytes()
    polygonized = tbp_reference(cube, tmp_path / "cube.ply")
    assert lines["cube.tbp"]["status"] == "ok" and lines["cube.tbp"]["triangles"] == polygonized["triangles"] > 0
    assert (out / "cube.ply").read_bytes() == (tmp_path / "cube.ply").read_bytes()

    again = run_batch(folder, "--out", out, "--workers", "1", "--format", "ply", "--tolerance", "0.05")
    assert again.returncode == 1
    second = {pathlib.Path(line["input"]).name: line["status"] for line in read_manifest(out / "manifest.jsonl")}
    assert second == {**{p.name: "skipped" for p in good}, "cube.tbp": "skipped", "damaged.igs": "failed"}


def test_usage_errors_exit_2_before_anything_runs(tmp_path):
    run = run_batch(tmp_path / "missing.igs", "--out", tmp_path / "out")
    assert run.returncode == 2 and "missing.igs: no such file or folder" in run.stderr
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    for folder in ("a", "b"):
        (tmp_path / folder / "part.igs").write_bytes((ROOT / "samples" / "bracket.igs").read_bytes())
    run = run_batch(tmp_path / "a" / "part.igs", tmp_path / "b" / "part.igs", "--out", tmp_path / "out")
    assert run.returncode == 2 and "would both be written to" in run.stderr
    run = run_batch(ROOT / "samples", "--out", tmp_path / "out", "--workers", "0")
    assert run.returncode == 2 and "--workers must be > 0" in run.stderr
    assert not os.path.exists(tmp_path / "out")
