"""IGES files the tests write themselves (samples/make_samples.py's writer): faces the
mesher cannot mesh correctly, for the failed-face paths of the command line, io and
the add-on. Importable from pytest (tests/python is on the path) and from Blender."""
import importlib.util
import math
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[2]
# The stray-hole plate's exact trimmed area by the even-odd rule over its own loops:
# the disc of radius 20 plus the stray disc of radius 10.
STRAY_HOLE_AREA = 500.0 * math.pi


def iges_writer():
    spec = importlib.util.spec_from_file_location("make_samples", ROOT / "samples" / "make_samples.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def write_stray_hole_plate(path, instances=()):
    """Face 0: a plate S = (u, v, 0) over [0, 100] x [0, 60] trimmed (144) to the disc
    of radius 20 at (30, 30), with a "hole" of radius 10 at (75, 30) outside that disc:
    the face's own loops bound both discs (STRAY_HOLE_AREA), which no mesh inside the
    outer loop covers, so trimkit reports the face instead of meshing it. Face 1: the
    bracket's quarter cylinder, which meshes. With `instances` (translations), both
    faces form a 308 subfigure placed by one 408 each: one body, several objects."""
    m = iges_writer()
    w = m.IgesWriter()
    plate = [1, 1, 1, 1, 0, 0, 1, 0, 0, 0, 0, 100, 100, 0, 0, 60, 60, 1.0, 1.0, 1.0, 1.0,
             0.0, 0.0, 0.0, 100.0, 0.0, 0.0, 0.0, 60.0, 0.0, 100.0, 60.0, 0.0,
             0.0, 100.0, 0.0, 60.0]
    surf = w.add(128, plate, status="00010000")
    loops = []
    for cx, radius, clockwise in ((30.0, 20.0, False), (75.0, 10.0, True)):
        pts, wts, knots = m.circle_nurbs(cx, 30.0, radius)
        if clockwise:
            pts, wts = pts[::-1], wts[::-1]
        pcurve = w.add(126, m.curve126(pts, wts, knots, 2), status="00010500")
        mcurve = w.add(126, m.curve126(pts, wts, knots, 2), status="00010000")
        loops.append(w.add(142, [1, surf, pcurve, mcurve, 1], status="00010000"))
    faces = [w.add(144, [surf, 1, 1, loops[0], loops[1]])]
    s = math.sqrt(0.5)
    cyl = [2, 1, 2, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 40, 40, 1.0, s, 1.0, 1.0, s, 1.0]
    for z in (0.0, 40.0):
        for x, y in ((120.0, 60.0), (120.0, 80.0), (100.0, 80.0)):
            cyl += [x, y, z]
    cyl += [0.0, 1.0, 0.0, 40.0]
    faces.append(w.add(128, cyl))
    if instances:
        definition = w.add(308, [0, "PLATE", len(faces), *faces], status="00000200")
        for x, y, z in instances:
            w.add(408, [definition, float(x), float(y), float(z), 1.0])
    path = pathlib.Path(path)
    path.write_text(w.text(path.name))
    return str(path)


def write_skipped_face_file(path):
    """A plane (128, read as a face) and a 144 face whose surface pointer names a curve:
    the reader skips the 144 with a warning naming it. Returns (path, the 144's DE)."""
    m = iges_writer()
    w = m.IgesWriter()
    pts, wts, knots = m.circle_nurbs(30.0, 30.0, 20.0)
    curve = w.add(126, m.curve126(pts, wts, knots, 2), status="00010000")
    plane = [1, 1, 1, 1, 0, 0, 1, 0, 0, 0, 0, 100, 100, 0, 0, 60, 60, 1.0, 1.0, 1.0, 1.0,
             0.0, 0.0, 0.0, 100.0, 0.0, 0.0, 0.0, 60.0, 0.0, 100.0, 60.0, 0.0, 0.0, 100.0, 0.0, 60.0]
    w.add(128, plane)
    loop = w.add(142, [1, curve, curve, curve, 1], status="00010000")
    bad = w.add(144, [curve, 1, 0, loop])
    path = pathlib.Path(path)
    path.write_text(w.text(path.name))
    return str(path), bad


def write_bracket_assembly(path, instances):
    """samples/bracket.igs's two faces (the plate with a hole, the quarter cylinder) as one
    308 subfigure, placed by a 408 per (x, y, z, scale) in `instances`: one body, a
    Model.Instance each."""
    m = iges_writer()
    w = m.IgesWriter()
    plate = [1, 1, 1, 1, 0, 0, 1, 0, 0, 0, 0, 100, 100, 0, 0, 60, 60, 1.0, 1.0, 1.0, 1.0,
             0.0, 0.0, 0.0, 100.0, 0.0, 0.0, 0.0, 60.0, 0.0, 100.0, 60.0, 0.0,
             0.0, 100.0, 0.0, 60.0]
    surf = w.add(128, plate, status="00010000")
    pts, wts, knots = m.circle_nurbs(30.0, 30.0, 10.0)
    pts, wts = pts[::-1], wts[::-1]  # a hole: clockwise in (u, v)
    pcurve = w.add(126, m.curve126(pts, wts, knots, 2), status="00010500")
    mcurve = w.add(126, m.curve126(pts, wts, knots, 2), status="00010000")
    loop = w.add(142, [1, surf, pcurve, mcurve, 1], status="00010000")
    faces = [w.add(144, [surf, 0, 1, 0, loop], status="00010000")]
    s = math.sqrt(0.5)
    cyl = [2, 1, 2, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 40, 40, 1.0, s, 1.0, 1.0, s, 1.0]
    for z in (0.0, 40.0):
        for x, y in ((120.0, 60.0), (120.0, 80.0), (100.0, 80.0)):
            cyl += [x, y, z]
    cyl += [0.0, 1.0, 0.0, 40.0]
    faces.append(w.add(128, cyl, status="00010000"))
    definition = w.add(308, [0, "BRACKET", len(faces), *faces], status="00000200")
    for x, y, z, scale in instances:
        w.add(408, [definition, float(x), float(y), float(z), float(scale)])
    path = pathlib.Path(path)
    path.write_text(w.text(path.name))
    return str(path)
