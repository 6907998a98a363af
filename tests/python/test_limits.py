"""Read and tessellation limits, progress and cancel (issues 12 and 13): read_timeout,
progress callbacks and CancelFlag on the readers, face_timeout, progress and cancel on
TessellationOptions, and the CLI's --read-timeout / --face-timeout."""
import re
import subprocess
import threading

import pytest

import _trimkit
from conftest import TRIMKIT

STEP = "step/as1-oc-214-mat.stp"


def test_defaults():
    assert _trimkit.TessellationOptions().face_timeout == 30.0
    assert _trimkit.DEFAULT_READ_TIMEOUT == 120.0
    assert _trimkit.TessellationOptions(face_timeout=0.5).face_timeout == 0.5
    assert issubclass(_trimkit.ReadStopped, _trimkit.ReadError)


def test_read_progress_rises_to_one(bracket):
    seen = []
    model = _trimkit.read_model(bracket, progress=seen.append)
    assert len(model.faces) > 0
    assert seen[0] == 0.0 and seen[-1] == 1.0
    assert all(a < b for a, b in zip(seen, seen[1:]))


@pytest.mark.parametrize("reader", ["read_model", "read_step"])
def test_step_read_cancelled_from_its_progress_callback(cad_sample, reader):
    if not _trimkit.step_supported():
        pytest.skip("built without Open CASCADE")
    path = cad_sample(STEP)
    cancel = _trimkit.CancelFlag()
    seen = []

    def progress(fraction):
        seen.append(fraction)
        if fraction > 0.3:  # inside the transfer (parsing ends at 0.3)
            cancel.set()
    with pytest.raises(_trimkit.ReadStopped, match=r"as1-oc-214-mat.stp: reading cancelled after"):
        getattr(_trimkit, reader)(path, progress=progress, cancel=cancel)
    assert cancel.is_set()
    # Stopped before the translation into our model (0.85 on): OCCT 7.6's transfer
    # reports progress often but asks UserBreak only between its own steps.
    assert max(seen) <= 0.85 + 1e-9, seen[-5:]


def test_step_read_cancelled_from_another_thread(cad_sample):
    if not _trimkit.step_supported():
        pytest.skip("built without Open CASCADE")
    path = cad_sample(STEP)
    cancel = _trimkit.CancelFlag()
    started = threading.Event()

    def progress(fraction):
        started.set()
    timer = threading.Thread(target=lambda: started.wait(30) and cancel.set())
    timer.start()
    with pytest.raises(_trimkit.ReadStopped, match="reading cancelled"):
        _trimkit.read_model(path, progress=progress, cancel=cancel)
    timer.join()


def test_step_read_timeout(cad_sample):
    if not _trimkit.step_supported():
        pytest.skip("built without Open CASCADE")
    with pytest.raises(_trimkit.ReadStopped, match=r"reading stopped after [0-9.]+ s \(read timeout\)"):
        _trimkit.read_model(cad_sample(STEP), read_timeout=1e-6)
    # 0 = no limit
    assert len(_trimkit.read_model(cad_sample(STEP), read_timeout=0).faces) > 0


def test_progress_callback_error_cancels_and_is_raised(bracket):
    def progress(fraction):
        raise KeyError("boom")
    with pytest.raises(RuntimeError, match="progress callback raised"):
        _trimkit.read_model(bracket, progress=progress)


def test_tessellation_progress_and_cancel(bracket):
    model = _trimkit.read_model(bracket)
    seen = []
    options = _trimkit.TessellationOptions(tolerance=0.05)
    options.progress = seen.append
    result = _trimkit.tessellate_model(model, options)
    assert result.faces_meshed == len(model.faces)
    assert seen[-1] == 1.0 and len(seen) == len(model.faces)

    cancel = _trimkit.CancelFlag()
    options = _trimkit.TessellationOptions(tolerance=0.05)
    options.cancel = cancel
    options.progress = lambda fraction: cancel.set()
    with pytest.raises(_trimkit.TessellationCancelled, match="cancelled"):
        _trimkit.tessellate_model(model, options)


def test_cli_read_timeout(cad_sample, tmp_path):
    if not _trimkit.step_supported():
        pytest.skip("built without Open CASCADE")
    path = cad_sample(STEP)
    run = subprocess.run([TRIMKIT, "mesh", path, "-o", str(tmp_path / "a.obj"), "--tolerance", "1",
                          "--read-timeout", "0.000001"], capture_output=True, text=True)
    assert run.returncode == 2
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1 and re.fullmatch(
        rf"trimkit: {re.escape(path)}: reading stopped after [0-9.]+ s \(--read-timeout\)", lines[0]), run.stderr
    assert not (tmp_path / "a.obj").exists()
    info = subprocess.run([TRIMKIT, "info", path, "--read-timeout", "-1"], capture_output=True, text=True)
    assert info.returncode == 2 and "--read-timeout must be seconds >= 0" in info.stderr


def test_cli_face_timeout_bounds_the_slow_fuzz_input(tmp_path):
    """tests/fuzz/slow/iges/self_crossing_trim_loop.igs: 6 s without a limit (bench/FUZZ.md)."""
    from conftest import ROOT
    path = ROOT / "tests" / "fuzz" / "slow" / "iges" / "self_crossing_trim_loop.igs"
    run = subprocess.run([TRIMKIT, "mesh", str(path), "-o", str(tmp_path / "a.obj"), "--tolerance", "0.02",
                          "--relative", "--json", "--face-timeout", "0.5"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    import json
    result = json.loads(run.stdout)
    timed_out = [f for f in result["failed_faces"] if f["defect"] == "timeout"]
    for face in timed_out:
        assert 0.5 <= face["seconds"] < 2.0, face
        assert "timeout: stopped after" in face["reason"]


def addon_modules():
    import pathlib
    import sys
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "addon"))
    from trimkit import io, limits  # the package's __init__ imports no bpy
    return io, limits


def test_addon_limits_cancel_reading_and_meshing(bracket, cad_sample):
    io, limits = addon_modules()
    work = limits.Limits(cancel=_trimkit.CancelFlag())
    work.cancel.set()
    with pytest.raises(limits.Cancelled, match="bracket.igs: cancelled"):
        io.read_source(bracket, work)
    model, _ = io.read_source(bracket, limits.Limits())
    with pytest.raises(limits.Cancelled):
        io.tessellate(model, 0.05, limits=work)
    stages = []
    fine = limits.Limits(cancel=_trimkit.CancelFlag(), on_progress=lambda s, f: stages.append((s, f)))
    result = io.tessellate(model, 0.05, limits=fine)
    assert result.triangles > 0 and stages[-1] == ("mesh", 1.0), stages
    if _trimkit.step_supported():  # STEP goes through a temporary copy: the message names the file
        with pytest.raises(limits.Cancelled, match="as1-oc-214-mat.stp: cancelled"):
            io.read_source(cad_sample(STEP), work)
        with pytest.raises(RuntimeError, match=r"as1-oc-214-mat.stp: reading stopped after .* \(read timeout\)"):
            io.read_source(cad_sample(STEP), limits.Limits(read_timeout=1e-6))
