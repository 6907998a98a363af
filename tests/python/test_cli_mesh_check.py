"""`trimkit mesh` then `trimkit check` on the built-in sample: the tolerance guarantee
end to end through the command line, in every output format; and a face the mesher
cannot mesh correctly (a file written here) reported on stderr, in the JSON with its
figures, and as exit status 3 with --strict."""
import importlib.util
import json
import math
import pathlib
import subprocess

import pytest

from conftest import ROOT


def trimkit_program():
    """The `trimkit` of the build whose _trimkit module is on the path (PYTHONPATH=BUILD/python),
    else build/bin/trimkit."""
    try:
        import _trimkit
        beside = pathlib.Path(_trimkit.__file__).resolve().parents[1] / "bin" / "trimkit"
        if beside.exists():
            return str(beside)
    except ImportError:
        pass
    return str(ROOT / "build" / "bin" / "trimkit")


TRIMKIT = trimkit_program()
# Exact areas of samples/bracket.igs: a 100 x 60 plate with a radius-10 hole, and a
# quarter cylinder of radius 20 and height 40.
PLATE_AREA = 100.0 * 60.0 - 3.141592653589793 * 10.0 ** 2
CYLINDER_AREA = 0.5 * 3.141592653589793 * 20.0 * 40.0


def run_json(*args):
    result = subprocess.run([TRIMKIT, *args, "--json"], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


@pytest.mark.parametrize("extension", ["ply", "obj", "stl", "glb"])
def test_mesh_is_within_tolerance_both_ways(tmp_path, bracket, extension):
    tolerance = 0.05
    out = tmp_path / f"bracket.{extension}"
    mesh = run_json("mesh", bracket, "-o", str(out), "--tolerance", str(tolerance))
    assert mesh["faces_meshed"] == 2 and mesh["failed_faces"] == []
    check = run_json("check", bracket, str(out))
    assert check["mesh_to_surface"]["max"] <= tolerance
    assert check["surface_to_mesh"]["max"] <= tolerance
    assert check["area_exact"] == pytest.approx(PLATE_AREA + CYLINDER_AREA, rel=1e-4)
    assert abs(check["area_ratio"] - 1.0) < 0.002
    assert check["triangles"] == mesh["triangles"]


def test_finer_tolerance_gives_more_triangles(tmp_path, bracket):
    counts = [run_json("mesh", bracket, "-o", str(tmp_path / f"b{t}.ply"), "--tolerance", str(t))["triangles"]
              for t in (0.5, 0.05, 0.005)]
    assert counts[0] < counts[1] < counts[2]


def test_relative_tolerance_is_reported_absolute(tmp_path, bracket):
    mesh = run_json("mesh", bracket, "-o", str(tmp_path / "b.ply"), "--relative", "--tolerance", "0.001")
    # The bracket spans (0,0,0)-(120,80,40): diagonal sqrt(120^2 + 80^2 + 40^2).
    assert mesh["tolerance"] == pytest.approx(0.001 * (120 ** 2 + 80 ** 2 + 40 ** 2) ** 0.5, rel=1e-3)


def iges_writer():
    spec = importlib.util.spec_from_file_location("make_samples", ROOT / "samples" / "make_samples.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def write_stray_hole_plate(path):
    """A plate S = (u, v, 0) over [0, 100] x [0, 60] trimmed (144) to the disc of radius
    20 at (30, 30), with a "hole" of radius 10 at (75, 30) outside that disc: the face's
    own loops bound the disc plus the stray one (500 pi by the even-odd rule), which no
    mesh inside the outer loop covers. Then the bracket's quarter cylinder, which meshes."""
    m = iges_writer()
    w = m.IgesWriter()
    plate = [1, 1, 1, 1, 0, 0, 1, 0, 0, 0, 0, 100, 100, 0, 0, 60, 60, 1.0, 1.0, 1.0, 1.0,
             0.0, 0.0, 0.0, 100.0, 0.0, 0.0, 0.0, 60.0, 0.0, 100.0, 60.0, 0.0,
             0.0, 100.0, 0.0, 60.0]
    surf = w.add(128, plate, status="00010000")
    loops = []
    for cx, radius, clockwise in ((30.0, 20.0, False), (75.0, 10.0, True)):
        pts, wts, knots = m.circle_nurbs(cx, 30.0, radius)
        if clockwise:
            pts, wts = pts[::-1], wts[::-1]
        pcurve = w.add(126, m.curve126(pts, wts, knots, 2), status="00010500")
        mcurve = w.add(126, m.curve126(pts, wts, knots, 2), status="00010000")
        loops.append(w.add(142, [1, surf, pcurve, mcurve, 1], status="00010000"))
    w.add(144, [surf, 1, 1, loops[0], loops[1]])
    s = math.sqrt(0.5)
    cyl = [2, 1, 2, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 40, 40, 1.0, s, 1.0, 1.0, s, 1.0]
    for z in (0.0, 40.0):
        for x, y in ((120.0, 60.0), (120.0, 80.0), (100.0, 80.0)):
            cyl += [x, y, z]
    cyl += [0.0, 1.0, 0.0, 40.0]
    w.add(128, cyl)
    path.write_text(w.text(path.name))
    return str(path)


def run_mesh(*args):
    return subprocess.run([TRIMKIT, "mesh", *args], capture_output=True, text=True, timeout=300)


def test_failed_face_is_reported_with_its_figures(tmp_path):
    model = write_stray_hole_plate(tmp_path / "stray_hole.igs")
    out = tmp_path / "stray_hole.ply"
    result = run_mesh(model, "-o", str(out), "--tolerance", "0.05", "--json")
    assert result.returncode == 0, result.stderr
    mesh = json.loads(result.stdout)
    assert mesh["faces"] == 2 and mesh["faces_meshed"] == 1
    [failed] = mesh["failed_faces"]
    assert failed["face"] == 0 and failed["defect"] in ("area", "trim_loop", "boundary")
    assert failed["area_exact"] == pytest.approx(500.0 * math.pi, rel=1e-3)
    assert abs(failed["area_mesh"] - failed["area_exact"]) > failed["area_bound"] or \
        failed["boundary_gap"] > failed["boundary_bound"]
    assert "retried with yang trims" in failed["reason"]
    assert result.stderr.splitlines() == [f"trimkit: {model}: {failed['reason']}"]
    assert result.stderr.startswith(f"trimkit: {model}: face 0: ")
    assert out.exists()  # the other face is still written


def test_strict_exits_3_when_a_face_failed(tmp_path, bracket):
    model = write_stray_hole_plate(tmp_path / "stray_hole.igs")
    out = tmp_path / "stray_hole.obj"
    result = run_mesh(model, "-o", str(out), "--tolerance", "0.05", "--strict")
    assert result.returncode == 3, result.stderr
    assert result.stderr.startswith(f"trimkit: {model}: face 0: ")
    assert len(result.stderr.splitlines()) == 1
    assert out.exists()
    clean = run_mesh(bracket, "-o", str(tmp_path / "bracket.obj"), "--tolerance", "0.05", "--strict")
    assert clean.returncode == 0 and clean.stderr == ""
