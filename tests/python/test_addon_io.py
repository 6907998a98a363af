"""addon/trimkit/io.py (the add-on's bpy-free half): parts, per-face UVs, materials, merging."""
import dataclasses
import pathlib
import sys

import numpy as np
import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "addon"))
from trimkit import io  # noqa: E402  (the package's __init__ imports no bpy)


def test_one_part_per_face_with_uvs_normalized_per_face(bracket):
    model, data = io.read_source(bracket)
    assert data.startswith(b"trimkit built-in sample")
    result = io.tessellate(model, 0.05, scale=1e-3, split="FACE", uv_mode="FACE")
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


def test_step_bytes_read_like_the_file(cad_sample):
    if not io.has_step():
        pytest.skip("_trimkit built without Open CASCADE")
    path = cad_sample("step/screw.step")
    model = io.read_bytes(pathlib.Path(path).read_bytes(), "screw.step")
    assert len(model.faces) == len(io.native().read_step(path).faces) == 10
    assert model.units == "mm" and model.scale_to_metres == 1e-3


def test_bad_step_bytes_raise_naming_the_file_not_its_copy():
    if not io.has_step():
        with pytest.raises(RuntimeError, match="broken.step: .*without Open CASCADE"):
            io.read_bytes(b"garbage", "broken.step")
        return
    with pytest.raises(RuntimeError, match="broken.step") as err:
        io.read_bytes(b"garbage", "broken.step")
    assert "trimkit-" not in str(err.value)


def test_models_without_instances_have_no_placements(bracket):
    model, _ = io.read_source(bracket)
    assert model.instances == [] and io.placements(model, 1e-3) == []


def test_instances_place_bodies_with_translations_in_blender_units(cad_sample):
    model, _ = io.read_source(cad_sample("iges/bug33327.igs"))
    if not model.instances:
        pytest.skip("the IGES reader flattens 308/408 subfigures (Model.instances empty)")
    placements = io.placements(model, 1e-3)
    assert len(placements) == len(model.instances)
    for placement, instance in zip(placements, model.instances):
        assert 0 <= placement.body < len(model.bodies)
        np.testing.assert_allclose(placement.matrix[:3, :3], np.asarray(instance.matrix)[:3, :3])
        np.testing.assert_allclose(placement.matrix[:3, 3], 1e-3 * np.asarray(instance.matrix)[:3, 3])
    result = io.tessellate(model, 0.001, relative=True, split="FACE")
    assert {p.kind for p in result.parts} <= {"BODY", "MODEL"}, "instances place whole bodies"


def test_step_in_metres_comes_in_millimetres(cad_sample):
    # OCCT converts lengths to xstep.cad.unit (mm); this file's unit is the metre and its
    # points span 0.414 m (placement points included).
    if not io.has_step():
        pytest.skip("_trimkit built without Open CASCADE")
    model, _ = io.read_source(cad_sample("step/bm2_ec_lever-A.stp"))
    assert model.units == "mm"
    assert 0.2 < io.native().model_diagonal(model) * model.scale_to_metres < 0.414


def test_placed_parts_move_instanced_bodies_and_keep_mirrored_ones_outward(bracket):
    model, _ = io.read_source(bracket)
    part = io.tessellate(model, 0.05).parts[0]
    body = dataclasses.replace(part, kind="BODY", index=0)
    turn = np.eye(4)
    turn[:2, :2] = [[0.0, -1.0], [1.0, 0.0]]
    turn[:3, 3] = (10.0, 0.0, 0.0)
    mirror = np.diag([-1.0, 1.0, 1.0, 1.0])
    placed = io.placed_parts([body, part], [io.Placement(0, turn, "a"), io.Placement(0, mirror, "b")])
    assert len(placed) == 3 and placed[2] is part
    for moved, matrix in zip(placed, (turn, mirror)):
        np.testing.assert_allclose(moved.positions, body.positions @ matrix[:3, :3].T + matrix[:3, 3])
        corners = moved.positions[moved.triangles]
        face_normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
        agree = np.sum(face_normals * moved.corner_normals.reshape(-1, 3, 3)[:, 0], axis=1)
        assert np.mean(agree > 0) > 0.99, "triangles turned against their normals"
        np.testing.assert_allclose(np.linalg.norm(moved.corner_normals, axis=1), 1.0, rtol=1e-5)


def test_measure_one_face_part_within_tolerance_and_a_moved_vertex_beyond(bracket):
    model, _ = io.read_source(bracket)
    result = io.tessellate(model, 0.05, split="FACE")
    part = result.parts[1]  # face 1 alone: face 0 is not measured
    report = io.measure(model, part.positions, part.triangles, part.face_ids, [1])
    assert 0.0 < max(report.mesh_to_surface, report.surface_to_mesh) <= result.tolerance
    assert report.area_ratio == pytest.approx(1.0, abs=2e-3)
    assert len(report.face_mesh_to_surface) == 1
    moved = part.positions.copy()
    moved[len(moved) // 2] += 10.0 * result.tolerance * part.corner_normals[
        np.argmax(part.triangles.ravel() == len(moved) // 2)]
    far = io.measure(model, moved, part.triangles, part.face_ids, [1])
    assert far.mesh_to_surface > 5.0 * result.tolerance
    with pytest.raises(ValueError, match="not among the faces measured"):
        io.measure(model, part.positions, part.triangles, part.face_ids, [0])


def test_a_face_the_reader_left_out_is_listed_with_its_reason(tmp_path):
    """Model.unread_faces: the faces missing from every mesh, also among the warnings the
    importer reports."""
    from iges_samples import write_skipped_face_file
    path, bad = write_skipped_face_file(tmp_path / "skipped_face.igs")
    model, _ = io.read_source(str(path))
    [reason] = model.unread_faces
    assert f"D{bad}" in reason and "skipped" in reason
    assert reason in model.warnings
