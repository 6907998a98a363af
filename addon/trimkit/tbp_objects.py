"""TBP solids as Blender objects: import a .tbp file, turn a closed mesh into a
PN-triangle solid, trim one TBP object by another, and re-mesh them from the
solids stored in the .blend (stored_source, like CAD files). Geometry is in the
object's local coordinates (Object.trimkit.scale stays 1). Every function
computes first and touches the scene only once nothing can fail, so an error
leaves the scene unchanged.

Trim result: a new object "<target> trimmed" with the target's transform; the
target is hidden (not deleted), the tool left as it is. The result keeps both
solids (its source and tool_source) and the tool's placement, so it re-meshes at
other levels/lod, or with the other side kept, after save and reload.
"""
import pathlib

import bpy
import numpy as np

from . import blender_mesh, stored_source, tbp_io


def is_tbp(obj):
    """An object polygonized from a TBP solid it stores (a possible trim target or tool)."""
    return obj is not None and obj.type == 'MESH' and obj.trimkit.kind == 'TBP' and obj.trimkit.source is not None


def is_tbp_kind(obj):
    return obj is not None and obj.type == 'MESH' and obj.trimkit.kind in ('TBP', 'TBP_TRIM') \
        and obj.trimkit.source is not None


def stored_solid(text):
    return tbp_io.tbp_from_bytes(stored_source.load(text), stored_source.file_name(text))


def record(props, patches, triangles, seconds):
    props.faces = patches
    props.triangles = triangles
    props.seconds = seconds
    props.failed_faces = 0
    props.failed_report = ""


def link_new(context, name, part, matrix=None):
    me = blender_mesh.create_mesh(part, name, smooth=True, exact_normals=True)
    obj = bpy.data.objects.new(name, me)
    context.collection.objects.link(obj)
    if matrix is not None:
        obj.matrix_world = matrix
    for other in context.view_layer.objects.selected:
        other.select_set(False)
    obj.select_set(True)
    context.view_layer.objects.active = obj
    return obj


def set_tbp_props(obj, text, name, levels, lod, kind='TBP'):
    props = obj.trimkit
    props.kind = kind
    props.source = text
    props.source_name = name
    props.part = 'MODEL'
    props.part_index = -1
    props.scale = 1.0
    props.tbp_levels = levels
    props.tbp_lod = lod


def estimate_report(name, patches, levels, lod):
    """The triangle estimate at levels/lod, and the warning above tbp_io.TBP_WARN_TRIANGLES
    on a second line (Object.trimkit.import_report of TBP objects)."""
    return "\n".join(line for line in tbp_io.tbp_estimate_lines(name, patches, levels, lod) if line)


def import_tbp(context, filepath, levels, lod):
    """A new object polygonized from a .tbp file; returns (object, tbp_io.TbpMeshing).
    Its trimkit.import_report holds the estimate (estimate_report)."""
    path = pathlib.Path(filepath)
    solid, data = tbp_io.read_tbp_source(path)
    name = solid.name or path.stem
    report = estimate_report(name, len(solid), levels, lod)  # before the work
    meshing = tbp_io.tbp_mesh(solid, levels, lod, name=name)
    text = stored_source.store(path.name, data)
    obj = link_new(context, name, meshing.part)
    set_tbp_props(obj, text, path.name, levels, lod)
    record(obj.trimkit, meshing.patches, meshing.triangles, meshing.seconds)
    obj.trimkit.import_report = report
    return obj, meshing


def mesh_arrays(context, obj):
    """(positions, triangles, sharp edges) of `obj`'s evaluated mesh (modifiers applied),
    local coordinates; sharp edges: (k, 2) vertex indices of the edges marked sharp."""
    evaluated = obj.evaluated_get(context.evaluated_depsgraph_get())
    me = evaluated.to_mesh()
    try:
        me.calc_loop_triangles()
        positions = np.empty(3 * len(me.vertices), np.float64)
        me.vertices.foreach_get("co", positions)
        triangles = np.empty(3 * len(me.loop_triangles), np.int32)
        me.loop_triangles.foreach_get("vertices", triangles)
        sharp = np.zeros(len(me.edges), bool)
        me.edges.foreach_get("use_edge_sharp", sharp)
        edges = np.empty(2 * len(me.edges), np.int32)
        me.edges.foreach_get("vertices", edges)
    finally:
        evaluated.to_mesh_clear()
    return positions.reshape(-1, 3), triangles.reshape(-1, 3), edges.reshape(-1, 2)[sharp]


def mesh_to_tbp(context, obj, levels, lod, sharp_angle=tbp_io.TBP_SHARP_ANGLE, marked_sharp=True):
    """A new TBP object (cubic PN triangles, creases above `sharp_angle` kept, and along
    the edges marked sharp when `marked_sharp`) from a closed mesh object, with its
    transform; the source mesh is hidden."""
    positions, triangles, sharp_edges = mesh_arrays(context, obj)
    name = f"{obj.name} TBP"
    solid = tbp_io.mesh_to_tbp(positions, triangles, name, sharp_angle, sharp_edges if marked_sharp else None)
    report = estimate_report(name, len(solid), levels, lod)
    meshing = tbp_io.tbp_mesh(solid, levels, lod, name=name)
    file_name = f"{name}.tbp"
    text = stored_source.store(file_name, tbp_io.tbp_bytes(solid))
    new = link_new(context, name, meshing.part, obj.matrix_world.copy())
    set_tbp_props(new, text, file_name, levels, lod)
    record(new.trimkit, meshing.patches, meshing.triangles, meshing.seconds)
    new.trimkit.import_report = report
    obj.hide_set(True)
    return new, meshing


def tool_matrix(target, tool):
    """Tool's local coordinates to the target's, as a 4x4 numpy array."""
    return np.array(target.matrix_world.inverted() @ tool.matrix_world)


def source_resolution(obj):
    """(levels, lod) the TBP object `obj` was polygonized at: a trim of it at these is as
    dense as it (rather than a fixed default, which can be many times denser)."""
    return obj.trimkit.tbp_levels, obj.trimkit.tbp_lod


def trim_estimate(target, levels, lod):
    """tbp_io.tbp_estimate_lines of trimming `target` at levels/lod (before the work)."""
    return tbp_io.tbp_estimate_lines(target.name, target.trimkit.faces, levels, lod)


def trim(context, target, tool, keep, levels, lod):
    """A new object: `target`'s patches trimmed against the solid of `tool`; returns (object, tbp_io.TbpTrim).
    The new object's trimkit.import_report holds the estimate (and the warning above
    tbp_io.TBP_WARN_TRIANGLES)."""
    if not is_tbp(target) or not is_tbp(tool):
        raise ValueError("trim needs two TBP solid objects (import a .tbp or use Mesh to TBP)")
    if target == tool:
        raise ValueError("the target and the tool are the same object")
    matrix = tool_matrix(target, tool)
    result = trim_solids(target.trimkit.source, tool.trimkit.source, matrix, keep, levels, lod,
                         f"{target.name} trimmed")
    if not len(result.part.triangles):
        raise ValueError(f"nothing of {target.name} is {keep} {tool.name}")
    obj = link_new(context, result.part.name, result.part, target.matrix_world.copy())
    set_tbp_props(obj, target.trimkit.source, target.trimkit.source_name, levels, lod, kind='TBP_TRIM')
    props = obj.trimkit
    props.keep = keep
    props.tool_source = tool.trimkit.source
    props.tool_name = tool.name
    props.tool_matrix = matrix.ravel().tolist()
    record(props, len(stored_solid(target.trimkit.source)), result.triangles, result.seconds)
    props.import_report = estimate_report(target.name, target.trimkit.faces, levels, lod)
    target.hide_set(True)
    return obj, result


def trim_solids(target_text, tool_text, matrix, keep, levels, lod, name):
    target = stored_solid(target_text)
    tool = tbp_io.transform_tbp(stored_solid(tool_text), matrix)
    return tbp_io.tbp_trim(target, tool, keep, levels, lod, name=name)


def remesh(obj):
    """Re-meshes a TBP or trimmed-TBP object from its stored solids at its levels/lod."""
    props = obj.trimkit
    if props.kind == 'TBP_TRIM':
        matrix = np.array(props.tool_matrix, np.float64).reshape(4, 4)
        result = trim_solids(props.source, props.tool_source, matrix, props.keep, props.tbp_levels,
                             props.tbp_lod, obj.name)
        patches = len(stored_solid(props.source))
    else:
        result = tbp_io.tbp_mesh(stored_solid(props.source), props.tbp_levels, props.tbp_lod, name=obj.name)
        patches = result.patches
    props.import_report = estimate_report(obj.name, patches, props.tbp_levels, props.tbp_lod)
    blender_mesh.replace_mesh(obj, result.part, props.smooth, props.exact_normals)
    record(props, patches, result.triangles, result.seconds)
    return result
