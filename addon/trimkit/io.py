"""CAD files to numpy arrays ready for Blender, without bpy (pytest covers it).

Lengths: `tessellate` takes the tolerance in the model's units (or as a fraction
of the model's diagonal when `relative`) and returns positions multiplied by
`scale` (model units -> Blender units). Corner arrays are in loop order: corner
k of triangle t is row 3t + k.
"""
import dataclasses
import math
import pathlib
import tempfile
import time
import zlib

import numpy as np

from . import limits as limits_module, uv_layout
from .uv_layout import normalize_uvs

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
    corner_uvs: np.ndarray      # (3m, 2) float32: metres of surface, packed (uv_layout.REAL), or 0-1 per face
    corner_normals: np.ndarray  # (3m, 3) float32, unit
    edges: np.ndarray           # (k, 2) int32 flagged edges
    edge_flags: np.ndarray      # (k,) uint8: EDGE_FACE_BOUNDARY | EDGE_SHARP
    materials: list             # [(name, (r, g, b))]
    material_index: np.ndarray  # (m,) int32 into materials
    # CAD face ids the part holds, with triangles or not (a face that failed to mesh
    # has none, yet belongs to its body's object).
    faces: list = dataclasses.field(default_factory=list)
    uv_layout: dict = None      # uv_layout.real_world_uvs's layout (REAL uvs), else None


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


def read_source(path, limits=None):
    """(model, source bytes) of a CAD file; RuntimeError/ValueError for a bad file.
    limits: a limits.Limits (read timeout, progress, cancel: limits.Cancelled)."""
    data = pathlib.Path(path).read_bytes()
    return read_bytes(data, pathlib.Path(path).name, limits), data


STEP_SUFFIXES = (".stp", ".step")
BREP_SUFFIXES = (".brep", ".brp")
OCCT_SUFFIXES = STEP_SUFFIXES + BREP_SUFFIXES


def read_bytes(data, name, limits=None):
    """Model from a CAD file's bytes, the reader chosen by what the bytes are
    (file_format), else by `name`'s extension: IGES is parsed in memory, STEP and
    .brep through a temporary copy (Open CASCADE reads files). ValueError naming the
    file and what it is for anything trimkit does not read as CAD."""
    kind = file_format(data, name)
    if kind in ("step", "brep"):
        return read_step_bytes(data, name, kind, limits)
    if kind == "tkz":  # trimkit compress's output: the compressed faces rebuilt (Muraki)
        return native().extend_model(native().read_tkz_bytes(bytes(data), name))
    if kind != "iges":
        raise ValueError(unsupported_message(name, kind))
    try:
        return native().read_model_bytes(data, name, **limits_module.read_arguments(limits))
    except native().ReadStopped as err:
        raise limits_module.cancelled_error(err, limits, name) or err from None


def compress_to_tkz(model, tolerance=0.0):
    """(.tkz bytes, faces compressed, faces) of a model, as `trimkit compress` (Muraki):
    each face refitted from its edges with G1; tolerance in model units, 0 for 1 % of
    each face's box."""
    options = native().CompressOptions()
    options.tolerance = tolerance
    compressed, report = native().compress_model(model, options)
    return bytes(native().tkz_bytes(compressed)), sum(r.compressed for r in report), len(report)


def rebuild_faces(model, faces, tolerance=0.0):
    """(.tkz bytes, [(face, rebuilt, reason, max error)]) with `faces` rebuilt from their
    boundary edges with G1 to their neighbours (Muraki; CompressOptions.rebuild: even
    where their own surface is damaged), every other face kept as it is."""
    options = native().CompressOptions()
    options.tolerance = tolerance
    options.faces = list(faces)
    options.rebuild = True
    compressed, report = native().compress_model(model, options)
    rows = [(f, report[f].compressed, report[f].reason, report[f].max_error) for f in faces]
    return bytes(native().tkz_bytes(compressed)), rows


READABLE = "IGES (.igs, .iges), STEP (.stp, .step), Open CASCADE .brep or trimkit .tkz"
# What other files are, by their first bytes or extension, and where Blender reads them.
OTHER_FORMATS = {
    "tbp": ("a TBP solid", "File > Import > TBP (.tbp) [trimkit]"),
    "stl": ("an STL mesh", "File > Import > STL"),
    "obj": ("a Wavefront OBJ mesh", "File > Import > Wavefront (.obj)"),
    "ply": ("a PLY mesh", "File > Import > Stanford (.ply)"),
    "gltf": ("a glTF scene", "File > Import > glTF 2.0"),
    "fbx": ("an FBX scene", "File > Import > FBX"),
    "blend": ("a .blend file", "File > Open or File > Append"),
    "3dm": ("a Rhino .3dm file", "the import_3dm add-on"),
    "sat": ("an ACIS .sat file", "a CAD program: export it as STEP"),
    "parasolid": ("a Parasolid file", "a CAD program: export it as STEP"),
    "zip": ("a zip archive", "unpack it first"),
    "gzip": ("a gzip-compressed file", "unpack it first"),
    "empty": ("an empty file", None),
    "unknown": ("not a CAD file trimkit recognises", None),
}
SUFFIX_FORMATS = {".tkz": "tkz", ".igs": "iges", ".iges": "iges", ".stp": "step", ".step": "step", ".p21": "step",
                  ".brep": "brep", ".brp": "brep", ".tbp": "tbp", ".stl": "stl", ".obj": "obj", ".ply": "ply",
                  ".gltf": "gltf", ".glb": "gltf", ".fbx": "fbx", ".blend": "blend", ".3dm": "3dm",
                  ".sat": "sat", ".sab": "sat", ".x_t": "parasolid", ".x_b": "parasolid", ".zip": "zip"}


MAGIC = ((b"TKZ1", "tkz"), (b"glTF", "gltf"), (b"BLENDER", "blend"), (b"PK\x03\x04", "zip"), (b"Kaydara FBX", "fbx"),
         (b"\x1f\x8b", "gzip"))


def file_format(data, name):
    """What a file is, from its first bytes where they say ("iges", "step", "brep",
    "tbp", "stl", ...), else from the extension of `name`; "unknown" otherwise."""
    head = bytes(data[:4096])
    text = head.lstrip(b"\xef\xbb\xbf \t\r\n")
    suffix = SUFFIX_FORMATS.get(pathlib.Path(name).suffix.lower(), "unknown")
    if not text:
        return "empty"
    if text.startswith(b"ISO-10303-21"):
        return "step"
    if text.startswith(b"DBRep_DrawableShape") or text.startswith(b"CASCADE Topology"):
        return "brep"
    for magic, kind in MAGIC:
        if head.startswith(magic):
            return kind
    if text.startswith(b"ply"):
        return "ply"
    if text.startswith(b"{") and b'"tbp"' in head:
        return "tbp"
    if text.startswith(b"solid ") and b"facet" in head:
        return "stl"
    if len(data) >= 84 and len(data) == 84 + 50 * int.from_bytes(bytes(data[80:84]), "little"):
        return "stl"  # binary STL: 80-byte header, triangle count, 50 bytes a triangle
    if is_iges_text(head):
        return "iges"
    if text.startswith(b"v ") or b"\nv " in head or b"\nf " in head:
        return "obj"
    return suffix  # an .igs that is none of these: the IGES reader says what is wrong


def is_iges_text(head):
    """IGES: 80-column records whose column 73 names the section (S, G, D, P, T)."""
    lines = head.split(b"\n")[:3]
    return len(lines) >= 2 and all(len(l.rstrip(b"\r")) == 80 and l[72:73] in (b"S", b"G", b"D", b"P", b"T")
                                   for l in lines[:2])


def unsupported_message(name, kind):
    what, where = OTHER_FORMATS.get(kind, OTHER_FORMATS["unknown"])
    message = f"{name}: {what}, not a CAD file this importer reads; trimkit reads {READABLE}"
    return message + (f"; open it with {where}" if where else "")


def read_step_bytes(data, name, kind=None, limits=None):
    if not has_step():
        raise RuntimeError(f"{name}: this trimkit module cannot read STEP or .brep (built without Open CASCADE)")
    kind = kind or ("brep" if pathlib.Path(name).suffix.lower() in BREP_SUFFIXES else "step")
    with tempfile.TemporaryDirectory(prefix="trimkit-") as folder:
        path = pathlib.Path(folder) / (pathlib.Path(name).stem + (".brep" if kind == "brep" else ".stp"))
        path.write_bytes(data)
        try:
            reader = native().read_brep if kind == "brep" else native().read_step
            return reader(str(path), **limits_module.read_arguments(limits))
        except native().ReadStopped as err:
            cancelled = limits_module.cancelled_error(err, limits, name)
            if cancelled:
                raise cancelled from None
            raise RuntimeError(str(err).replace(str(path), name).replace(path.name, name)) from None
        except RuntimeError as err:  # name the file, not its temporary copy
            raise RuntimeError(str(err).replace(str(path), name).replace(path.name, name)) from None


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
               trim_method="bezier3d", scale=1.0, split="BODY", parts=None, stem="Model",
               uv_mode=uv_layout.REAL, metres=None, uv_layouts=None, limits=None):
    """Meshes `model` and splits the mesh into parts.

    split: "BODY" (one part per body, faces in no body together), "FACE" (one
    part per face) or "MODEL" (one part); always "BODY" for a model with instances,
    which place whole bodies (see placements). `parts`: optional [(kind, index)] to
    return only those parts (re-meshing existing objects). Raises ValueError
    for bad options. uv_mode: uv_layout.REAL (1 UV unit per metre, `metres` per model
    unit, default model.scale_to_metres; each part packed, or placed by
    uv_layouts[(kind, index)] where given) or uv_layout.FACE (each face 0-1).
    limits: a limits.Limits (face timeout, progress "mesh", cancel: limits.Cancelled).
    """
    start = time.perf_counter()
    split = "BODY" if model.instances else split
    options = native().TessellationOptions(
        tolerance=absolute_tolerance(model, tolerance, relative), angle=angle,
        mode=mode, trim_method=trim_method)
    limits_module.apply(options, limits)
    try:
        result = native().tessellate_model(model, options)
    except native().TessellationCancelled:
        raise limits_module.Cancelled(f"{stem}: cancelled") from None
    if limits is not None:
        limits.check()
    mesh = result.mesh
    corner_uvs, corner_normals = native().corner_attributes(model, mesh)
    arrays = dict(positions=mesh.positions * scale, triangles=mesh.triangles,
                  face_ids=mesh.face_ids, edges=mesh.edges, edge_flags=mesh.edge_flags,
                  corner_uvs=corner_uvs.reshape(-1, 2),
                  corner_normals=corner_normals.reshape(-1, 3).astype(np.float32))
    colors = face_colors(model, mesh)
    wanted = parts if parts is not None else part_list(model, split)
    out = [make_part(model, arrays, colors, kind, index, stem) for kind, index in wanted]
    for part in out:
        if uv_mode == uv_layout.FACE:
            part.corner_uvs = normalize_uvs(part.corner_uvs, part.face_ids)
        else:
            part.corner_uvs, part.uv_layout = uv_layout.real_world_uvs(
                model, part.corner_uvs, part.face_ids, model.scale_to_metres if metres is None else metres,
                (uv_layouts or {}).get((part.kind, part.index)))
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


@dataclasses.dataclass
class Placement:
    """One instance of a body: where a linked duplicate of the body's mesh goes."""
    body: int
    matrix: np.ndarray  # (4, 4) float64, the body's coordinates to the scene's (Blender units)
    name: str
    path: tuple = ()    # assembly names from the root down to the instance's (STEP)


def placements(model, scale=1.0):
    """The model's instances as Placements (translations scaled like the positions);
    empty when each body appears once, untransformed."""
    out = []
    for instance in model.instances:
        matrix = np.array(instance.matrix, np.float64)
        matrix[:3, 3] *= scale
        out.append(Placement(body=instance.body, matrix=matrix, name=instance.name,
                             path=tuple(getattr(instance, "path", ()))))
    return out


def placed_parts(parts, placements):
    """The parts as flat meshes (file export): an instanced body once per placement,
    moved there; the other parts as they are."""
    out = []
    for part in parts:
        mine = [p for p in placements if part.kind == "BODY" and p.body == part.index]
        out += [moved_part(part, p.matrix) for p in mine] if mine else [part]
    return out


def moved_part(part, matrix):
    """`part` mapped by the 4x4 affine `matrix`: positions, normals by the inverse
    transpose; a mirroring matrix reverses each triangle's corners to keep it outward."""
    linear, offset = matrix[:3, :3], matrix[:3, 3]
    normals = part.corner_normals @ np.linalg.inv(linear)  # rows: (L^-T n)^T = n^T L^-1
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    moved = dataclasses.replace(part, positions=part.positions @ linear.T + offset,
                                corner_normals=normals.astype(np.float32))
    if np.linalg.det(linear) > 0.0:
        return moved
    m = len(part.triangles)
    return dataclasses.replace(moved, triangles=np.ascontiguousarray(part.triangles[:, ::-1]),
                               corner_uvs=moved.corner_uvs.reshape(m, 3, 2)[:, ::-1].reshape(-1, 2),
                               corner_normals=moved.corner_normals.reshape(m, 3, 3)[:, ::-1].reshape(-1, 3))


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


def measure(model, positions, triangles, face_ids, faces, samples=4):
    """Deviation report (native DeviationReport, model units) of a mesh in model units
    from the model's faces `faces`; its face ids must be among them."""
    mesh = native().Mesh(positions=np.asarray(positions, np.float64), triangles=np.asarray(triangles, np.int32),
                         face_ids=np.asarray(face_ids, np.int32))
    return native().measure_deviation(model, mesh, faces=list(faces), samples=samples)


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
        materials=materials, material_index=material_index,
        faces=list(range(len(model.faces))) if faces is None else list(faces))


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


# -- TBP solids (triangular Bézier patches, [García et al.]) -------------------
#
# A TBP object's geometry is the solid's .tbp text (stored in the .blend like a CAD
# file's bytes). Meshes: polygonization at hierarchy level L and lod K, i.e.
# (K+1)^L segments per patch edge, one CAD face per patch (face id = patch index),
# corner normals and (u, v) from each patch, vertices welded across patches.

TBP_DEFAULT_ANGLE = np.radians(30.0)


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


def mesh_to_tbp(positions, triangles, name="", sharp_angle=TBP_SHARP_ANGLE):
    """Cubic PN-triangle TbpSolid of a closed, outward-oriented triangle mesh, sides
    meeting at more than `sharp_angle` kept as creases (a cube stays a cube); ValueError
    if the mesh has no triangles or open edges (it must bound a solid)."""
    positions = np.asarray(positions, np.float64).reshape(-1, 3)
    triangles = np.asarray(triangles, np.int32).reshape(-1, 3)
    if len(triangles) == 0:
        raise ValueError("the mesh has no faces")
    mesh = native().Mesh(positions, triangles)
    weld = native().weld_map(mesh, native().WeldOptions(tolerance=weld_tolerance(positions)))
    welded = weld.vertex_map[triangles]
    open_edges = open_edge_count(welded)
    if open_edges:
        raise ValueError(f"the mesh is not closed ({open_edges} open edges): a TBP solid needs a closed mesh")
    solid = native().pn_triangles(mesh, sharp_angle)
    solid.name = name
    return solid
