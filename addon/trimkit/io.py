"""CAD files to numpy arrays ready for Blender, without bpy (pytest covers it); TBP
solids are tbp_io.py's, which fills this module's MeshPart too.

Lengths: `tessellate` takes the tolerance in the model's units (or as a fraction
of the model's diagonal when `relative`) and returns positions multiplied by
`scale` (model units -> Blender units). Corner arrays are in loop order: corner
k of triangle t is row 3t + k.
"""
import dataclasses
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


def lossless_tkz(model):
    """The model as .tkz bytes with every surface kept: it reads back as the same model
    (read_bytes), so what is meshed from it is what the source gives."""
    return bytes(native().model_tkz_bytes(model))


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
        mode=mode, trim_method=trim_method, area_per_body=split != "MODEL")
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
