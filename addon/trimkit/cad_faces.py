"""Picking CAD faces in Edit Mode: every mesh face of the active face's `cad_face`,
and the CAD faces like the selected ones (the same kind of surface, about the same
area). Areas are the mesh's own (object space), compared relatively."""
import bmesh
import numpy as np

from . import io, stored_source

FACE_ATTRIBUTE = "cad_face"


def face_layer(bm, obj):
    layer = bm.faces.layers.int.get(FACE_ATTRIBUTE)
    if layer is None:
        raise ValueError(f"{obj.name}: no cad_face attribute (re-tessellate the object first)")
    return layer


def select_cad_face(obj, extend=False):
    """Selects the mesh faces of the active face's CAD face. Returns ([cad face], faces selected)."""
    bm = bmesh.from_edit_mesh(obj.data)
    layer = face_layer(bm, obj)
    active = bm.faces.active
    if active is None:
        selected = [f for f in bm.faces if f.select]
        if not selected:
            raise ValueError(f"{obj.name}: no active face; click a face first")
        active = selected[-1]
    target = active[layer]
    count = select_faces(bm, obj, layer, {target}, extend)
    return [target], count


def selected_cad_faces(obj):
    """The CAD faces (cad_face values) of the selected mesh faces, in Edit Mode."""
    bm = bmesh.from_edit_mesh(obj.data)
    layer = face_layer(bm, obj)
    return sorted({f[layer] for f in bm.faces if f.select})


def select_faces(bm, obj, layer, wanted, extend):
    count = 0
    for face in bm.faces:
        hit = face[layer] in wanted
        if hit or not extend:
            face.select_set(hit)
        count += hit
    bm.select_flush_mode()
    bmesh.update_edit_mesh(obj.data, loop_triangles=False, destructive=False)
    return count


def select_similar(obj, threshold=0.02, kind_only=False):
    """Selects the CAD faces of obj's part with the surface kind of a selected CAD face
    and (unless kind_only) an area within `threshold` of its. Returns (cad faces, mesh faces)."""
    bm = bmesh.from_edit_mesh(obj.data)
    layer = face_layer(bm, obj)
    model = io.read_bytes(stored_source.load(obj.trimkit.source), stored_source.file_name(obj.trimkit.source))
    areas = {}
    chosen = set()
    for face in bm.faces:
        k = face[layer]
        areas[k] = areas.get(k, 0.0) + face.calc_area()
        if face.select:
            chosen.add(k)
    if not chosen:
        raise ValueError(f"{obj.name}: select a face first")
    kinds = {k: str(model.faces[k].surface_kind) for k in areas}
    wanted = {k for k in areas for c in chosen
              if kinds[k] == kinds[c] and (kind_only or similar_area(areas[k], areas[c], threshold))}
    count = select_faces(bm, obj, layer, wanted, False)
    return sorted(wanted), count


def similar_area(a, b, threshold):
    return abs(a - b) <= threshold * max(a, b)
