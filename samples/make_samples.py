#!/usr/bin/env python3
"""Writes the built-in IGES samples in samples/ (run by hand; outputs are committed).

bracket.igs: a 100 x 60 mm plate (entity 128, bilinear) trimmed (144) with the
plate's natural boundary outside and a circular hole of radius 10 at (30, 30)
(142 with a rational quadratic 126 circle in parameter space, and the same circle
in model space), plus a quarter-cylinder wall of radius 20 (128, rational) as an
untrimmed face. Units mm.
"""
import math
import os


def fmt(x):
    if isinstance(x, str):
        return f"{len(x)}H{x}"
    if isinstance(x, int):
        return str(x)
    return repr(float(x)).replace("e", "E")


class IgesWriter:
    def __init__(self):
        self.entities = []  # (type, form, params, status)

    def add(self, etype, params, form=0, status="00000000"):
        self.entities.append((etype, form, params, status))
        return 2 * len(self.entities) - 1  # DE pointer

    def text(self, name):
        start = ["trimkit built-in sample: plate with a hole and a quarter cylinder"]
        glob = [",", ";", name, name, "trimkit", "trimkit 0.1", 32, 38, 6, 308, 15,
                name, 1.0, 2, "MM", 1, 0.1, "20261122.120000", 1e-6, 100.0,
                "trimkit", "trimkit", 11, 0, "20261122.120000"]
        lines = []
        for i, s in enumerate(start):
            lines.append(f"{s:<72}S{i + 1:7d}")
        gtext = ",".join(fmt(g) for g in glob) + ";"
        for i in range(0, len(gtext), 72):
            lines.append(f"{gtext[i:i + 72]:<72}G{i // 72 + 1:7d}")
        dlines, plines = [], []
        for k, (etype, form, params, status) in enumerate(self.entities):
            de = 2 * k + 1
            ptext = ",".join([str(etype)] + [fmt(p) for p in params]) + ";"
            chunks = []
            rest = ptext
            while rest:
                cut = len(rest) if len(rest) <= 64 else rest.rfind(",", 0, 64) + 1
                chunks.append(rest[:cut])
                rest = rest[cut:]
            first = len(plines) + 1
            for c in chunks:
                plines.append(f"{c:<64}{de:8d}P{len(plines) + 1:7d}")
            d1 = [etype, first, 0, 0, 0, 0, 0, 0]
            d2 = [etype, 0, 0, len(chunks), form, "", "", "", 0]
            dlines.append("".join(f"{v:>8}" for v in d1) + f"{status:>8}D{de:7d}")
            dlines.append("".join(f"{v:>8}" for v in d2) + f"D{de + 1:7d}")
        lines += dlines + plines
        ns = len(start)
        ng = (len(gtext) + 71) // 72
        lines.append(f"S{ns:7d}G{ng:7d}D{len(dlines):7d}P{len(plines):7d}".ljust(72) + "T      1")
        return "\n".join(lines) + "\n"


def circle_nurbs(cx, cy, r, z=0.0):
    """Full circle as 9 control points, degree 2, weights 1, s, 1, ... (counter-clockwise)."""
    s = math.sqrt(0.5)
    pts = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    w = [1, s, 1, s, 1, s, 1, s, 1]
    knots = [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]
    return [(cx + r * x, cy + r * y, z) for x, y in pts], w, knots


def curve126(points, weights, knots, degree, planar=1):
    """Entity 126 parameters: K, M, PROP1 planar, PROP2 closed, PROP3 polynomial, PROP4 periodic."""
    n = len(points) - 1
    polynomial = 1 if all(abs(w - 1) < 1e-15 for w in weights) else 0
    closed = 1 if points[0] == points[-1] else 0
    params = [n, degree, planar, closed, polynomial, 0] + list(knots) + list(weights)
    for p in points:
        params += list(p)
    params += [knots[degree], knots[n + 1], 0.0, 0.0, 1.0]
    return params


def bracket():
    w = IgesWriter()
    # Plate: bilinear 128 over (u, v) in [0, 100] x [0, 60], S = (u, v, 0).
    plate = [1, 1, 1, 1, 0, 0, 1, 0, 0, 0, 0, 100, 100, 0, 0, 60, 60, 1.0, 1.0, 1.0, 1.0,
             0.0, 0.0, 0.0, 100.0, 0.0, 0.0, 0.0, 60.0, 0.0, 100.0, 60.0, 0.0,
             0.0, 100.0, 0.0, 60.0]
    surf = w.add(128, plate, status="00010000")
    # Hole: clockwise in parameter space (a hole of a face with a normal along +z).
    pts, wts, knots = circle_nurbs(30.0, 30.0, 10.0)
    pts = pts[::-1]
    wts = wts[::-1]
    pcurve = w.add(126, curve126(pts, wts, knots, 2), status="00010500")
    mcurve = w.add(126, curve126(pts, wts, knots, 2), status="00010000")
    loop = w.add(142, [1, surf, pcurve, mcurve, 1], status="00010000")
    w.add(144, [surf, 0, 1, 0, loop])
    # Quarter cylinder radius 20 about the z axis at (100, 60), angle 0..90 deg, z 0..40.
    s = math.sqrt(0.5)
    cx, cy = 100.0, 60.0
    arc = [(cx + 20, cy), (cx + 20, cy + 20), (cx, cy + 20)]
    # K1 K2 M1 M2, PROP1-5 (not closed, rational, not periodic), knots, weights,
    # then points with the u index fastest.
    cyl = [2, 1, 2, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 40, 40]
    cyl += [1.0, s, 1.0, 1.0, s, 1.0]
    for z in (0.0, 40.0):
        for x, y in arc:
            cyl += [x, y, z]
    cyl += [0.0, 1.0, 0.0, 40.0]
    w.add(128, cyl)
    return w.text("bracket.igs")


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "bracket.igs"), "w") as f:
        f.write(bracket())
