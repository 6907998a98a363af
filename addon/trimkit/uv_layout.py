"""UV maps of CAD faces, without bpy: one island per CAD face, either at real-world
scale (1 UV unit = 1 metre of surface, measured on the exact surface) and packed
without overlap, or each face's (u, v) parameters stretched to 0-1 (islands overlap).

Real-world scale: each face's parameters (u, v) are mapped by a 2x2 matrix M, the
area-weighted mean over its triangles of sqrt(G), G the first fundamental form
[[Su.Su, Su.Sv], [Su.Sv, Sv.Sv]] (Su, Sv from the exact surface by finite
differences), times metres per model unit; a parameter step du then has UV length
sqrt(du^T G du) where G is constant (planes), the arc length along a direction whose
speed alone varies (a rational circle's), to first order elsewhere. Islands are mirrored where needed so that every
island keeps the triangles' winding (no flipped islands for normal maps), and packed
by their boxes in shelves (tallest first) with a margin.

A layout ({face: 8 floats: M row-major, offset, box size}) can be handed back so
that a re-mesh or a level of detail puts each face's UVs where they were.
"""
import numpy as np

REAL = "REAL"  # real-world scale, packed
FACE = "FACE"  # each face 0-1
# Triangles per face used to average the metric: plenty for a mean, bounded cost.
METRIC_SAMPLES = 400
# Finite-difference step, as a share of the face's parameter box.
DIFFERENCE_STEP = 1e-5
# Gap between packed islands, as a share of the packed layout's side.
MARGIN_SHARE = 0.01


def normalize_uvs(uvs, face_ids):
    """(3m, 2) corner uvs scaled to [0, 1] within each CAD face (one UV island per face)."""
    corner_faces = np.repeat(face_ids, 3)
    count = int(face_ids.max()) + 1 if len(face_ids) else 0
    lo = np.full((count, 2), np.inf)
    hi = np.full((count, 2), -np.inf)
    np.minimum.at(lo, corner_faces, uvs)
    np.maximum.at(hi, corner_faces, uvs)
    size = hi - lo
    size[~(size > 0.0)] = 1.0
    return ((uvs - lo[corner_faces]) / size[corner_faces]).astype(np.float32)


def real_world_uvs(model, uvs, face_ids, metres, layout=None):
    """(3m, 2) float32 corner uvs at 1 UV unit per metre, islands packed, and the layout
    used. `uvs`: (3m, 2) surface parameters of each corner in its face; `metres`: metres
    per model unit; `layout`: a previous layout whose faces keep their mapping (a
    parameter point gets the same UV), the others are packed above them."""
    layout = dict(layout or {})
    uvs = np.asarray(uvs, np.float64).reshape(-1, 2)
    out = np.zeros_like(uvs)
    order = np.argsort(face_ids, kind="stable")
    faces, starts = np.unique(face_ids[order], return_index=True)
    groups = np.split(order, starts[1:]) if len(order) else []
    new = {}
    for face, tris in zip(faces.tolist(), groups):
        corners = (3 * tris[:, None] + np.arange(3)).ravel()
        if face in layout:
            entry = layout[face]
            out[corners] = uvs[corners] @ np.reshape(entry[:4], (2, 2)).T + np.asarray(entry[4:6])
            continue
        matrix = face_matrix(model.faces[face].surface, uvs[corners].reshape(-1, 3, 2)) * metres
        new[face] = (corners, matrix, uvs[corners] @ matrix.T)
    place(layout, new)
    for face, (corners, _, points) in new.items():
        out[corners] = points + np.asarray(layout[face][4:6])
    return out.astype(np.float32), layout


def face_matrix(surface, triangles):
    """2x2 M: the mean of sqrt(G) of `surface` over the (k, 3, 2) parameter triangles
    (weighted by their parameter area), mirrored if the triangles would wind clockwise."""
    step = max(len(triangles) // METRIC_SAMPLES, 1)
    sample = triangles[::step]
    centroids = sample.mean(axis=1)
    u_end, v_end = surface.domain_u[1], surface.domain_v[1]
    box = np.ptp(triangles.reshape(-1, 2), axis=0)
    h = DIFFERENCE_STEP * np.where(box > 0.0, box, 1.0)
    du = np.where(centroids[:, 0] + h[0] <= u_end, h[0], -h[0])
    dv = np.where(centroids[:, 1] + h[1] <= v_end, h[1], -h[1])
    points = surface.evaluate(np.concatenate([centroids, centroids + np.stack([du, 0 * du], 1),
                                              centroids + np.stack([0 * dv, dv], 1)]))
    p0, pu, pv = np.split(points, 3)
    su, sv = (pu - p0) / du[:, None], (pv - p0) / dv[:, None]
    e, f, g = np.sum(su * su, 1), np.sum(su * sv, 1), np.sum(sv * sv, 1)
    edge1, edge2 = sample[:, 1] - sample[:, 0], sample[:, 2] - sample[:, 0]
    weights = np.abs(edge1[:, 0] * edge2[:, 1] - edge1[:, 1] * edge2[:, 0])  # parameter area: a mean over (u, v)
    if not weights.sum() > 0.0:
        weights = np.ones(len(sample))
    # Mean of each sample's sqrt(G) (closed form for 2x2 SPD: (G + sqrt(det) I) / sqrt(tr + 2 sqrt(det))):
    # along a line of constant metric direction its scale is the mean speed, so a parameter
    # range maps to its arc length (a rational circle's speed varies; sqrt of the mean G would overshoot).
    root_det = np.sqrt(np.maximum(e * g - f * f, 0.0))
    norm = np.sqrt(np.maximum(e + g + 2.0 * root_det, 0.0))
    ok = norm > 0.0
    if not ok.any():
        return np.eye(2)
    w = weights[ok]
    roots = np.stack([(e + root_det)[ok], f[ok], f[ok], (g + root_det)[ok]], 1) / norm[ok, None]
    matrix = np.average(roots, axis=0, weights=w if w.sum() > 0.0 else None).reshape(2, 2)
    if not (np.all(np.isfinite(matrix)) and np.linalg.det(matrix) > 0.0):
        matrix = np.eye(2) * max(float(np.sqrt(np.average(e + g, weights=w if w.sum() > 0.0 else None) / 2)), 1e-300)
    mapped = triangles @ matrix.T
    a, b = mapped[:, 1] - mapped[:, 0], mapped[:, 2] - mapped[:, 0]
    if np.sum(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]) < 0.0:
        matrix = np.diag([-1.0, 1.0]) @ matrix
    return matrix


def place(layout, islands):
    """Adds islands ({face: (corners, matrix, (k, 2) points)}) to `layout` as entries
    [M row-major (4), offset (2), box low (2), box high (2)], in shelves (tallest
    first) above the boxes it holds, with a margin between boxes."""
    if not islands:
        return
    lows = {f: p.min(axis=0) for f, (_, _, p) in islands.items()}
    sizes = {f: np.ptp(p, axis=0) for f, (_, _, p) in islands.items()}
    old = [(np.asarray(v[6:8]), np.asarray(v[8:10])) for v in layout.values()]
    area = sum(float(s[0] * s[1]) for s in sizes.values()) + sum(float(np.prod(h - l)) for l, h in old)
    widest = max(float(s[0]) for s in sizes.values())
    side = max(np.sqrt(area), widest, 1e-12)
    margin = MARGIN_SHARE * side
    y = max((float(h[1]) + margin for _, h in old), default=0.0)
    x, row = 0.0, 0.0
    for face in sorted(islands, key=lambda f: (-float(sizes[f][1]), f)):
        size = sizes[face]
        if x > 0.0 and x + size[0] > side:
            x, y, row = 0.0, y + row + margin, 0.0
        corner = np.array([x, y])
        matrix = islands[face][1]
        layout[face] = [*matrix.ravel().tolist(), *(corner - lows[face]).tolist(), *corner.tolist(),
                        *(corner + size).tolist()]
        x += float(size[0]) + margin
        row = max(row, float(size[1]))


def layout_to_json(layout):
    import json
    return json.dumps({str(f): [round(float(x), 12) for x in v] for f, v in layout.items()})


def layout_from_json(text):
    import json
    if not text:
        return None
    return {int(f): v for f, v in json.loads(text).items()}
