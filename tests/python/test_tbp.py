"""_trimkit TBP bindings and addon/trimkit/tbp_io.py, on the samples of
tests/native/tbp/tbp_samples.h: the unit cube as 12 flat cubic TBPs, the tilted
square z = 0.4 + 0.1 x + 0.05 y over [-0.6, 1.7] x [-0.45, 1.55] crossing it, an
icosphere made a PN-triangle solid."""
import json
import math
import pathlib
import sys

import numpy as np
import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "addon"))
from trimkit import io, tbp_io  # noqa: E402

tk = io.native()


def flat(a, b, c, n=3):
    a, b, c = map(np.asarray, (a, b, c))
    return [(i * a + j * b + (n - i - j) * c) / n for i in range(n, -1, -1) for j in range(n - i, -1, -1)]


def quads(*corners):
    out = []
    for p0, p1, p2, p3 in corners:
        out += [flat(p0, p1, p2), flat(p0, p2, p3)]
    return np.array(out, np.float64)


def cube(lo=0.0, hi=1.0):
    v = lambda x, y, z: (hi if x else lo, hi if y else lo, hi if z else lo)
    return tk.TbpSolid(quads(
        (v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0)), (v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)),
        (v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)), (v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0)),
        (v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)), (v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1))),
        3, "cube")


def tilted_square(x0=-0.6, x1=1.7, y0=-0.45, y1=1.55):
    p = lambda x, y: (x, y, 0.4 + 0.1 * x + 0.05 * y)
    return tk.TbpSolid(quads((p(x0, y0), p(x1, y0), p(x1, y1), p(x0, y1))), 3, "square")


def icosphere():
    t = (1 + 5 ** 0.5) / 2
    v = np.array([(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
                  (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)], np.float64)
    f = np.array([(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
                  (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
                  (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)], np.int32)
    return v / np.linalg.norm(v, axis=1, keepdims=True), f


SLOPE = math.sqrt(1 + 0.1 ** 2 + 0.05 ** 2)


def test_solid_round_trips_through_numpy_text_and_file(tmp_path):
    c = cube()
    assert (c.degree, len(c), c.name) == (3, 12, "cube")
    assert c.points.shape == (12, 10, 3) and c.points.dtype == np.float64
    again = tk.parse_tbp(tk.tbp_text(c), "cube.tbp")
    np.testing.assert_array_equal(again.points, c.points)
    path = tmp_path / "cube.tbp"
    tk.write_tbp(c, str(path))
    assert json.loads(path.read_text())["degree"] == 3
    np.testing.assert_array_equal(tk.read_tbp(str(path)).points, c.points)
    solid, data = tbp_io.read_tbp_source(path)
    assert data == path.read_bytes() and len(solid) == 12
    np.testing.assert_array_equal(tbp_io.tbp_from_bytes(io.decompress(io.compress(tbp_io.tbp_bytes(c))), "x").points,
                                  c.points)


def test_bad_solids_raise_clear_errors():
    with pytest.raises(ValueError, match=r"\(p, 10, 3\)"):
        tk.TbpSolid(np.zeros((2, 9, 3)), 3)
    with pytest.raises(ValueError, match="degree 21"):
        tk.TbpSolid(np.zeros((1, 3, 3)), 21)
    bad = cube().points
    bad[3, 4, 1] = np.nan
    with pytest.raises(ValueError):
        tk.TbpSolid(bad, 3)
    with pytest.raises(RuntimeError, match="broken.tbp"):
        tk.parse_tbp('{"tbp": 1, "degree": 3, "patches": [[[0,0,0]]]}', "broken.tbp")
    with pytest.raises(RuntimeError, match="missing.tbp"):
        tbp_io.tbp_from_bytes(b"{", "missing.tbp")


def test_cube_polygonizes_watertight_with_area_6():
    for level, lod in ((0, 0), (1, 1), (2, 1), (1, 3)):
        m = tk.polygonize(cube(), tk.PolygonizeOptions(level=level, lod=lod))
        rate = (lod + 1) ** level
        assert m.triangle_count == 12 * rate * rate
        assert tk.surface_area(m) == pytest.approx(6.0, abs=1e-12)
        assert tbp_io.open_edge_count(m.triangles) == 0
        assert m.positions.shape == (m.vertex_count, 3) and m.triangles.dtype == np.int32
        assert set(m.face_ids.tolist()) == set(range(12))
    meshing = tbp_io.tbp_mesh(cube(), 2, 1)
    part = meshing.part
    assert (meshing.triangles, meshing.open_edges, meshing.patches) == (192, 0, 12)
    assert len(part.positions) == 6 * 25 - 12 * 5 + 8  # faces' 5x5 grids, shared edges and corners once
    assert part.corner_normals.shape == (3 * 192, 3) and part.corner_uvs.shape == (3 * 192, 2)
    # every patch edge is a face boundary; the cube's 12 edges (4 segments each) are sharp
    boundary = part.edge_flags & io.EDGE_FACE_BOUNDARY != 0
    sharp = part.edge_flags & io.EDGE_SHARP != 0
    assert np.all(boundary) and sharp.sum() == 12 * 4
    assert len(part.edges) == 12 * 4 + 6 * 4  # cube edges + each face's diagonal
    with pytest.raises(ValueError):
        tbp_io.tbp_mesh(cube(), 3, 63)  # rate 64^3 above TBP_MAX_POLYGONIZE_RATE


def test_points_are_classified_against_the_cube():
    points = np.array([[0.5, 0.5, 0.5], [1.5, 0.5, 0.5], [0.5, 0.5, 1.0], [1e-9, 0.3, 0.7], [-1e-9, 0.3, 0.7],
                       [0.999999, 0.999999, 0.999999], [2, 2, 2], [1, 1, 1]])
    codes = tbp_io.tbp_classify(cube(), points, 1, 1)
    assert codes.dtype == np.int8 and codes.shape == (8,)
    IN, OUT, ON = tk.TBP_INSIDE, tk.TBP_OUTSIDE, tk.TBP_BOUNDARY
    assert codes.tolist() == [IN, OUT, ON, IN, OUT, IN, OUT, ON]
    rng = np.random.default_rng(5)
    random = rng.uniform(-0.5, 1.5, (2000, 3))
    expected = np.where(np.all((random > 0) & (random < 1), axis=1), IN, OUT)
    np.testing.assert_array_equal(tbp_io.tbp_classify(cube(), random), expected)
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        tk.point_in_solid(tk.build_hierarchies(cube(), 1, 1), np.zeros((3, 2)))


def test_square_through_cube_intersects_in_one_closed_loop_with_pruning():
    result = tbp_io.tbp_intersect(tilted_square(), cube(), 2, 3)
    assert len(result.components) == 1 and result.components[0][1]
    points = result.components[0][0]
    assert np.max(np.min(np.abs(np.concatenate([points, points - 1], axis=1)), axis=1)) < 1e-9
    brute = tbp_io.tbp_intersect(tilted_square(), cube(), 2, 3, use_hierarchy=False)
    assert brute.segments == result.segments
    assert result.triangle_tests < brute.triangle_tests / 10
    print(f"square x cube: {len(points)} points, {result.triangle_tests} triangle tests "
          f"({brute.triangle_tests} without the hierarchy)")


@pytest.mark.parametrize("keep, expected", [("outside", (2.3 * 2.0 - 1.0) * SLOPE), ("inside", SLOPE)])
def test_square_trimmed_by_cube_keeps_the_exact_area(keep, expected):
    assert (2.3 * 2.0 - 1.0) * SLOPE == pytest.approx(3.62243012354966, rel=1e-14)
    mesh, parts = tk.trim_solid(tilted_square(), cube(), tk.TrimOptions(levels=2, lod=3, keep=keep))
    assert tk.surface_area(mesh) == pytest.approx(expected, rel=1e-6)
    assert len(parts) == 2
    cut = [b.points[k] for r in parts for b in r.boundaries for k in np.flatnonzero(b.on_cut)]
    assert cut and max(min(min(abs(c), abs(c - 1)) for c in p) for p in cut) < 1e-9
    trim = tbp_io.tbp_trim(tilted_square(), cube(), keep, 2, 3)
    assert trim.area == pytest.approx(expected, rel=1e-6)
    assert trim.triangles == len(trim.part.triangles) > 0 and trim.cut_edges > 0
    assert trim.triangle_tests == sum(r.stats.intersection.triangle_tests for r in parts)
    print(f"square x cube keep {keep}: area {trim.area:.12f}, {trim.triangles} triangles, "
          f"{trim.triangle_tests} triangle tests, {trim.seconds:.3f} s")


def test_bad_trim_keep_is_a_value_error():
    with pytest.raises(ValueError, match="keep"):
        tk.TrimOptions(keep="both")


def test_pn_icosphere_is_closed_and_trims_a_plane_to_a_hole():
    v, f = icosphere()
    # Every side smoothed: the icosahedron's faces meet at 41.8 degrees, above the
    # default crease angle (30), which would keep it flat.
    sphere = tbp_io.mesh_to_tbp(v, f, "ico", sharp_angle=math.pi)
    assert (len(sphere), sphere.degree, sphere.name) == (20, 3, "ico")
    meshing = tbp_io.tbp_mesh(sphere, 1, 2)
    assert meshing.open_edges == 0 and meshing.triangles == 20 * 9
    codes = tbp_io.tbp_classify(sphere, [[0, 0, 0], [0.3, -0.2, 0.1], [2, 0, 0]])
    assert codes.tolist() == [tk.TBP_INSIDE, tk.TBP_INSIDE, tk.TBP_OUTSIDE]
    plane = tilted_square(-2, 2, -2, 2)
    whole = tbp_io.tbp_mesh(plane, 2, 3)
    trim = tbp_io.tbp_trim(plane, sphere, "outside", 2, 3)
    untrimmed_area = 16 * SLOPE
    hole = untrimmed_area - trim.area
    d = 0.4 / SLOPE  # the plane's distance from the centre: the unit sphere's section is pi (1 - d^2)
    assert 0.8 * math.pi * (1 - d * d) < hole < 1.1 * math.pi * (1 - d * d)
    assert trim.boundary_loops == 2  # the hole crosses the diagonal: each half's outline is notched
    print(f"plane x PN icosphere: {whole.triangles} -> {trim.triangles} triangles, area "
          f"{untrimmed_area:.6f} -> {trim.area:.6f}")


def test_sides_marked_sharp_are_creases_whatever_the_sharp_angle():
    v, f = icosphere()
    f = np.asarray(f)
    sides = np.unique(np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1), axis=0)
    assert len(sides) == 30  # the icosahedron's edges
    # every side marked, none sharp by angle (pi) = every side sharp by angle (0): flat patches
    marked = tbp_io.mesh_to_tbp(v, f, "ico", sharp_angle=math.pi, sharp_edges=sides)
    by_angle = tbp_io.mesh_to_tbp(v, f, "ico", sharp_angle=0.0)
    smooth = tbp_io.mesh_to_tbp(v, f, "ico", sharp_angle=math.pi)
    np.testing.assert_array_equal(marked.points, by_angle.points)
    assert np.abs(marked.points - smooth.points).max() > 0.01
    with pytest.raises(ValueError, match="sharp_edges"):
        tbp_io.mesh_to_tbp(v, f, sharp_edges=[(0, len(v))])


def test_open_mesh_is_refused():
    v, f = icosphere()
    with pytest.raises(ValueError, match="not closed"):
        tbp_io.mesh_to_tbp(v, f[1:])


def test_transform_moves_control_points_and_refuses_mirrors():
    m = np.eye(4)
    m[:3, 3] = (1, 2, 3)
    m[0, 0] = 2
    moved = tbp_io.transform_tbp(cube(), m)
    np.testing.assert_allclose(moved.points.reshape(-1, 3).min(0), (1, 2, 3))
    np.testing.assert_allclose(moved.points.reshape(-1, 3).max(0), (3, 3, 4))
    m[0, 0] = -1
    with pytest.raises(ValueError, match="mirror"):
        tbp_io.transform_tbp(cube(), m)
