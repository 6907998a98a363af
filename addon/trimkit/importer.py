"""CAD files into Blender objects, and re-meshing objects from their stored
geometry: what the operators, the render handler and batch.py share.
`settings` carry lengths in Blender units; io works in model units.
"""
import dataclasses
import pathlib

import bpy

from . import blender_mesh, io, stored_source, tbp_objects


@dataclasses.dataclass
class ImportSettings:
    tolerance: float = 0.001          # Blender units, when not relative
    relative: bool = True
    relative_tolerance: float = 0.001  # fraction of the model's diagonal
    render_tolerance: float = 0.0     # Blender units; 0: the viewport tolerance
    angle: float = 0.5235987755982988  # radians
    mode: str = "guaranteed"
    trim_method: str = "bezier3d"
    scale: float = 0.0                # model units -> Blender units; 0: file units to metres
    split: str = "BODY"               # "BODY", "FACE" or "MODEL"
    smooth: bool = True
    exact_normals: bool = True        # custom split normals from the exact surface


def scene_scale(model, scene, scale):
    """Model units -> Blender units: `scale`, or the file's units in metres."""
    if scale > 0.0:
        return scale
    return model.scale_to_metres / (scene.unit_settings.scale_length or 1.0)


def import_file(context, filepath, settings, progress=None):
    """Reads, meshes and links one CAD file into the active collection.

    Returns (objects, io.Tessellation). Raises RuntimeError/ValueError before
    anything is added to the scene when the file or the settings are bad.
    `progress(fraction)` is called as objects are created.
    """
    path = pathlib.Path(filepath)
    model, data = io.read_source(path)
    scale = scene_scale(model, context.scene, settings.scale)
    tolerance = settings.relative_tolerance if settings.relative else settings.tolerance / scale
    result = io.tessellate(model, tolerance, relative=settings.relative, angle=settings.angle,
                           mode=settings.mode, trim_method=settings.trim_method, scale=scale,
                           split=settings.split, stem=path.stem)
    text = stored_source.store(path.name, data)
    collection = context.collection
    objects = []
    for k, part in enumerate(result.parts):
        me = blender_mesh.create_mesh(part, smooth=settings.smooth, exact_normals=settings.exact_normals)
        obj = bpy.data.objects.new(part.name, me)
        collection.objects.link(obj)
        props = obj.trimkit
        props.source = text
        props.source_name = path.name
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
        record_stats(props, part, result)
        objects.append(obj)
        if progress:
            progress((k + 1) / len(result.parts))
    for obj in context.view_layer.objects.selected:
        obj.select_set(False)
    for obj in objects:
        obj.select_set(True)
    if objects:
        context.view_layer.objects.active = objects[0]
    return objects, result


def record_stats(props, part, result):
    faces = set(int(f) for f in set(part.face_ids.tolist()))
    failed = [(f, reason) for f, reason in result.failed_faces if part.kind == "MODEL" or f in faces]
    props.faces = len(faces) + len(failed)
    props.triangles = len(part.triangles)
    props.seconds = result.seconds
    props.failed_faces = len(failed)
    props.failed_report = "; ".join(f"face {f}: {reason}" for f, reason in failed)[:1000]


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
    for k, obj in enumerate(tbp if not render else []):
        tbp_objects.remesh(obj)
        if progress:
            progress((k + 1) / (len(tbp) + len(objects)))
    groups = {}
    for obj in objects:
        p = obj.trimkit
        key = (p.source.name, object_tolerance(p, render), p.angle, p.mode, p.trim_method, p.scale)
        groups.setdefault(key, []).append(obj)
    results = []
    for k, (key, members) in enumerate(groups.items()):
        props = members[0].trimkit
        model = io.read_bytes(stored_source.load(props.source), stored_source.file_name(props.source))
        tolerance, relative = key[1]
        result = io.tessellate(model, tolerance, relative=relative, angle=props.angle, mode=props.mode,
                               trim_method=props.trim_method, scale=props.scale,
                               parts=[(o.trimkit.part, o.trimkit.part_index) for o in members])
        for obj, part in zip(members, result.parts):
            blender_mesh.replace_mesh(obj, part, obj.trimkit.smooth, obj.trimkit.exact_normals)
            if not render:
                if obj.trimkit.relative:
                    obj.trimkit.tolerance = result.tolerance * obj.trimkit.scale
                record_stats(obj.trimkit, part, result)
        results.append(result)
        if progress:
            progress((k + 1) / len(groups))
    return results
