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
# MeshLoop.vertex_index / edge_index, MeshPolygon.loop_start / loop_total and
# MeshEdge.vertices are unsigned in RNA: foreach_set/get copy a uint32 buffer in one
# block and convert an int32 one element by element (3.4: 0.16 s -> 0.01 s for 3M loops).
INDEX = np.uint32


def create_mesh(part, name=None, smooth=True, exact_normals=True):
    """A new bpy.types.Mesh from an io.MeshPart. `exact_normals`: custom split normals
    from the exact surface (see set_custom_normals); without them smooth shading uses
    Blender's own normals, split at the sharp edges."""
    me = bpy.data.meshes.new(name or part.name)
    add_triangles(me, part, smooth)
    add_edges(me, part)
    mark_edges(me, part)
    add_uv_map(me, part)
    add_face_attribute(me, part)
    assign_materials(me, part)
    if smooth:
        set_smooth_normals(me, part, exact_normals)
    me.update()  # tags the new edge flags and normals for redraw; costs nothing measurable
    return me


# The steps of create_mesh, in order (bench/blender_import.py times each).
STEPS = ("add_triangles", "add_edges", "mark_edges", "add_uv_map", "add_face_attribute", "assign_materials",
         "set_smooth_normals")


def add_triangles(me, part, smooth):
    """Vertices, one loop per triangle corner and one polygon per triangle."""
    n, m = len(part.positions), len(part.triangles)
    me.vertices.add(n)
    me.vertices.foreach_set("co", np.ascontiguousarray(part.positions, np.float32).ravel())
    me.loops.add(3 * m)
    me.loops.foreach_set("vertex_index", np.ascontiguousarray(part.triangles, INDEX).ravel())
    me.polygons.add(m)
    me.polygons.foreach_set("loop_start", np.arange(0, 3 * m, 3, dtype=INDEX))
    if SET_LOOP_TOTAL:
        me.polygons.foreach_set("loop_total", np.full(m, 3, INDEX))
    me.polygons.foreach_set("use_smooth", np.full(m, smooth, bool))


def add_edges(me, part):
    """Edges and each loop's edge from the native edge map (linear, 0.1 s for 1M
    triangles), set with foreach_set; Blender's update(calc_edges=True) took 0.5-1 s."""
    native = io.native()
    if not hasattr(native, "edge_map"):  # a module built before edge_map
        me.update(calc_edges=True)
        return
    edges, corner_edges = native.edge_map(part.triangles, len(part.positions))
    me.edges.add(len(edges))
    me.edges.foreach_set("vertices", edges.ravel())
    me.loops.foreach_set("edge_index", corner_edges)


def add_uv_map(me, part):
    uv = me.uv_layers.new(name=UV_NAME)
    uv.data.foreach_set("uv", np.ascontiguousarray(part.corner_uvs, np.float32).ravel())


def add_face_attribute(me, part):
    attribute = me.attributes.new(FACE_ATTRIBUTE, 'INT', 'FACE')
    attribute.data.foreach_set("value", np.ascontiguousarray(part.face_ids, np.int32))


def set_smooth_normals(me, part, exact_normals):
    """Auto smooth at 180 degrees (before 4.1), so that only sharp edges split the
    normals, and the exact custom normals when asked."""
    if HAS_AUTO_SMOOTH:
        me.use_auto_smooth = True
        me.auto_smooth_angle = np.pi
    if exact_normals:
        set_custom_normals(me, part)


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
    normal (unused vertices get zero, Blender's "automatic"), else None. Each normal
    is moved and compared as one 12-byte item (bit for bit), twice as fast as rows."""
    corners = np.asarray(triangles).ravel()
    items = np.ascontiguousarray(corner_normals, np.float32).view(NORMAL_ITEM).ravel()
    vertex_normals = np.zeros((n, 3), np.float32)
    vertex_items = vertex_normals.view(NORMAL_ITEM).ravel()
    vertex_items[corners] = items
    if not np.array_equal(vertex_items[corners], items):
        return None
    return vertex_normals


NORMAL_ITEM = np.dtype((np.void, 3 * 4))  # three float32


def mark_edges(me, part):
    """UV seams on CAD face boundaries, sharp edges where the normals break."""
    count = len(me.edges)
    if count == 0 or len(part.edges) == 0:
        return
    index = flagged_edge_indices(me, part)
    found = index >= 0
    seam = np.zeros(count, bool)
    sharp = np.zeros(count, bool)
    seam[index[found & (part.edge_flags & io.EDGE_FACE_BOUNDARY != 0)]] = True
    sharp[index[found & (part.edge_flags & io.EDGE_SHARP != 0)]] = True
    me.edges.foreach_set("use_seam", seam)
    me.edges.foreach_set("use_edge_sharp", sharp)


def flagged_edge_indices(me, part):
    """Index into me.edges of each flagged edge (part.edges), -1 where the mesh has none.
    Only the edges with both ends on flagged edges are sorted."""
    vertices = np.empty(2 * len(me.edges), INDEX)
    me.edges.foreach_get("vertices", vertices)
    vertices = vertices.reshape(-1, 2)
    touched = np.zeros(len(part.positions), bool)
    touched[part.edges.ravel()] = True
    candidates = np.flatnonzero(touched[vertices[:, 0]] & touched[vertices[:, 1]])
    if len(candidates) == 0:
        return np.full(len(part.edges), -1, np.int64)
    n = len(part.positions)
    keys = edge_keys(vertices[candidates], n)
    order = np.argsort(keys)
    wanted = edge_keys(part.edges, n)
    at = order[np.minimum(np.searchsorted(keys, wanted, sorter=order), len(keys) - 1)]
    return np.where(keys[at] == wanted, candidates[at], -1)


def edge_keys(pairs, n):
    """One int64 per unordered vertex pair."""
    a = pairs[:, 0].astype(np.int64)
    b = pairs[:, 1].astype(np.int64)
    return np.minimum(a, b) * n + np.maximum(a, b)


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
    replace_shared_mesh([obj], part, smooth, exact_normals)


def replace_shared_mesh(objects, part, smooth=True, exact_normals=True):
    """Gives `objects` (the users of one mesh) one new mesh built from `part`, keeping
    the old mesh's name, its materials by CAD face (carry_over) and its custom
    properties; the old one is removed when unused. The objects themselves (their
    transforms, modifiers, custom properties, object-linked material slots) are
    untouched."""
    old = objects[0].data
    name = old.name
    me = create_mesh(part, name, smooth, exact_normals)
    carry_over(old, me)
    for obj in objects:
        obj.data = me
    if old.users == 0:
        bpy.data.meshes.remove(old)
        me.name = name


def cad_face_materials(me):
    """{cad_face: material slot index} of an existing mesh: each CAD face's most used slot."""
    attribute = me.attributes.get(FACE_ATTRIBUTE)
    if attribute is None or attribute.domain != 'FACE' or len(me.polygons) == 0:
        return {}
    faces = np.empty(len(me.polygons), np.int32)
    attribute.data.foreach_get("value", faces)
    slots = np.empty(len(me.polygons), np.int32)
    me.polygons.foreach_get("material_index", slots)
    pairs, counts = np.unique(np.stack([faces, slots], 1), axis=0, return_counts=True)
    out = {}
    for (face, slot), count in sorted(zip(map(tuple, pairs.tolist()), counts.tolist()), key=lambda x: x[1]):
        out[face] = slot  # the most used slot comes last
    return out


def carry_over(old, me):
    """What the user did to `old` that survives a re-mesh into `me`: its material slots
    in order, each CAD face's material (by `cad_face`; a face new to the mesh gets the
    material the importer gives it), and the mesh's custom properties."""
    by_face = cad_face_materials(old)
    if len(old.materials):
        fresh = list(me.materials)
        fresh_index = np.empty(len(me.polygons), np.int32)
        me.polygons.foreach_get("material_index", fresh_index)
        me.materials.clear()
        for mat in old.materials:
            me.materials.append(mat)
        slots = {}
        for k, mat in enumerate(fresh):  # the importer's materials, found or appended
            found = [i for i, m in enumerate(me.materials) if m == mat]
            if not found:
                me.materials.append(mat)
                found = [len(me.materials) - 1]
            slots[k] = found[0]
        faces = np.empty(len(me.polygons), np.int32)
        me.attributes[FACE_ATTRIBUTE].data.foreach_get("value", faces)
        table = np.array([slots[k] for k in range(len(fresh))] or [0], np.int32)
        index = table[np.clip(fresh_index, 0, len(table) - 1)]
        if by_face:
            keys = np.array(sorted(by_face), np.int32)
            values = np.array([by_face[k] for k in keys.tolist()], np.int32)
            at = np.minimum(np.searchsorted(keys, faces), len(keys) - 1)
            known = keys[at] == faces
            index[known] = values[at[known]]
        me.polygons.foreach_set("material_index", index)
    for key in old.keys():
        if key not in me.keys():
            me[key] = old[key]
