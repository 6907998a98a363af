"""_trimkit.compress_model / extend_model / tkz bytes ([Muraki], issue 11)."""
import pytest

import _trimkit

from conftest import CAD


def test_bracket_round_trip_through_tkz_bytes(bracket):
    model = _trimkit.read_model(bracket)
    compressed, report = _trimkit.compress_model(model)
    assert len(report) == 2
    # The plate's hole would need a 64-point cubic edge: larger than its surface, kept.
    assert all(not r.compressed for r in report) or compressed.compressed_faces
    data = _trimkit.tkz_bytes(compressed)
    assert data[:4] == b"TKZ1"
    back = _trimkit.read_tkz_bytes(data, "bracket.tkz")
    assert _trimkit.tkz_bytes(back) == data
    extended = _trimkit.extend_model(back)
    assert len(extended.faces) == 2
    assert max(d.max for d in _trimkit.model_deviation(model, extended)) <= max(r.tolerance for r in report)


def test_hammer_compresses_most_faces_within_their_tolerance():
    path = CAD / "iges" / "hammer.iges"
    if not path.exists():
        pytest.skip(f"{path} not found (../shared/data/cad)")
    model = _trimkit.read_model(str(path))
    options = _trimkit.CompressOptions()
    compressed, report = _trimkit.compress_model(model, options)
    done = [f for f, r in enumerate(report) if r.compressed]
    assert done == compressed.compressed_faces
    assert len(done) >= 30
    extended = _trimkit.extend_model(compressed)
    deviation = _trimkit.model_deviation(model, extended)
    for f in done:
        assert deviation[f].max <= report[f].tolerance, f


def test_bad_tkz_bytes_raise_read_error():
    with pytest.raises(RuntimeError, match="bad.tkz: not a .tkz file"):
        _trimkit.read_tkz_bytes(b"IGES1234", "bad.tkz")


def test_addon_reads_tkz_bytes_as_a_model(tmp_path):
    """The add-on's bpy-free io: .tkz bytes (by their TKZ1 magic) become the extended model,
    so imports and re-meshes from a stored .tkz work like a stored IGES file."""
    import pathlib
    import sys
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "addon"))
    from trimkit import io  # noqa: E402  (the package's __init__ imports no bpy)

    path = CAD / "iges" / "BIGES.igs"
    if not path.exists():
        pytest.skip(f"{path} not found (../shared/data/cad)")
    compressed, report = _trimkit.compress_model(_trimkit.read_model(str(path)))
    data = _trimkit.tkz_bytes(compressed)
    assert io.file_format(data, "model.bin") == "tkz"
    model = io.read_bytes(data, "BIGES.tkz")
    assert len(model.faces) == len(report)
    result = io.tessellate(model, 0.05, scale=1e-3, split="FACE", uv_mode="FACE")
    assert result.faces == len(report) and not result.failed_faces
    # File > Export's half: the same bytes as compress_model + tkz_bytes.
    packed, done, faces = io.compress_to_tkz(_trimkit.read_model(str(path)))
    assert packed == bytes(data) and done == len(compressed.compressed_faces) and faces == len(report)


@pytest.mark.parametrize("name", ["step/as1-oc-214-mat.stp", "iges/OCC8842_cylinder_CATIA.igs", "brep/bottle.brep"])
def test_lossless_tkz_stores_the_model_smaller_and_meshes_the_same(name):
    """What the add-on stores in a .blend (stored_source): the model as a .tkz with every
    surface kept reads back as the same model (warnings, instances and their assembly
    paths too) and meshes to the same triangles at the same points."""
    import pathlib
    import sys
    import zlib
    import numpy as np
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "addon"))
    from trimkit import io  # noqa: E402

    path = CAD / name
    if not path.exists():
        pytest.skip(f"{path} not found (../shared/data/cad)")
    model = io.read_source(path)[0]
    data = io.lossless_tkz(model)
    back = io.read_bytes(data, path.name)
    assert [len(f.warnings) for f in back.faces] == [len(f.warnings) for f in model.faces]
    assert [i.path for i in back.instances] == [i.path for i in model.instances]
    options = _trimkit.TessellationOptions()
    options.tolerance = 0.5 if name.endswith(".stp") else 1.0
    options.threads = 1
    a, b = _trimkit.tessellate_model(model, options).mesh, _trimkit.tessellate_model(back, options).mesh
    assert np.array_equal(np.asarray(a.triangles), np.asarray(b.triangles))
    assert np.array_equal(np.asarray(a.positions), np.asarray(b.positions))
    if not name.endswith(".igs"):  # a 4-face IGES part is smaller as text
        assert len(zlib.compress(data, 9)) < 0.6 * len(zlib.compress(path.read_bytes(), 9))


def test_g1_normals_are_the_samples_of_the_reported_g1_angle():
    """_trimkit.g1_normals (bench/g1_normals.py, [Muraki] Fig. 15) gives the check's own
    samples: 50 per G1 edge, unit normals, and their largest angle is the report's g1_angle."""
    import numpy as np
    path = CAD / "brep" / "bottle.brep"
    if not path.exists():
        pytest.skip(f"{path} not found (../shared/data/cad)")
    compressed, report = _trimkit.compress_model(_trimkit.read_model(str(path)))
    extended = _trimkit.extend_model(compressed)
    checked = 0
    for f, r in enumerate(report):
        points, normals, neighbours, angles = _trimkit.g1_normals(compressed, extended, f)
        if not (r.compressed and r.g1_edges):
            assert len(angles) == 0
            continue
        assert len(angles) == 50 * r.g1_edges
        assert np.allclose(np.linalg.norm(np.asarray(normals), axis=1), 1.0)
        assert np.allclose(np.linalg.norm(np.asarray(neighbours), axis=1), 1.0)
        cosines = np.abs(np.sum(np.asarray(normals) * np.asarray(neighbours), axis=1))
        assert np.allclose(np.degrees(np.arccos(np.minimum(1.0, cosines))), angles, atol=1e-9)
        assert max(angles) == pytest.approx(r.g1_angle, abs=1e-12) and max(angles) <= 0.5
        checked += 1
    assert checked >= 20
    with pytest.raises(IndexError):
        _trimkit.g1_normals(compressed, extended, len(report))
