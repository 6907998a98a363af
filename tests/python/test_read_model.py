"""_trimkit.read_model and summarize against the built-in sample and real files."""
import json
import math

import numpy as np
import pytest

import _trimkit


def test_bracket_has_plate_with_hole_and_quarter_cylinder(bracket):
    model = _trimkit.read_model(bracket)
    assert model.units == "mm"
    assert model.scale_to_metres == pytest.approx(1e-3)
    assert len(model.faces) == 2
    loops = sorted(len(f.loops) for f in model.faces)
    assert loops == [1, 2]  # cylinder: natural boundary; plate: outer + hole
    summary = _trimkit.summarize(model, bracket)
    assert summary.faces == 2 and summary.loops == 3


def test_surface_evaluation_matches_closed_form(bracket):
    model = _trimkit.read_model(bracket)
    cylinder = next(f.surface for f in model.faces if f.surface.is_rational)
    u0, u1 = cylinder.domain_u
    v0, v1 = cylinder.domain_v
    uv = np.array([[u0 + (u1 - u0) * a, v0 + (v1 - v0) * b]
                   for a in np.linspace(0, 1, 7) for b in np.linspace(0, 1, 5)])
    points = cylinder.evaluate(uv)
    assert points.shape == (35, 3) and points.dtype == np.float64
    radius = np.hypot(points[:, 0] - 100.0, points[:, 1] - 60.0)
    np.testing.assert_allclose(radius, 20.0, atol=1e-10)
    assert points[:, 2].min() == pytest.approx(0.0) and points[:, 2].max() == pytest.approx(40.0)


def test_evaluate_rejects_wrong_shape(bracket):
    surface = _trimkit.read_model(bracket).faces[0].surface
    with pytest.raises(ValueError, match=r"shape \(n, 2\)"):
        surface.evaluate(np.zeros((4, 3)))


def test_json_summary_has_documented_keys(bracket):
    summary = json.loads(_trimkit.to_json(_trimkit.summarize(_trimkit.read_model(bracket), bracket)))
    for key in ("units", "scale_to_metres", "faces", "surfaces", "loops", "coedges",
                "shared_edges", "bodies", "warnings"):
        assert key in summary
    assert sum(summary["surfaces"].values()) == summary["faces"] == 2


def test_not_iges_raises_read_error_naming_the_file(tmp_path):
    bogus = tmp_path / "notes.igs"
    bogus.write_text("this is not an IGES file\n")
    with pytest.raises(_trimkit.ReadError, match="notes.igs"):
        _trimkit.read_model(str(bogus))
    assert issubclass(_trimkit.ReadError, RuntimeError)


def test_bearing_faces_evaluate_finite(cad_sample):
    model = _trimkit.read_model(cad_sample("iges/bearing.iges"))
    assert len(model.faces) == 213
    for face in model.faces[::10]:
        s = face.surface
        (u0, u1), (v0, v1) = s.domain_u, s.domain_v
        g = np.linspace(0.0, 1.0, 4)
        uv = np.array([[u0 + (u1 - u0) * a, v0 + (v1 - v0) * b] for a in g for b in g])
        assert np.isfinite(s.evaluate(uv)).all()


def test_read_step_exists_only_with_step_support(cad_sample):
    # The add-on shows its STEP operator when read_step exists (built with Open CASCADE).
    assert hasattr(_trimkit, "read_step") == _trimkit.step_supported()
    if not _trimkit.step_supported():
        pytest.skip("trimkit built without Open CASCADE")
    path = cad_sample("step/screw.step")
    for model in (_trimkit.read_step(path), _trimkit.read_model(path)):
        summary = _trimkit.summarize(model, path)
        assert summary.faces == 10 and summary.units == "mm"
        assert summary.bodies == 1
