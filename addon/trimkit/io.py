"""CAD files to numpy arrays ready for Blender, without bpy (pytest covers it).

Lengths: `tessellate` takes the tolerance in the model's units (or as a fraction
of the model's diagonal when `relative`) and returns positions multiplied by
`scale` (model units -> Blender units). Corner arrays are in loop order: corner
k of triangle t is row 3t + k.
"""
import dataclasses
import pathlib
import time
import zlib

import numpy as np

_native = None


def native():
    """The compiled _trimkit module, imported on first use so that the add-on registers
    (and reports a clear error in execute()) even where it cannot load."""
    global _native
    if _native is None:
        try:
            from . import _trimkit as module
        except ImportError:  # pytest and development: build/python on sys.path
            import _trimkit as module
        _native = module
    return _native

DEFAULT_COLOR = (0.8, 0.8, 0.8)
EDGE_FACE_BOUNDARY = 1
EDGE_SHARP = 2


@dataclasses.dataclass
class MeshPart:
    """One Blender object's mesh: a body, a face, or the whole model."""
    name: str
    kind: str           # "MODEL", "BODY" or "FACE"
    index: int          # body or face index; -1 for the whole model
    positions: np.ndarray       # (n, 3) float64, Blender units
    triangles: np.ndarray       # (m, 3) int32
    face_ids: np.ndarray        # (m,) int32: CAD face per triangle (cad_face)
    corner_uvs: np.ndarray      # (3m, 2) float32, normalized to [0, 1] per CAD face
    corner_normals: np.ndarray  # (3m, 3) float32, unit
    edges: np.ndarray           # (k, 2) int32 flagged edges
    edge_flags: np.ndarray      # (k,) uint8: EDGE_FACE_BOUNDARY | EDGE_SHARP
    materials: list             # [(name, (r, g, b))]
    material_index: np.ndarray  # (m,) int32 into materials


@dataclasses.dataclass
class Tessellation:
    parts: list
    faces: int
    triangles: int
    tolerance: float            # absolute, model units
    seconds: float
    failed_faces: list          # [(face id, reason)]
    warnings: list


def has_step():
    try:
        return hasattr(native(), "read_step")
    except ImportError:
        return False


def read_source(path):
    """(model, source bytes) of a CAD file; RuntimeError/ValueError for a bad file."""
    data = pathlib.Path(path).read_bytes()
    return read_bytes(data, pathlib.Path(path).name), data


def read_bytes(data, name):
    return native().read_model_bytes(data, name)


def compress(data):
    return zlib.compress(data, 9)


def decompress(data):
    return zlib.decompress(data)


def absolute_tolerance(model, tolerance, relative):
    """Tolerance in model units: `tolerance` itself, or that fraction of the diagonal."""
    if not relative:
        return tolerance
    diagonal = native().model_diagonal(model)
    if not diagonal > 0.0:
        raise ValueError("relative tolerance needs a model with faces")
    return tolerance * diagonal


def tessellate(model, tolerance, *, relative=False, angle=np.radians(30.0), mode="guaranteed",
               trim_method="bezier3d", scale=1.0, split="BODY", parts=None, stem="Model"):
    """Meshes `model` and splits the mesh into parts.

    split: "BODY" (one part per body, faces in no body together), "FACE" (one
    part per face) or "MODEL" (one part). `parts`: optional [(kind, index)] to
    return only those parts (re-meshing existing objects). Raises ValueError
    for bad options.
    """
    start = time.perf_counter()
    options = native().TessellationOptions(
        tolerance=absolute_tolerance(model, tolerance, relative), angle=angle,
        mode=mode, trim_method=trim_method)
    result = native().tessellate_model(model, options)
    mesh = result.mesh
    corner_uvs, corner_normals = native().corner_attributes(model, mesh)
    arrays = dict(positions=mesh.positions * scale, triangles=mesh.triangles,
                  face_ids=mesh.face_ids, edges=mesh.edges, edge_flags=mesh.edge_flags,
                  corner_uvs=normalize_uvs(corner_uvs.reshape(-1, 2), mesh.face_ids),
                  corner_normals=corner_normals.reshape(-1, 3).astype(np.float32))
    colors = face_colors(model, mesh)
    wanted = parts if parts is not None else part_list(model, split)
    out = [make_part(model, arrays, colors, kind, index, stem) for kind, index in wanted]
    return Tessellation(
        parts=out, faces=result.faces, triangles=mesh.triangle_count, tolerance=result.tolerance,
        seconds=time.perf_counter() - start,
        failed_faces=[(f.face, f.reason) for f in result.failed_faces], warnings=list(result.warnings))


def part_list(model, split):
    if split == "FACE":
        return [("FACE", f) for f in range(len(model.faces))]
    if split == "BODY" and model.bodies:
        in_body = set(f for body in model.bodies for f in body.faces)
        parts = [("BODY", b) for b in range(len(model.bodies))]
        if len(in_body) < len(model.faces):
            parts.append(("MODEL", -1))  # free faces
        return parts
    return [("MODEL", -1)]


def part_faces(model, kind, index):
    """CAD face ids of a part; None for all faces."""
    if kind == "FACE":
        return [index]
    if kind == "BODY":
        return list(model.bodies[index].faces)
    if model.bodies:  # the faces in no body
        in_body = set(f for body in model.bodies for f in body.faces)
        return [f for f in range(len(model.faces)) if f not in in_body]
    return None


def part_name(model, kind, index, stem):
    if kind == "FACE":
        return model.faces[index].name or f"Face.{index}"
    if kind == "BODY":
        return model.bodies[index].name or f"Body.{index}"
    return stem


def make_part(model, arrays, colors, kind, index, stem):
    faces = part_faces(model, kind, index)
    face_ids = arrays["face_ids"]
    keep = np.ones(len(face_ids), bool) if faces is None else np.isin(face_ids, faces)
    triangles = arrays["triangles"][keep]
    used, local = np.unique(triangles, return_inverse=True)
    remap = np.full(len(arrays["positions"]), -1, np.int32)
    remap[used] = np.arange(len(used), dtype=np.int32)
    edges = arrays["edges"]
    edge_keep = np.all(remap[edges] >= 0, axis=1) if len(edges) else np.zeros(0, bool)
    corner_keep = np.repeat(keep, 3)
    part_face_ids = face_ids[keep]
    materials, material_index = part_materials(model, colors, part_face_ids)
    return MeshPart(
        name=part_name(model, kind, index, stem), kind=kind, index=index,
        positions=arrays["positions"][used], triangles=local.reshape(-1, 3).astype(np.int32),
        face_ids=part_face_ids, corner_uvs=arrays["corner_uvs"][corner_keep],
        corner_normals=arrays["corner_normals"][corner_keep],
        edges=remap[edges[edge_keep]].reshape(-1, 2), edge_flags=arrays["edge_flags"][edge_keep],
        materials=materials, material_index=material_index)


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


def face_colors(model, mesh):
    """(faces, 3) rgb per CAD face: the mesh's face colours, else the model's, else grey."""
    colors = np.tile(np.array(DEFAULT_COLOR, np.float32), (len(model.faces), 1))
    has = np.zeros(len(model.faces), bool)
    for f, face in enumerate(model.faces):
        if 0 <= face.color < len(model.colors):
            colors[f] = model.colors[face.color].rgb
            has[f] = True
    mesh_colors = mesh.face_colors
    if len(mesh_colors):
        n = min(len(mesh_colors), len(colors))
        colors[:n] = mesh_colors[:n]
        has[:n] = True
    return colors, has


def part_materials(model, colors, face_ids):
    """Materials [(name, rgb)] for the colours used by `face_ids`, and (m,) indices."""
    rgb, has = colors
    keys = np.where(has[face_ids], face_ids, -1)  # -1: no colour, default material
    used = np.unique(keys)
    key_colors = [tuple(round(float(c), 4) for c in rgb[f]) if f >= 0 else None for f in used]
    unique = sorted(set(key_colors), key=lambda c: (c is not None, c or ()))
    lookup = {c: i for i, c in enumerate(unique)}
    table = np.array([lookup[c] for c in key_colors], np.int32)
    index = table[np.searchsorted(used, keys)] if len(keys) else np.zeros(0, np.int32)
    return [material_name(c) for c in unique], index


def material_name(rgb):
    if rgb is None:
        return ("trimkit default", DEFAULT_COLOR)
    return ("trimkit #%02x%02x%02x" % tuple(int(round(255 * c)) for c in rgb), rgb)


def merge_parts(parts):
    """One native().Mesh from parts (for .glb/.obj output); face ids are made unique
    per part, vertex normals taken from the corners."""
    positions, triangles, normals, uvs, face_ids, colors = [], [], [], [], [], []
    offset = face_offset = 0
    for part in parts:
        n = len(part.positions)
        vertex_normals = np.zeros((n, 3))
        vertex_normals[part.triangles.ravel()] = part.corner_normals
        vertex_uvs = np.zeros((n, 2))
        vertex_uvs[part.triangles.ravel()] = part.corner_uvs
        _, local_faces = np.unique(part.face_ids, return_inverse=True)
        positions.append(part.positions)
        triangles.append(part.triangles + offset)
        normals.append(vertex_normals / np.linalg.norm(vertex_normals, axis=1, keepdims=True))
        uvs.append(vertex_uvs)
        face_ids.append(local_faces.astype(np.int32) + face_offset)
        first = np.zeros(local_faces.max() + 1 if len(local_faces) else 0, np.int32)
        first[local_faces] = np.arange(len(local_faces))
        colors.append(np.array([part.materials[i][1] for i in part.material_index[first]], np.float32).reshape(-1, 3))
        offset += n
        face_offset += len(first)
    return native().Mesh(np.concatenate(positions), np.concatenate(triangles), normals=np.concatenate(normals),
                         uvs=np.concatenate(uvs), face_ids=np.concatenate(face_ids),
                         face_colors=np.concatenate(colors))


def write_mesh(path, parts):
    native().write_mesh(str(path), merge_parts(parts))
