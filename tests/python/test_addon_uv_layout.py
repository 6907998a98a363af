"""addon/trimkit/uv_layout.py and io.file_format: real-world UVs measured on the exact
surface, packed without overlap; what a file is from its first bytes."""
import math
import pathlib
import sys

import numpy as np
import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "addon"))
from trimkit import io, uv_layout  # noqa: E402


def island_boxes(part):
    boxes = {}
    for f in np.unique(part.face_ids):
        corners = part.corner_uvs.reshape(-1, 3, 2)[part.face_ids == f].reshape(-1, 2)
        boxes[int(f)] = (corners.min(axis=0), corners.max(axis=0))
    return boxes


def test_bracket_islands_have_the_faces_sizes_in_metres_and_do_not_overlap(bracket):
    model, _ = io.read_source(bracket)
    part = io.tessellate(model, 0.01, scale=1e-3, split="MODEL").parts[0]
    boxes = island_boxes(part)
    # samples/make_samples.py: the plate is 100 x 60 mm; the quarter cylinder of radius
    # 20 mm is 40 mm tall, its arc pi/2 * 20 mm (the UV of a chord's end lies on the arc).
    plate = sorted(boxes[0][1] - boxes[0][0])
    wall = sorted(boxes[1][1] - boxes[1][0])
    assert plate == pytest.approx([0.06, 0.1], abs=1e-8)  # float32 uvs
    assert wall == pytest.approx(sorted([0.04, math.pi / 2 * 0.02]), rel=1e-4)  # mean speed by centroids
    (lo0, hi0), (lo1, hi1) = boxes[0], boxes[1]
    assert np.any(hi0 < lo1) or np.any(hi1 < lo0), "island boxes overlap"
    assert part.corner_uvs.min() >= 0.0


def test_islands_keep_the_winding_of_their_triangles(bracket):
    model, _ = io.read_source(bracket)
    part = io.tessellate(model, 0.01, scale=1e-3, split="MODEL").parts[0]
    uv = part.corner_uvs.reshape(-1, 3, 2).astype(np.float64)
    a, b = uv[:, 1] - uv[:, 0], uv[:, 2] - uv[:, 0]
    assert np.all(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0] >= 0.0)  # none mirrored


def test_a_layout_handed_back_maps_each_parameter_point_to_the_same_uv(bracket):
    model, _ = io.read_source(bracket)
    coarse = io.tessellate(model, 0.5, scale=1e-3, split="MODEL").parts[0]
    fine = io.tessellate(model, 0.01, scale=1e-3, split="MODEL",
                         uv_layouts={("MODEL", -1): coarse.uv_layout}).parts[0]
    assert len(fine.triangles) > 2 * len(coarse.triangles)
    # On the plate UV = position (metres) + a constant offset: same offset at both levels.
    for part in (coarse, fine):
        corners = part.corner_uvs.reshape(-1, 3, 2)[part.face_ids == 0].reshape(-1, 2)
        xyz = part.positions[part.triangles[part.face_ids == 0].ravel()][:, :2]
        offset = corners - xyz
        assert np.ptp(offset, axis=0) == pytest.approx([0.0, 0.0], abs=1e-7)
        if part is coarse:
            first = offset[0]
    assert offset[0] == pytest.approx(first, abs=1e-7)


def test_per_face_mode_stretches_each_face_to_0_1(bracket):
    model, _ = io.read_source(bracket)
    part = io.tessellate(model, 0.01, scale=1e-3, split="MODEL", uv_mode=uv_layout.FACE).parts[0]
    for lo, hi in island_boxes(part).values():
        assert lo == pytest.approx([0, 0], abs=1e-6) and hi == pytest.approx([1, 1], abs=1e-6)


@pytest.mark.parametrize("data, name, kind", [
    (b"ISO-10303-21;\nHEADER;", "x.igs", "step"),
    (b"DBRep_DrawableShape\n\nCASCADE Topology V1", "x.igs", "brep"),
    (b"solid part\n facet normal 0 0 1\n", "x.igs", "stl"),
    (bytes(80) + (1).to_bytes(4, "little") + bytes(50), "x.stl", "stl"),
    (b"# exported\nv 0 0 0\n", "x.igs", "obj"),
    (b"glTF\x02\x00\x00\x00", "x.igs", "gltf"),
    (b"", "x.igs", "empty"),
    (b"garbage", "x.igs", "iges"),  # the IGES reader says what is wrong with it
    (b"garbage", "x.sat", "sat"),
])
def test_file_format_from_the_first_bytes(data, name, kind):
    assert io.file_format(data, name) == kind


def test_bracket_is_iges_by_its_columns(bracket):
    assert io.file_format(pathlib.Path(bracket).read_bytes(), "renamed.dat") == "iges"


def test_a_mesh_file_is_refused_naming_what_it_is():
    with pytest.raises(ValueError, match=r"part.stl: an STL mesh, not a CAD file .* File > Import > STL"):
        io.read_bytes(b"solid part\n facet normal 0 0 1\n", "part.stl")
