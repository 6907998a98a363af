"""`trimkit tbp`: mesh, intersect, trim, inside and from-mesh on small generated solids
(a unit cube of 12 flat cubic TBPs, a tilted square of two, an icosahedron OBJ)."""
import json
import math
import subprocess

import pytest

from conftest import TRIMKIT


def run(*args):
    return subprocess.run([TRIMKIT, *args], capture_output=True, text=True, timeout=120)


def flat(a, b, c, n=3):
    return [[(i * a[t] + j * b[t] + (n - i - j) * c[t]) / n for t in range(3)]
            for i in range(n, -1, -1) for j in range(n - i, -1, -1)]


def quad(out, p0, p1, p2, p3):
    out += [flat(p0, p1, p2), flat(p0, p2, p3)]


@pytest.fixture
def solids(tmp_path):
    v = lambda x, y, z: [float(x), float(y), float(z)]
    cube = []
    quad(cube, v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0))
    quad(cube, v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1))
    quad(cube, v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1))
    quad(cube, v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0))
    quad(cube, v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0))
    quad(cube, v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1))
    p = lambda x, y: [x, y, 0.4 + 0.1 * x + 0.05 * y]
    square = []
    quad(square, p(-0.6, -0.45), p(1.7, -0.45), p(1.7, 1.55), p(-0.6, 1.55))
    paths = {"cube": tmp_path / "cube.tbp", "square": tmp_path / "square.tbp"}
    paths["cube"].write_text(json.dumps({"tbp": 1, "degree": 3, "name": "cube", "patches": cube}))
    paths["square"].write_text(json.dumps({"tbp": 1, "degree": 3, "patches": square}))
    return {k: str(x) for k, x in paths.items()}


def test_mesh_cube_is_watertight(solids, tmp_path):
    result = run("tbp", "mesh", solids["cube"], "--levels", "2", "--lod", "1", "-o", str(tmp_path / "c.obj"), "--json")
    assert result.returncode == 0, result.stderr
    info = json.loads(result.stdout)
    assert info["triangles"] == 12 * 16 and info["open_edges"] == 0


def test_intersect_square_cube_is_one_closed_loop(solids):
    result = run("tbp", "intersect", solids["square"], solids["cube"], "--json")
    assert result.returncode == 0, result.stderr
    info = json.loads(result.stdout)
    assert info["closed"] == 1 and info["open"] == 0
    assert 0 < info["triangle_tests"] < 10000
    for point in info["components"][0]["points"]:
        assert min(min(abs(c), abs(c - 1)) for c in point) < 1e-9


def test_trim_keeps_square_minus_section(solids, tmp_path):
    factor = math.sqrt(1 + 0.1 ** 2 + 0.05 ** 2)
    for keep, area in (("outside", (2.3 * 2.0 - 1) * factor), ("inside", factor)):
        result = run("tbp", "trim", solids["square"], solids["cube"], "--keep", keep, "-o", str(tmp_path / "t.ply"), "--json")
        assert result.returncode == 0, result.stderr
        assert json.loads(result.stdout)["area"] == pytest.approx(area, rel=1e-6)


def test_inside_point_and_points_file(solids, tmp_path):
    assert run("tbp", "inside", solids["cube"], "0.5", "0.5", "0.5").stdout.strip() == "inside"
    assert run("tbp", "inside", solids["cube"], "-0.5", "0.5", "0.5").stdout.strip() == "outside"
    points = tmp_path / "p.txt"
    points.write_text("0.5 0.5 0.5\n1.000000001 0.5 0.5\n")
    result = run("tbp", "inside", solids["cube"], "--points", str(points))
    assert result.stdout.split() == ["inside", "outside"]


def test_from_mesh_pn_and_loop(tmp_path):
    t = (1 + 5 ** 0.5) / 2
    V = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
         (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
         (8, 6, 7), (9, 8, 1)]
    obj = tmp_path / "ico.obj"
    obj.write_text("".join("v %r %r %r\n" % v for v in V) + "".join("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in F))
    for scheme, degree in (("pn", 3), ("loop", 4)):
        out = tmp_path / f"{scheme}.tbp"
        result = run("tbp", "from-mesh", str(obj), "-o", str(out), "--scheme", scheme)
        assert result.returncode == 0, result.stderr
        solid = json.loads(out.read_text())
        assert solid["degree"] == degree and len(solid["patches"]) == 20
        assert solid["name"] == "ico"  # named after the mesh file, not after the scheme
        assert run("tbp", "inside", str(out), "0", "0", "0").stdout.strip() == "inside"
    # The icosahedron's faces meet at 41.8 degrees: creases at the default 30, smooth at 45.
    def bulge(path):
        patches = json.loads(path.read_text())["patches"]
        return max(abs(sum(x * x for x in p[4]) ** 0.5) for p in patches)  # centre control point's radius
    for angle, out in (("30", "flat.tbp"), ("45", "round.tbp")):
        assert run("tbp", "from-mesh", str(obj), "-o", str(tmp_path / out), "--sharp-angle", angle).returncode == 0
    corner = (1 + t * t) ** 0.5  # the vertices' radius
    assert bulge(tmp_path / "flat.tbp") < corner * 0.8  # face centres sit inside, on the flat faces
    assert bulge(tmp_path / "round.tbp") > bulge(tmp_path / "flat.tbp") * 1.1
    assert run("tbp", "from-mesh", str(obj), "-o", str(tmp_path / "x.tbp"), "--sharp-angle", "-1").returncode == 2


def test_bad_tbp_names_file_and_line(tmp_path):
    bad = tmp_path / "bad.tbp"
    bad.write_text('{"tbp": 1, "degree": 3,\n "patches": [[[0, 0, 0]]]}')
    result = run("tbp", "mesh", str(bad), "-o", str(tmp_path / "x.obj"))
    assert result.returncode == 2
    assert result.stderr.startswith(f"trimkit: {bad}:2: patch 0 has 1 control points, expected 10")


def test_usage_errors_exit_2(solids, tmp_path):
    assert run("tbp").returncode == 2
    assert run("tbp", "trim", solids["square"], solids["cube"], "--keep", "sideways", "-o", str(tmp_path / "x.obj")).returncode == 2
