"""object.trimkit_check: the deviation of a trimkit object's mesh from its stored exact
faces (what `trimkit check` measures), written onto the mesh: a face attribute
`trimkit_deviation` (each polygon gets its CAD face's larger deviation, scene units)
and a corner colour attribute `trimkit_check` (green within half the tolerance,
yellow at the tolerance, red beyond), plus a one-line summary on the object."""
import bpy
import numpy as np

from . import io, stored_source

DEVIATION_ATTRIBUTE = "trimkit_deviation"
COLOR_ATTRIBUTE = "trimkit_check"


def mesh_arrays(me):
    """(positions (n,3), triangles (m,3), polygon of each triangle) of a Blender mesh."""
    me.calc_loop_triangles()
    positions = np.empty(3 * len(me.vertices), np.float32)
    me.vertices.foreach_get("co", positions)
    triangles = np.empty(3 * len(me.loop_triangles), np.uint32)
    me.loop_triangles.foreach_get("vertices", triangles)
    polygons = np.empty(len(me.loop_triangles), np.uint32)
    me.loop_triangles.foreach_get("polygon_index", polygons)
    return positions.reshape(-1, 3), triangles.reshape(-1, 3).astype(np.int32), polygons


def polygon_faces(me):
    """The `cad_face` of every polygon; ValueError when the mesh has none."""
    attribute = me.attributes.get("cad_face")
    if attribute is None or attribute.domain != 'FACE':
        raise ValueError(f"{me.name}: no cad_face attribute (re-tessellate the object first)")
    values = np.empty(len(me.polygons), np.int32)
    attribute.data.foreach_get("value", values)
    return values


def check_object(obj):
    """Measures obj's mesh against its stored faces and writes the attributes.
    Returns (report, tolerance in model units)."""
    props = obj.trimkit
    model = io.read_bytes(stored_source.load(props.source), stored_source.file_name(props.source))
    me = obj.data
    positions, triangles, polygons = mesh_arrays(me)
    cad_face = polygon_faces(me)
    faces = io.part_faces(model, props.part, props.part_index)
    faces = list(range(len(model.faces))) if faces is None else faces
    report = io.measure(model, positions / props.scale, triangles, cad_face[polygons], faces)
    tolerance = props.tolerance / props.scale
    per_face = face_deviations(report, faces, len(model.faces))
    write_attributes(me, per_face[cad_face] * props.scale, per_face[cad_face] / tolerance)
    props.check_report = summary(report, tolerance)
    return report, tolerance


def face_deviations(report, faces, count):
    """Largest deviation of each model face in either direction (model units); faces
    without triangles (not meshed) are infinitely far."""
    out = np.zeros(count)
    for k, face in enumerate(faces):
        a, b = report.face_mesh_to_surface[k], report.face_surface_to_mesh[k]
        out[face] = np.inf if np.isnan(a) else max(a, b)
    return out


def write_attributes(me, deviation, ratio):
    for name in (DEVIATION_ATTRIBUTE, COLOR_ATTRIBUTE):
        old = me.attributes.get(name)
        if old is not None:
            me.attributes.remove(old)
    values = me.attributes.new(DEVIATION_ATTRIBUTE, 'FLOAT', 'FACE')
    values.data.foreach_set("value", np.nan_to_num(deviation, posinf=np.finfo(np.float32).max).astype(np.float32))
    colors = me.attributes.new(COLOR_ATTRIBUTE, 'FLOAT_COLOR', 'CORNER')
    loop_total = np.empty(len(me.polygons), np.uint32)
    me.polygons.foreach_get("loop_total", loop_total)
    loop_polygon = np.repeat(np.arange(len(me.polygons)), loop_total)
    colors.data.foreach_set("color", ramp(ratio)[loop_polygon].ravel())
    if hasattr(me, "color_attributes"):
        me.color_attributes.active_color = colors


def ramp(ratio):
    """(k, 4) RGBA: green up to 0.5, yellow at 1, red above 1 (ratio = deviation / tolerance)."""
    t = np.clip(np.nan_to_num(ratio, posinf=2.0), 0.0, 2.0)
    red = np.clip(2.0 * t - 1.0, 0.0, 1.0)
    green = np.where(t <= 1.0, 1.0, np.clip(2.0 - t, 0.0, 1.0))
    return np.stack([red, green, np.zeros_like(t), np.ones_like(t)], axis=1).astype(np.float32)


def summary(report, tolerance):
    return (f"mesh->surface {report.mesh_to_surface / tolerance:.2f} T, surface->mesh "
            f"{report.surface_to_mesh / tolerance:.2f} T, area ratio {report.area_ratio:.5f}, "
            f"{report.open_edges} open edges")
