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
