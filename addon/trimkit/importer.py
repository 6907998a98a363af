"""CAD files into Blender objects, and re-meshing objects from their stored
geometry: what the operators, the render handler and batch.py share.
`settings` carry lengths in Blender units; io works in model units.
"""
import dataclasses
import pathlib
import time

import bpy
import mathutils
import numpy as np

from . import blender_mesh, io, properties, stored_source, tbp_objects, uv_layout
from .settings import ImportSettings  # noqa: F401  (importer.ImportSettings for callers)


# Parts smaller or larger than this (metres) get a warning: the file's unit is likely wrong.
SMALLEST_PART = 0.001
LARGEST_PART = 100.0


def model_metres(model, units):
    """Metres per model unit: the file's declared unit, or the unit the user chose."""
    return model.scale_to_metres if units == 'FILE' else properties.UNIT_METRES[units]


def unit_label(model, units):
    return f"{model.units} (the file's)" if units == 'FILE' else f"{units.lower()} (chosen; the file says {model.units})"


def scene_scale(model, scene, scale, units='FILE'):
    """Model units -> Blender units: `scale`, or metres per model unit over the scene's unit scale."""
    return unit_scale_of(model, unit_scale(scene), scale, units)


def unit_scale(scene):
    """Metres per Blender unit of `scene`."""
    return scene.unit_settings.scale_length or 1.0


def unit_scale_of(model, metres_per_unit, scale, units='FILE'):
    """scene_scale for a scene of `metres_per_unit` (no bpy: for the working thread)."""
    if scale > 0.0:
        return scale
    return model_metres(model, units) / metres_per_unit


def format_length(metres):
    for unit, size in (("km", 1000.0), ("m", 1.0), ("mm", 0.001)):
        if abs(metres) >= size:
            return f"{metres / size:.4g} {unit}"
    return f"{metres * 1e6:.4g} um"


def size_report(path, model, units, parts, scene):
    """(one line: unit and size, [warnings]) for the parts of one file."""
    metres = unit_scale(scene)
    extents = {p.name: (np.ptp(p.positions, axis=0) * metres if len(p.positions) else np.zeros(3)) for p in parts}
    everything = np.concatenate([p.positions for p in parts if len(p.positions)] or [np.zeros((1, 3))])
    whole = np.ptp(everything, axis=0) * metres
    line = f"{path.name}: unit {unit_label(model, units)}, size " + \
        " x ".join(format_length(x) for x in whole)
    warnings = []
    for name, extent in extents.items():
        size = float(extent.max())
        if size < SMALLEST_PART or size > LARGEST_PART:
            warnings.append(f"{path.name}: {name} is {format_length(size)} across, "
                            f"{'below 1 mm' if size < SMALLEST_PART else 'above 100 m'}: is the unit right? "
                            f"(import Units: File, Millimetres, Centimetres, Metres, Inches)")
    return line, warnings


@dataclasses.dataclass
class PreparedFile:
    """One CAD file read and meshed, not yet in the scene (prepare_file -> link_file)."""
    path: pathlib.Path
    model: object
    data: bytes
    result: object          # io.Tessellation
    scale: float            # model units -> Blender units
    read_seconds: float
    mesh_seconds: float
    started: float          # time.perf_counter() when the read began
    finished: float         # and when the mesh was done


def prepare_file(filepath, settings, metres_per_unit, limits=None):
    """Reads and meshes one CAD file for a scene of `metres_per_unit`. No bpy: it runs
    in the import's working thread. limits: a limits.Limits (timeouts, progress of
    stages "read" and "mesh", cancel: limits.Cancelled). RuntimeError/ValueError for
    a bad file or bad settings."""
    path = pathlib.Path(filepath)
    started = time.perf_counter()
    if limits:
        limits.begin("read")
    model, data = io.read_source(path, limits)
    read_end = time.perf_counter()
    if limits:
        limits.check()
        limits.begin("mesh")
    mesh_start = time.perf_counter()
    scale = unit_scale_of(model, metres_per_unit, settings.scale, settings.units)
    tolerance = settings.relative_tolerance if settings.relative else settings.tolerance / scale
    result = io.tessellate(model, tolerance, relative=settings.relative, angle=settings.angle,
                           mode=settings.mode, trim_method=settings.trim_method, scale=scale,
                           split=settings.split, stem=path.stem, uv_mode=settings.uv_mode,
                           metres=scale * metres_per_unit, limits=limits)
    finished = time.perf_counter()
    return PreparedFile(path, model, data, result, scale, read_end - started, finished - mesh_start, started, finished)


# Waits shorter than this are not listed in the timing (a function return, not a wait).
LISTED_WAIT = 0.005


def timing_line(prepared, link_start, link_end):
    """'NAME: 1.23 s (read 0.40 s, mesh 0.70 s, objects 0.13 s)': the import's time, from the
    start of its read to its last object, and its parts, each timed on its own; a modal
    import's wait between the working thread's end and the main thread's next look at
    it is listed as 'waiting' when it is not negligible."""
    total = link_end - prepared.started
    wait = link_start - prepared.finished
    waiting = f", waiting {wait:.2f} s" if wait >= LISTED_WAIT else ""
    return (f"{prepared.path.name}: {total:.2f} s (read {prepared.read_seconds:.2f} s, "
            f"mesh {prepared.mesh_seconds:.2f} s{waiting}, objects {link_end - link_start:.2f} s)")


def import_file(context, filepath, settings, progress=None, limits=None):
    """Reads, meshes and links one CAD file into the active collection; a model with
    instances goes into a new collection named after the file, one object per
    instance, the instances of a body sharing its mesh (linked duplicates).

    Returns (objects, io.Tessellation, report lines). Raises RuntimeError/ValueError
    before anything is added to the scene when the file or the settings are bad, and
    limits.Cancelled when `limits.cancel` is set while reading or meshing.
    `progress(fraction)` is called as objects are created.
    """
    prepared = prepare_file(filepath, settings, unit_scale(context.scene), limits)
    objects, result, lines, _ = link_file(context, prepared, settings, progress)
    return objects, result, lines


def link_file(context, prepared, settings, progress=None):
    """The objects of a prepare_file result, linked into the scene (main thread).
    Returns (objects, io.Tessellation, report lines, timing_line); each object's
    trimkit.import_report holds the lines, trimkit.import_timing the timing."""
    start = time.perf_counter()
    path, model, data, result, scale = prepared.path, prepared.model, prepared.data, prepared.result, prepared.scale
    placements = io.placements(model, scale)
    line, warnings = size_report(path, model, settings.units, result.parts, context.scene)
    warnings += [f"{path.name}: {w}" for w in model.warnings]  # the reader's (a face it skipped)
    text = stored_source.store(path.name, data, path.resolve(), model)
    collection = new_collection(context.collection, path.stem) if placements else context.collection
    assemblies = {(): collection}
    objects = []
    for k, part in enumerate(result.parts):
        offset = origin_offset(part, settings.origin)
        me = blender_mesh.create_mesh(shifted(part, offset), part.name, smooth=settings.smooth,
                                      exact_normals=settings.exact_normals)
        for name, matrix, tree in object_placements(part, placements):
            obj = bpy.data.objects.new(name, me)
            assembly_collection(assemblies, tree).objects.link(obj)
            # the part's coordinates to the scene's, then the origin moved to `offset` in them
            placed = mathutils.Matrix(matrix.tolist()) if matrix is not None else mathutils.Matrix.Identity(4)
            if matrix is not None or offset.any():
                obj.matrix_world = placed @ mathutils.Matrix.Translation(offset.tolist())
            store_settings(obj.trimkit, text, path.name, part, scale, result, settings)
            obj.trimkit.origin = offset.tolist()
            write_metadata(obj, path, model, settings.units, name)
            objects.append(obj)
        if progress:
            progress((k + 1) / len(result.parts))
    select_only(context, objects)
    timing = timing_line(prepared, start, time.perf_counter())
    for obj in objects:
        obj.trimkit.import_report = "\n".join([line] + warnings)
        obj.trimkit.import_timing = timing
    return objects, result, [line] + warnings, timing


def origin_offset(part, origin):
    """(3,) where the object origin of `part` goes in the part's coordinates (Blender
    units): zero for File Origin, the centre of the part's bounding box for Part Box Centre."""
    if origin != 'BOX' or len(part.positions) == 0:
        return np.zeros(3)
    return 0.5 * (part.positions.min(axis=0) + part.positions.max(axis=0))


def shifted(part, offset):
    """`part` with its positions less `offset` (the mesh of an object whose origin is there)."""
    offset = np.asarray(offset, np.float64)
    if not offset.any():
        return part
    return dataclasses.replace(part, positions=part.positions - offset)


def write_metadata(obj, path, model, units, product):
    """What the file says about the object, as custom properties (Object > Custom Properties)."""
    obj["trimkit_file"] = path.name
    obj["trimkit_path"] = str(path.resolve())
    obj["trimkit_unit"] = model.units if units == 'FILE' else units.lower()
    obj["trimkit_product"] = product
    obj["trimkit_cad_faces"] = obj.trimkit.faces
    update_tolerance_metadata(obj)


def update_tolerance_metadata(obj):
    """trimkit_tolerance: the absolute tolerance of the current mesh, in the file's units."""
    props = obj.trimkit
    obj["trimkit_tolerance"] = props.tolerance / props.scale if props.scale > 0.0 else props.tolerance


def new_collection(parent, name):
    collection = bpy.data.collections.new(name)
    parent.children.link(collection)
    return collection


def assembly_collection(assemblies, tree):
    """The collection of the assembly path `tree` (a tuple of names below the file's
    collection, assemblies[()]), made with its parents when new."""
    if tree not in assemblies:
        parent = assembly_collection(assemblies, tree[:-1])
        assemblies[tree] = new_collection(parent, tree[-1] or "assembly")
    return assemblies[tree]


def object_placements(part, placements):
    """[(name, (4, 4) matrix or None, assembly path)] of the objects showing `part`: one
    per instance of its body, else one, untransformed."""
    if part.kind == "BODY":
        mine = [p for p in placements if p.body == part.index]
        if mine:
            return [(p.name or part.name, p.matrix, p.path) for p in mine]
    return [(part.name, None, ())]


def store_settings(props, text, file_name, part, scale, result, settings):
    """What re-meshing the object needs: the stored file, its part and the settings."""
    props.source = text
    props.source_name = file_name
    props.part = part.kind
    props.part_index = part.index
    props.scale = scale
    props.tolerance = result.tolerance * scale
    props.render_tolerance = settings.render_tolerance
    props.relative = settings.relative
    props.relative_tolerance = settings.relative_tolerance
    props.angle = settings.angle
    props.mode = settings.mode
    props.trim_method = settings.trim_method
    props.smooth = settings.smooth
    props.exact_normals = settings.exact_normals
    props.units = settings.units
    props.uv_mode = settings.uv_mode
    props.uv_layout = uv_layout.layout_to_json(part.uv_layout) if part.uv_layout else ""
    record_stats(props, part, result)


def select_only(context, objects):
    for obj in context.view_layer.objects.selected:
        obj.select_set(False)
    for obj in objects:
        obj.select_set(True)
    if objects:
        context.view_layer.objects.active = objects[0]


def record_stats(props, part, result):
    """Counts and failures of the object showing `part`: the failed faces are those the
    part holds (part.faces: its body's, its face, or the model's), which have no
    triangles and so are not among part.face_ids."""
    faces = set(part.faces) | set(int(f) for f in np.unique(part.face_ids))
    failed = [(f, reason) for f, reason in result.failed_faces if f in faces]
    props.faces = len(faces)
    props.triangles = len(part.triangles)
    props.seconds = result.seconds
    props.failed_faces = len(failed)
    props.failed_report = "; ".join(reason if reason.startswith(f"face {f}:") else f"face {f}: {reason}"
                                    for f, reason in failed)[:1000]
    props.check_report = ""  # a new mesh: the last check no longer describes it
    props.check_failed = ""


def is_trimkit(obj):
    return obj is not None and obj.type == 'MESH' and obj.trimkit.source is not None


def object_tolerance(props, render=False):
    """(tolerance, relative) in the units io.tessellate expects."""
    if render and props.render_tolerance > 0.0:
        return props.render_tolerance / props.scale, False
    if props.relative:
        return props.relative_tolerance, True
    return props.tolerance / props.scale, False


def retessellate(objects, render=False, progress=None):
    """Re-meshes trimkit objects from their stored geometry with their own settings
    (the render tolerance when `render`). Objects sharing a source and settings
    are meshed together. Returns the io.Tessellation of each group. TBP objects
    re-mesh at their levels/lod (tbp_objects.remesh; no render detail)."""
    tbp = [o for o in objects if o.trimkit.kind != 'CAD']
    objects = [o for o in objects if o.trimkit.kind == 'CAD']
    if not render:
        objects = with_linked_duplicates(objects)
    for k, obj in enumerate(tbp if not render else []):
        tbp_objects.remesh(obj)
        if progress:
            progress((k + 1) / (len(tbp) + len(objects)))
    groups = {}
    for obj in objects:
        p = obj.trimkit
        key = (p.source.name, object_tolerance(p, render), p.angle, p.mode, p.trim_method, p.scale, p.uv_mode)
        groups.setdefault(key, []).append(obj)
    results = []
    for k, (key, members) in enumerate(groups.items()):
        props = members[0].trimkit
        model = io.read_bytes(stored_source.load(props.source), stored_source.file_name(props.source))
        tolerance, relative = key[1]
        wanted = list(dict.fromkeys(object_part(o) for o in members))  # instances share a part
        result = io.tessellate(model, tolerance, relative=relative, angle=props.angle, mode=props.mode,
                               trim_method=props.trim_method, scale=props.scale, parts=wanted,
                               uv_mode=props.uv_mode, metres=object_metres(props),
                               uv_layouts=stored_layouts(members))
        for part in result.parts:
            remesh_part([o for o in members if object_part(o) == (part.kind, part.index)], part, result, render)
        results.append(result)
        if progress:
            progress((k + 1) / len(groups))
    return results


def rebuild_faces(obj, faces):
    """Rebuilds CAD faces of obj's stored model from their edges with G1 to their
    neighbours (io.rebuild_faces), stores the result (a .tkz) in place of the source
    and re-meshes every object made from it. Returns io.rebuild_faces' rows."""
    props = obj.trimkit
    text = props.source
    name = stored_source.file_name(text)
    model = io.read_bytes(stored_source.load(text), name)
    tolerance, relative = object_tolerance(props)
    data, rows = io.rebuild_faces(model, faces, 0.0 if relative else tolerance)
    stored_source.replace(text, data)
    text["trimkit_file"] = pathlib.Path(name).stem + ".tkz"
    retessellate([o for o in bpy.data.objects if is_trimkit(o) and o.trimkit.source == text])
    return rows


def object_metres(props):
    """Metres per model unit of the object's mesh (its scale times the scene's unit scale)."""
    return props.scale * (bpy.context.scene.unit_settings.scale_length or 1.0)


def stored_layouts(objects):
    """{(kind, index): UV layout} of the objects' real-world UV maps: a re-mesh keeps
    every face's UVs where they were."""
    out = {}
    for obj in objects:
        if obj.trimkit.uv_mode == 'REAL' and obj.trimkit.uv_layout:
            out.setdefault(object_part(obj), uv_layout.layout_from_json(obj.trimkit.uv_layout))
    return out


# The settings of Object.trimkit that decide the mesh.
MESH_SETTINGS = ("tolerance", "render_tolerance", "relative", "relative_tolerance", "angle", "mode",
                 "trim_method", "smooth", "exact_normals", "uv_mode")


def with_linked_duplicates(objects):
    """`objects` and the other trimkit objects sharing a mesh with one of them (the
    instances of a body), which take that object's mesh settings: re-meshing shared
    data changes every user, as editing it in Blender does."""
    first = {}
    for obj in objects:
        first.setdefault(obj.data.as_pointer(), obj)
    out, seen = list(objects), set(objects)
    for other in bpy.data.objects:
        source = first.get(other.data.as_pointer()) if is_trimkit(other) else None
        if source is not None and other not in seen:
            for name in MESH_SETTINGS:
                setattr(other.trimkit, name, getattr(source.trimkit, name))
            out.append(other)
    return out


def object_part(obj):
    return obj.trimkit.part, obj.trimkit.part_index


def remesh_part(objects, part, result, render):
    """New meshes from `part` for the objects showing it: one per mesh they share, so
    linked duplicates (instances) stay linked."""
    sharing = {}
    for obj in objects:
        sharing.setdefault(obj.data.as_pointer(), []).append(obj)
    for users in sharing.values():
        blender_mesh.replace_shared_mesh(users, shifted(part, users[0].trimkit.origin), users[0].trimkit.smooth,
                                         users[0].trimkit.exact_normals)
    if render:
        return
    for obj in objects:
        if obj.trimkit.relative:
            obj.trimkit.tolerance = result.tolerance * obj.trimkit.scale
        if part.uv_layout:
            obj.trimkit.uv_layout = uv_layout.layout_to_json(part.uv_layout)
        record_stats(obj.trimkit, part, result)
        update_tolerance_metadata(obj)


def reload(text):
    """Reads the stored file's source path again, stores the new bytes and re-meshes every
    object made from it. Returns (path, objects). ValueError/RuntimeError, with nothing
    changed, when the file is gone, unreadable, or no longer has an object's part."""
    path = stored_source.source_path(text)
    name = stored_source.file_name(text)
    if not path:
        raise ValueError(f"{name}: imported before trimkit stored source paths; import it again")
    try:
        data = pathlib.Path(path).read_bytes()
    except OSError as err:
        raise OSError(f"{name}: cannot read {path}: {err.strerror or err}") from None
    model = io.read_bytes(data, name)
    objects = [o for o in bpy.data.objects if is_trimkit(o) and o.trimkit.source == text]
    for obj in objects:
        kind, index = object_part(obj)
        count = len(model.bodies) if kind == "BODY" else len(model.faces) if kind == "FACE" else 1
        if kind != "MODEL" and index >= count:
            raise ValueError(f"{path}: {obj.name} shows {kind.lower()} {index}, which the file no longer has "
                             f"({count} {kind.lower()}s)")
    stored_source.replace(text, data, model)
    for obj in objects:
        obj.trimkit.uv_layout = ""  # the faces may have changed: lay the UVs out again
    retessellate(objects)
    for obj in objects:
        obj["trimkit_cad_faces"] = obj.trimkit.faces
    return path, objects
