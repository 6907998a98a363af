"""The one module that turns io.MeshPart arrays into Blender meshes, with
foreach_set only (no per-vertex Python loops): vertices, triangle loops and
polygons, a UV map (one island per CAD face, seams on face boundaries), custom
split normals from the exact surface, sharp edges where the CAD faces break,
an integer face attribute `cad_face` and materials from CAD colours.
"""
import bpy
import numpy as np

from . import io

UV_NAME = "UVMap"
FACE_ATTRIBUTE = "cad_face"
# Blender 4.1 removed Mesh.use_auto_smooth; custom normals then work without it.
HAS_AUTO_SMOOTH = bpy.app.version < (4, 1, 0)
# Blender 4.0 made MeshPolygon.loop_total read-only (derived from loop_start).
SET_LOOP_TOTAL = bpy.app.version < (4, 0, 0)


def create_mesh(part, name=None, smooth=True, exact_normals=True):
    """A new bpy.types.Mesh from an io.MeshPart. `exact_normals`: custom split normals
    from the exact surface (Blender converts them element by element, see
    set_custom_normals); without them smooth shading uses Blender's own normals,
    split at the sharp edges."""
    me = bpy.data.meshes.new(name or part.name)
    n, m = len(part.positions), len(part.triangles)
    me.vertices.add(n)
    me.vertices.foreach_set("co", np.ascontiguousarray(part.positions, np.float32).ravel())
    me.loops.add(3 * m)
    me.loops.foreach_set("vertex_index", np.ascontiguousarray(part.triangles, np.int32).ravel())
    me.polygons.add(m)
    me.polygons.foreach_set("loop_start", np.arange(0, 3 * m, 3, dtype=np.int32))
    if SET_LOOP_TOTAL:
        me.polygons.foreach_set("loop_total", np.full(m, 3, np.int32))
    me.polygons.foreach_set("use_smooth", np.full(m, smooth, bool))
    me.update(calc_edges=True)

    mark_edges(me, part)
    uv = me.uv_layers.new(name=UV_NAME)
    uv.data.foreach_set("uv", np.ascontiguousarray(part.corner_uvs, np.float32).ravel())
    attribute = me.attributes.new(FACE_ATTRIBUTE, 'INT', 'FACE')
    attribute.data.foreach_set("value", np.ascontiguousarray(part.face_ids, np.int32))
    assign_materials(me, part)
    if smooth:
        if HAS_AUTO_SMOOTH:
            me.use_auto_smooth = True
            me.auto_smooth_angle = np.pi
        if exact_normals:
            set_custom_normals(me, part)
    me.update()
    return me


def set_custom_normals(me, part):
    """Custom split normals from part.corner_normals. Blender 3.4 converts them
    element by element, so when every vertex's corners share one normal (smooth
    CAD faces, one patch per vertex) it gets the per-vertex array, 1/6 of the
    floats; otherwise (vertices welded across creases) the per-corner one."""
    corners = np.ascontiguousarray(part.corner_normals, np.float32)
    vertex_normals = vertex_normals_if_shared(part.triangles, corners, len(part.positions))
    if vertex_normals is None:
        me.normals_split_custom_set(corners)
    else:
        me.normals_split_custom_set_from_vertices(vertex_normals)


def vertex_normals_if_shared(triangles, corner_normals, n):
    """(n, 3) float32 normals when all corners of each vertex have exactly the same
    normal (unused vertices get zero, Blender's "automatic"), else None."""
    corners = np.asarray(triangles).ravel()
    vertex_normals = np.zeros((n, 3), np.float32)
    vertex_normals[corners] = corner_normals
    if not np.array_equal(vertex_normals[corners], corner_normals):
        return None
    return vertex_normals


def mark_edges(me, part):
    """UV seams on CAD face boundaries, sharp edges where the normals break."""
    count = len(me.edges)
    if count == 0 or len(part.edges) == 0:
        return
    vertices = np.empty(2 * count, np.int32)
    me.edges.foreach_get("vertices", vertices)
    n = np.int64(len(me.vertices))
    keys = edge_keys(vertices.reshape(-1, 2), n)
    flagged = edge_keys(part.edges, n)
    order = np.argsort(keys)
    found = np.searchsorted(keys, flagged, sorter=order)
    found = np.minimum(found, count - 1)
    index = order[found]
    hit = keys[index] == flagged
    seam = np.zeros(count, bool)
    sharp = np.zeros(count, bool)
    seam[index[hit & (part.edge_flags & io.EDGE_FACE_BOUNDARY != 0)]] = True
    sharp[index[hit & (part.edge_flags & io.EDGE_SHARP != 0)]] = True
    me.edges.foreach_set("use_seam", seam)
    me.edges.foreach_set("use_edge_sharp", sharp)


def edge_keys(pairs, n):
    pairs = np.sort(pairs.astype(np.int64), axis=1)
    return pairs[:, 0] * n + pairs[:, 1]


def assign_materials(me, part):
    for name, rgb in part.materials:
        me.materials.append(material(name, rgb))
    if len(part.materials) > 1:
        me.polygons.foreach_set("material_index", np.ascontiguousarray(part.material_index, np.int32))


def material(name, rgb):
    """The material called `name`, created with base colour `rgb` when missing."""
    mat = bpy.data.materials.get(name)
    if mat is None:
        mat = bpy.data.materials.new(name)
        mat.diffuse_color = (*rgb, 1.0)  # viewport and Workbench colour
        mat.use_nodes = True
        bsdf = mat.node_tree.nodes.get("Principled BSDF")
        if bsdf is not None:
            bsdf.inputs["Base Color"].default_value = (*rgb, 1.0)
    return mat


def replace_mesh(obj, part, smooth=True, exact_normals=True):
    """Gives `obj` a new mesh built from `part`; the old one is removed when unused."""
    old = obj.data
    name = old.name
    obj.data = create_mesh(part, name, smooth, exact_normals)
    if old.users == 0:
        bpy.data.meshes.remove(old)
        obj.data.name = name
