"""`trimkit mesh` then `trimkit check` on the built-in sample: the tolerance guarantee
end to end through the command line, in every output format."""
import json
import subprocess

import pytest

from conftest import ROOT

TRIMKIT = str(ROOT / "build" / "bin" / "trimkit")
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
