"""addon/trimkit/io.py (the add-on's bpy-free half): parts, per-face UVs, materials, merging."""
import pathlib
import sys

import numpy as np
import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "addon"))
from trimkit import io  # noqa: E402  (the package's __init__ imports no bpy)


def test_one_part_per_face_with_uvs_normalized_per_face(bracket):
    model, data = io.read_source(bracket)
    assert data.startswith(b"trimkit built-in sample")
    result = io.tessellate(model, 0.05, scale=1e-3, split="FACE")
    assert [p.name for p in result.parts] == ["Face.0", "Face.1"]
    assert sum(len(p.triangles) for p in result.parts) == result.triangles
    for part in result.parts:
        m = len(part.triangles)
        assert part.triangles.dtype == np.int32 and part.triangles.max() < len(part.positions)
        assert part.corner_uvs.shape == (3 * m, 2) and part.corner_normals.shape == (3 * m, 3)
        np.testing.assert_allclose(part.corner_uvs.min(axis=0), 0.0, atol=1e-6)
        np.testing.assert_allclose(part.corner_uvs.max(axis=0), 1.0, atol=1e-6)
        assert set(part.face_ids.tolist()) == {part.index}
        assert np.all(part.edges < len(part.positions)) and len(part.edges) == len(part.edge_flags)
        assert part.materials == [("trimkit default", io.DEFAULT_COLOR)]
        assert np.all(part.material_index == 0)
    assert np.abs(np.concatenate([p.positions for p in result.parts])).max() < 1.0  # mm -> m


def test_model_without_bodies_is_one_part_named_after_the_file(bracket):
    model, _ = io.read_source(bracket)
    result = io.tessellate(model, 0.001, relative=True, stem="bracket")
    assert [(p.name, p.kind, p.index) for p in result.parts] == [("bracket", "MODEL", -1)]
    assert result.tolerance == pytest.approx(0.001 * io.native().model_diagonal(model))


def test_stored_bytes_round_trip_and_merge_writes_glb(bracket, tmp_path):
    data = pathlib.Path(bracket).read_bytes()
    model = io.read_bytes(io.decompress(io.compress(data)), "bracket.igs")
    result = io.tessellate(model, 0.05, split="FACE")
    out = tmp_path / "bracket.glb"
    io.write_mesh(out, result.parts)
    assert out.stat().st_size > 1000


def test_bad_bytes_raise_naming_the_file():
    with pytest.raises(RuntimeError, match="broken.igs"):
        io.read_bytes(b"garbage", "broken.igs")
