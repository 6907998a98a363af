"""TBP solids (triangular Bézier patches, [García et al.]) to numpy arrays ready for
Blender, without bpy (pytest covers it): the TBP half of the add-on's geometry code,
beside io.py's CAD half, whose MeshPart it fills.

A TBP object's geometry is the solid's .tbp text (stored in the .blend like a CAD
file's bytes). Meshes: polygonization at hierarchy level L and lod K, i.e.
(K+1)^L segments per patch edge, one CAD face per patch (face id = patch index),
corner normals and (u, v) from each patch, vertices welded across patches.
"""
import dataclasses
import math
import pathlib
import time

import numpy as np

from .io import EDGE_FACE_BOUNDARY, EDGE_SHARP, MeshPart, material_name, native
from .uv_layout import normalize_uvs

TBP_DEFAULT_ANGLE = np.radians(30.0)
# Meshes of more triangles than this are reported with a warning before they are made.
TBP_WARN_TRIANGLES = 500_000


def tbp_triangle_estimate(patches, levels, lod):
    """Triangles of `patches` patches polygonized at level L = `levels`, lod K = `lod`:
    (K+1)^L segments per patch edge, so (K+1)^(2L) triangles a patch. A trim at that
    resolution keeps the part of them on its side of the tool (and splits the cut ones)."""
    return patches * (lod + 1) ** (2 * levels)


def tbp_estimate_lines(what, patches, levels, lod):
    """(the estimate, a warning or None) for `what` (an object's name) at levels/lod."""
    count = tbp_triangle_estimate(patches, levels, lod)
    line = f"estimate {count} triangles ({patches} patches at levels {levels}, lod {lod})"
    if count <= TBP_WARN_TRIANGLES:
        return line, None
    return line, f"{what}: {count} triangles, above {TBP_WARN_TRIANGLES}: slow and heavy; lower Levels or LOD"


@dataclasses.dataclass
class TbpMeshing:
    part: MeshPart
    patches: int
    triangles: int
    open_edges: int
    seconds: float


@dataclasses.dataclass
class TbpTrim:
    part: MeshPart
    area: float
    triangles: int
    boundary_loops: int
    cut_edges: int           # boundary edges on trimming curves
    untrimmed_subpatches: int
    box_tests: int
    triangle_tests: int
    seconds: float


@dataclasses.dataclass
class TbpIntersection:
    components: list         # [((k, 3) points, closed)]
    junctions: np.ndarray    # (j, 3)
    box_tests: int
    triangle_tests: int
    segments: int
    seconds: float


def tbp_solid(points, degree, name=""):
    """A TbpSolid from a (p, (n+1)(n+2)/2, 3) array of control points; ValueError if malformed."""
    return native().TbpSolid(np.asarray(points, np.float64), degree, name)


def read_tbp_source(path):
    """(solid, .tbp bytes) of a file; RuntimeError 'NAME:LINE: reason' for a bad one."""
    path = pathlib.Path(path)
    data = path.read_bytes()
    return tbp_from_bytes(data, path.name), data


def tbp_from_bytes(data, name):
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as err:
        raise ValueError(f"{name}: not a .tbp file (not UTF-8 text)") from err
    return native().parse_tbp(text, name)


def tbp_bytes(solid):
    return native().tbp_text(solid).encode("utf-8")


def transform_tbp(solid, matrix):
    """The solid with every control point mapped by the 4x4 affine `matrix` (exact for
    Bézier patches). ValueError for a mirroring matrix, which would turn the normals in."""
    matrix = np.asarray(matrix, np.float64).reshape(4, 4)
    if np.linalg.det(matrix[:3, :3]) <= 0.0:
        raise ValueError("the transform mirrors or flattens the solid (negative or zero scale)")
    points = solid.points
    moved = points @ matrix[:3, :3].T + matrix[:3, 3]
    return native().TbpSolid(moved, solid.degree, solid.name)


def weld_tolerance(positions):
    if len(positions) == 0:
        return 0.0
    return native().TBP_WELD_RELATIVE_TOLERANCE * float(np.linalg.norm(positions.max(0) - positions.min(0)))


def tbp_part(mesh, name, scale=1.0, angle=TBP_DEFAULT_ANGLE):
    """MeshPart from a native Mesh whose vertices belong to one patch each (not welded
    across patches): corner normals and uvs from each patch, vertices then welded,
    patch boundaries flagged as face boundaries (UV seams), sharp where the two
    sides' normals differ by more than `angle`."""
    positions, triangles = mesh.positions, mesh.triangles
    weld = native().weld_map(mesh, native().WeldOptions(tolerance=weld_tolerance(positions)))
    vertex_map = weld.vertex_map
    welded = np.zeros((weld.vertex_count, 3))
    welded[vertex_map] = positions
    tris = vertex_map[triangles].astype(np.int32)
    keep = (tris[:, 0] != tris[:, 1]) & (tris[:, 1] != tris[:, 2]) & (tris[:, 2] != tris[:, 0])
    tris, triangles = tris[keep], triangles[keep]  # slivers welding collapses
    corner_normals = mesh.normals[triangles].reshape(-1, 3).astype(np.float32)
    face_ids = mesh.face_ids[keep]
    corner_uvs = normalize_uvs(mesh.uvs[triangles].reshape(-1, 2), face_ids)
    edges, flags = patch_edges(tris, face_ids, corner_normals, angle)
    return MeshPart(name=name, kind="TBP", index=-1, positions=welded * scale, triangles=tris, face_ids=face_ids,
                    corner_uvs=corner_uvs, corner_normals=corner_normals, edges=edges, edge_flags=flags,
                    materials=[material_name(None)], material_index=np.zeros(len(tris), np.int32))


def edge_uses(triangles):
    """Every triangle edge as (keys, a, b, corner_a, corner_b), sorted by key (the unordered pair)."""
    m = len(triangles)
    corner = np.arange(3 * m).reshape(m, 3)
    ca = corner.ravel()
    cb = corner[:, [1, 2, 0]].ravel()
    a = triangles.ravel().astype(np.int64)
    b = triangles[:, [1, 2, 0]].ravel().astype(np.int64)
    n = int(triangles.max()) + 1 if m else 1
    keys = np.minimum(a, b) * n + np.maximum(a, b)
    order = np.argsort(keys, kind="stable")
    return keys[order], a[order], b[order], ca[order], cb[order]


def open_edge_count(triangles):
    """Edges used by exactly one triangle."""
    if len(triangles) == 0:
        return 0
    keys = edge_uses(np.asarray(triangles))[0]
    _, counts = np.unique(keys, return_counts=True)
    return int(np.sum(counts == 1))


def patch_edges(triangles, face_ids, corner_normals, angle):
    """(k, 2) edges between triangles of different patches and their flags."""
    if len(triangles) == 0:
        return np.zeros((0, 2), np.int32), np.zeros(0, np.uint8)
    keys, a, b, ca, cb = edge_uses(triangles)
    pair = np.flatnonzero(keys[:-1] == keys[1:])  # manifold edges: uses i and i+1
    i, j = pair, pair + 1
    tri_i, tri_j = ca[i] // 3, ca[j] // 3
    cross = face_ids[tri_i] != face_ids[tri_j]
    i, j = i[cross], j[cross]
    same = a[i] == a[j]  # j's corner at vertex a[i]
    cj_a = np.where(same, ca[j], cb[j])
    cj_b = np.where(same, cb[j], ca[j])
    cos = np.cos(angle)
    sharp = (np.sum(corner_normals[ca[i]] * corner_normals[cj_a], axis=1) < cos) | \
            (np.sum(corner_normals[cb[i]] * corner_normals[cj_b], axis=1) < cos)
    flags = (EDGE_FACE_BOUNDARY | np.where(sharp, EDGE_SHARP, 0)).astype(np.uint8)
    return np.stack([a[i], b[i]], axis=1).astype(np.int32), flags


def tbp_mesh(solid, levels, lod, scale=1.0, angle=TBP_DEFAULT_ANGLE, name=None):
    """Polygonizes `solid` at level `levels` and lod `lod` into a TbpMeshing; ValueError
    for negative values or a rate (lod+1)^levels above TBP_MAX_POLYGONIZE_RATE."""
    start = time.perf_counter()
    options = native().PolygonizeOptions(level=levels, lod=lod, weld=False)
    mesh = native().polygonize(solid, options)
    part = tbp_part(mesh, name or solid.name or "TBP", scale, angle)
    return TbpMeshing(part=part, patches=len(solid), triangles=len(part.triangles),
                      open_edges=open_edge_count(part.triangles), seconds=time.perf_counter() - start)


def tbp_classify(solid, points, levels=2, lod=3):
    """(n,) int8 codes native().TBP_OUTSIDE / TBP_INSIDE / TBP_BOUNDARY of (n, 3) points."""
    hierarchies = native().build_hierarchies(solid, levels, lod)
    return native().point_in_solid(hierarchies, np.asarray(points, np.float64).reshape(-1, 3))


def tbp_intersect(a, b, levels=2, lod=3, use_hierarchy=True):
    """Intersection curves of two solids as a TbpIntersection."""
    start = time.perf_counter()
    ha = native().build_hierarchies(a, levels, lod)
    hb = native().build_hierarchies(b, levels, lod)
    result = native().intersect_solids(ha, hb, use_hierarchy)
    return TbpIntersection(components=[(c.points, c.closed) for c in result.components],
                           junctions=result.junctions, box_tests=result.stats.box_tests,
                           triangle_tests=result.stats.triangle_tests, segments=result.stats.segments,
                           seconds=time.perf_counter() - start)


def tbp_trim(target, tool, keep="outside", levels=2, lod=3, scale=1.0, angle=TBP_DEFAULT_ANGLE, name=None):
    """Every patch of `target` trimmed against the closed solid `tool` (both in the same
    coordinates), keeping the part "outside" or "inside" it, as a TbpTrim. The part's
    triangles are on the exact patches, at the target hierarchy's leaf resolution."""
    start = time.perf_counter()
    options = native().TrimOptions(levels=levels, lod=lod, keep=keep)
    _, results = native().trim_solid(target, tool, options)
    meshes = [r.mesh for r in results if r.mesh.triangle_count]
    if meshes:
        merged = merge_meshes(meshes)
        part = tbp_part(merged, name or (target.name or "TBP") + " trimmed", scale, angle)
        area = native().surface_area(merged)
    else:
        part = empty_part(name or "TBP trimmed")
        area = 0.0
    return TbpTrim(part=part, area=float(area) * scale * scale, triangles=len(part.triangles),
                   boundary_loops=sum(len(r.boundaries) for r in results),
                   cut_edges=sum(r.stats.boundary_segments for r in results),
                   untrimmed_subpatches=sum(len(r.untrimmed) for r in results),
                   box_tests=sum(r.stats.intersection.box_tests for r in results),
                   triangle_tests=sum(r.stats.intersection.triangle_tests for r in results),
                   seconds=time.perf_counter() - start)


def merge_meshes(meshes):
    """One native Mesh of several (positions, triangles, normals, uvs, face ids) without welding."""
    offsets = np.cumsum([0] + [m.vertex_count for m in meshes[:-1]])
    return native().Mesh(np.concatenate([m.positions for m in meshes]),
                         np.concatenate([m.triangles + o for m, o in zip(meshes, offsets)]).astype(np.int32),
                         normals=np.concatenate([m.normals for m in meshes]),
                         uvs=np.concatenate([m.uvs for m in meshes]),
                         face_ids=np.concatenate([m.face_ids for m in meshes]))


def empty_part(name):
    return MeshPart(name=name, kind="TBP", index=-1, positions=np.zeros((0, 3)),
                    triangles=np.zeros((0, 3), np.int32), face_ids=np.zeros(0, np.int32),
                    corner_uvs=np.zeros((0, 2), np.float32), corner_normals=np.zeros((0, 3), np.float32),
                    edges=np.zeros((0, 2), np.int32), edge_flags=np.zeros(0, np.uint8),
                    materials=[material_name(None)], material_index=np.zeros(0, np.int32))


# Mesh to TBP: sides whose faces meet at more than this (radians) stay creases.
TBP_SHARP_ANGLE = math.radians(30.0)


def mesh_to_tbp(positions, triangles, name="", sharp_angle=TBP_SHARP_ANGLE, sharp_edges=None):
    """Cubic PN-triangle TbpSolid of a closed, outward-oriented triangle mesh, sides
    meeting at more than `sharp_angle`, and the sides `sharp_edges` ((k, 2) vertex
    indices: the edges a user marked sharp), kept as creases (a cube stays a cube);
    ValueError if the mesh has no triangles or open edges (it must bound a solid)."""
    positions = np.asarray(positions, np.float64).reshape(-1, 3)
    triangles = np.asarray(triangles, np.int32).reshape(-1, 3)
    pairs = np.asarray(sharp_edges if sharp_edges is not None else [], np.int64).reshape(-1, 2)
    if len(triangles) == 0:
        raise ValueError("the mesh has no faces")
    mesh = native().Mesh(positions, triangles)
    weld = native().weld_map(mesh, native().WeldOptions(tolerance=weld_tolerance(positions)))
    welded = weld.vertex_map[triangles]
    open_edges = open_edge_count(welded)
    if open_edges:
        raise ValueError(f"the mesh is not closed ({open_edges} open edges): a TBP solid needs a closed mesh")
    solid = native().pn_triangles(mesh, sharp_angle, [tuple(p) for p in pairs.tolist()])
    solid.name = name
    return solid
