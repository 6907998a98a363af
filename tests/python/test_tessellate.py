"""_trimkit.tessellate_model, Mesh arrays, read_model_bytes, corner_attributes, write_mesh."""
import numpy as np
import pytest

import _trimkit


def tessellate(path, tolerance):
    model = _trimkit.read_model(path)
    return model, _trimkit.tessellate_model(model, _trimkit.TessellationOptions(tolerance=tolerance))


def test_mesh_arrays_have_documented_shapes_and_dtypes(bracket):
    _, result = tessellate(bracket, 0.05)
    mesh = result.mesh
    n, m = mesh.vertex_count, mesh.triangle_count
    assert n > 0 and m > 0
    assert mesh.positions.shape == (n, 3) and mesh.positions.dtype == np.float64
    assert mesh.normals.shape == (n, 3) and mesh.normals.dtype == np.float64
    assert mesh.uvs.shape == (n, 2) and mesh.uvs.dtype == np.float64
    assert mesh.triangles.shape == (m, 3) and mesh.triangles.dtype == np.int32
    assert mesh.face_ids.shape == (m,) and mesh.face_ids.dtype == np.int32
    k = len(mesh.edge_flags)
    assert mesh.edges.shape == (k, 2) and mesh.edges.dtype == np.int32 and k > 0
    assert mesh.edge_flags.dtype == np.uint8 and np.all(mesh.edge_flags != 0)
    assert mesh.face_colors.shape[1] == 3 and mesh.face_colors.dtype == np.float32
    assert set(np.unique(mesh.face_ids)) == {0, 1}
    assert np.all(np.isfinite(mesh.positions))
    np.testing.assert_allclose(np.linalg.norm(mesh.normals, axis=1), 1.0, atol=1e-6)
    assert result.faces == result.faces_meshed == 2 and not result.failed_faces


def test_cylinder_vertices_lie_within_tolerance_of_radius_20(bracket):
    tolerance = 0.05
    model, result = tessellate(bracket, tolerance)
    mesh = result.mesh
    cylinder = next(i for i, f in enumerate(model.faces) if f.surface.is_rational)
    vertices = np.unique(mesh.triangles[mesh.face_ids == cylinder])
    p = mesh.positions[vertices]
    radius = np.hypot(p[:, 0] - 100.0, p[:, 1] - 60.0)
    assert np.all(np.abs(radius - 20.0) <= tolerance)
    # Triangle centroids deviate from the chord by at most the tolerance too.
    centroids = mesh.positions[mesh.triangles[mesh.face_ids == cylinder]].mean(axis=1)
    r = np.hypot(centroids[:, 0] - 100.0, centroids[:, 1] - 60.0)
    assert np.all(np.abs(r - 20.0) <= tolerance)


def test_triangle_count_decreases_when_tolerance_grows(bracket):
    counts = [tessellate(bracket, t)[1].mesh.triangle_count for t in (0.005, 0.05, 0.5)]
    assert counts[0] > counts[1] > counts[2]


@pytest.mark.parametrize("tolerance", [0.0, -1.0])
def test_tolerance_must_be_positive(bracket, tolerance):
    model = _trimkit.read_model(bracket)
    with pytest.raises(ValueError, match="tolerance"):
        _trimkit.tessellate_model(model, _trimkit.TessellationOptions(tolerance=tolerance))


def test_options_take_mode_and_trim_method_as_strings():
    options = _trimkit.TessellationOptions(tolerance=0.1, mode="approximate", trim_method="yang")
    assert options.mode == "approximate" and options.trim_method == "yang"
    with pytest.raises(ValueError, match="mode"):
        _trimkit.TessellationOptions(mode="exact")


def test_read_model_bytes_matches_read_model(bracket):
    data = open(bracket, "rb").read()
    model = _trimkit.read_model_bytes(data, "bracket.igs")
    assert len(model.faces) == 2 and model.units == "mm"
    with pytest.raises(_trimkit.ReadError, match="broken.igs"):
        _trimkit.read_model_bytes(b"not IGES at all\n", "broken.igs")


def test_relative_tolerance_uses_model_diagonal(bracket):
    model = _trimkit.read_model(bracket)
    diagonal = _trimkit.model_diagonal(model)
    assert 100.0 < diagonal < 300.0


def test_corner_attributes_follow_each_face(bracket):
    model, result = tessellate(bracket, 0.05)
    mesh = result.mesh
    uvs, normals = _trimkit.corner_attributes(model, mesh)
    m = mesh.triangle_count
    assert uvs.shape == (m, 3, 2) and normals.shape == (m, 3, 3)
    np.testing.assert_allclose(np.linalg.norm(normals, axis=2), 1.0, atol=1e-6)
    for f, face in enumerate(model.faces):
        tri = mesh.face_ids == f
        points = face.surface.evaluate(uvs[tri].reshape(-1, 2))
        corners = mesh.positions[mesh.triangles[tri]].reshape(-1, 3)
        assert np.max(np.linalg.norm(points - corners, axis=1)) < 0.05


def test_mesh_round_trips_through_arrays_and_write_mesh(bracket, tmp_path):
    mesh = tessellate(bracket, 0.05)[1].mesh
    copy = _trimkit.Mesh(mesh.positions, mesh.triangles, normals=mesh.normals, uvs=mesh.uvs,
                         face_ids=mesh.face_ids, edges=mesh.edges, edge_flags=mesh.edge_flags)
    np.testing.assert_array_equal(copy.triangles, mesh.triangles)
    with pytest.raises(ValueError, match=r"normals: expected an array of shape \(%d, 3\)" % mesh.vertex_count):
        _trimkit.Mesh(mesh.positions, mesh.triangles, normals=mesh.normals[:-1])
    out = tmp_path / "bracket.glb"
    _trimkit.write_mesh(str(out), copy)
    assert out.stat().st_size > 1000
