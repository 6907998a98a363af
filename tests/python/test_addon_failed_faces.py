"""Faces the mesher reports instead of meshing (failed_faces) belong to their parts in
addon/trimkit/io.py: a failed face has no triangles, so a part names the CAD faces it
holds (MeshPart.faces) for the add-on to record the failure on every object of its body."""
import pathlib
import sys

import numpy as np
import pytest

from iges_samples import STRAY_HOLE_AREA, write_stray_hole_plate

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "addon"))
from trimkit import io  # noqa: E402  (the package's __init__ imports no bpy)


def test_failed_face_of_an_instanced_body_belongs_to_the_body_part(tmp_path):
    path = write_stray_hole_plate(tmp_path / "stray_subfigure.igs", instances=((0, 0, 0), (200, 0, 0)))
    model, _ = io.read_source(path)
    assert len(model.instances) == 2 and [list(b.faces) for b in model.bodies] == [[0, 1]]
    result = io.tessellate(model, 0.05)
    assert [f for f, _ in result.failed_faces] == [0]
    [part] = result.parts
    assert (part.kind, part.index, part.faces) == ("BODY", 0, [0, 1])
    assert set(np.unique(part.face_ids).tolist()) == {1}  # face 0 has no triangles


def test_failed_face_has_its_own_empty_part_when_split_by_face(tmp_path):
    model, _ = io.read_source(write_stray_hole_plate(tmp_path / "stray_hole.igs"))
    result = io.tessellate(model, 0.05, split="FACE")
    assert [(p.faces, len(p.triangles) > 0) for p in result.parts] == [([0], False), ([1], True)]
    [(face, reason)] = result.failed_faces
    # the disc of radius 20 alone (its chords within T / 2) against it and the stray hole's 10
    assert face == 0 and reason.startswith("face 0: mesh area 0.799")
    assert "x the exact trimmed area (125" in reason and " vs 1571, allowed" in reason
    native = io.native().tessellate_model(model, io.native().TessellationOptions(tolerance=0.05))
    [failed] = native.failed_faces
    assert failed.defect == "area" and failed.area_exact == pytest.approx(STRAY_HOLE_AREA, rel=1e-3)
    assert failed.area_mesh == pytest.approx(400.0 * np.pi, rel=1e-2)  # the disc alone
    # verified at the tolerance faces are meshed to, 0.9 T
    assert np.isfinite(failed.boundary_gap) and failed.boundary_bound > 0.9 * 0.05
