"""Levels of detail of a CAD object: a chain of new objects <name>_LOD0, _LOD1, ...
(the suffix Unreal and Unity group by) meshed from the stored geometry at tolerances
T, T f, T f^2, ... (T: the object's tolerance, f: the factor), each a trimkit object of
its own (re-meshable, checkable), sharing the source's materials by CAD face and one
UV layout (LOD0's: a face's parameter point has the same UV at every level)."""
import bpy

from . import blender_mesh, importer, io, stored_source, uv_layout

# Object.trimkit fields an LOD takes from its source.
COPIED = ("source", "source_name", "kind", "part", "part_index", "scale", "origin", "units", "angle", "mode",
          "trim_method", "smooth", "exact_normals", "uv_mode")


def lod_name(obj, level):
    return f"{obj.name}_LOD{level}"


def make_lods(context, obj, count, factor=4.0):
    """Makes (or re-makes) obj's chain of `count` levels; hides obj, whose place LOD0
    takes. Returns the LOD objects, finest first. ValueError for a bad count or factor."""
    if count < 1 or not factor > 1.0:
        raise ValueError(f"{obj.name}: LODs need at least 1 level and a factor above 1 (got {count}, {factor})")
    props = obj.trimkit
    model = io.read_bytes(stored_source.load(props.source), stored_source.file_name(props.source))
    part_key = importer.object_part(obj)
    layout = uv_layout.layout_from_json(props.uv_layout) if props.uv_mode == 'REAL' else None
    chain, lines = [], []
    for level in range(count):
        tolerance = props.tolerance * factor ** level  # Blender units
        result, share = within_tolerance(model, tolerance / props.scale, props, part_key, layout)
        part = result.parts[0]
        layout = layout or part.uv_layout
        lod = lod_object(context, obj, level)
        me = blender_mesh.create_mesh(importer.shifted(part, props.origin), lod_name(obj, level), props.smooth,
                                      props.exact_normals)
        blender_mesh.carry_over(obj.data, me)
        old = lod.data
        lod.data = me
        if old is not None and old.users == 0:
            bpy.data.meshes.remove(old)
            me.name = lod_name(obj, level)
        for name in COPIED:
            setattr(lod.trimkit, name, getattr(props, name))
        lod.trimkit.tolerance = tolerance
        lod.trimkit.relative = False
        lod.trimkit.render_tolerance = 0.0
        lod.trimkit.lod_level = level
        lod.trimkit.lod_source = obj.name
        lod.trimkit.uv_layout = uv_layout.layout_to_json(part.uv_layout) if part.uv_layout else ""
        importer.record_stats(lod.trimkit, part, result)
        for key in obj.keys():
            if key.startswith("trimkit_"):
                lod[key] = obj[key]
        importer.update_tolerance_metadata(lod)
        chain.append(lod)
        lines.append(f"LOD{level} {lod.trimkit.triangles} triangles at {tolerance:.4g}" +
                     (f" (meshed at {share:.2f} of it to stay within it)" if share < 1.0 else ""))
    props.lod_report = "; ".join(lines)
    obj.hide_set(True)
    return chain


# Re-meshes of a level whose measured deviation exceeds its tolerance, at most.
TIGHTEN_ROUNDS = 4
# Each re-mesh asks for the tolerance over the measured excess, with this margin.
TIGHTEN_MARGIN = 1.1


def within_tolerance(model, tolerance, props, part_key, layout):
    """(io.Tessellation, share of `tolerance` asked for) of the object's part whose
    two-sided deviation from the exact faces, measured, is within `tolerance` (model
    units): the tessellator's own bound can be exceeded at coarse tolerances, so each
    level is measured and, if over, meshed again at a proportionally smaller one.
    RuntimeError if TIGHTEN_ROUNDS re-meshes do not get there."""
    share = 1.0
    for _ in range(TIGHTEN_ROUNDS + 1):
        result = io.tessellate(model, share * tolerance, angle=props.angle, mode=props.mode,
                               trim_method=props.trim_method, scale=props.scale, parts=[part_key],
                               uv_mode=props.uv_mode, metres=importer.object_metres(props),
                               uv_layouts={part_key: layout} if layout else None)
        part = result.parts[0]
        if len(part.triangles) == 0:
            return result, share
        faces = io.part_faces(model, *part_key)
        report = io.measure(model, part.positions / props.scale, part.triangles, part.face_ids,
                            faces if faces is not None else range(len(model.faces)))
        excess = max(report.mesh_to_surface, report.surface_to_mesh) / tolerance
        if excess <= 1.0:
            return result, share
        share /= excess * TIGHTEN_MARGIN
    raise RuntimeError(f"{props.source_name}: a level of detail at tolerance {tolerance:.4g} is still "
                       f"{excess:.2f}x off after {TIGHTEN_ROUNDS} re-meshes")


def lod_object(context, obj, level):
    """The LOD object of that level: the one made before, or a new one beside obj."""
    name = lod_name(obj, level)
    lod = bpy.data.objects.get(name)
    if lod is not None and lod.trimkit.lod_source == obj.name:
        return lod
    me = bpy.data.meshes.new(name)
    lod = bpy.data.objects.new(name, me)
    for collection in obj.users_collection or [context.collection]:
        collection.objects.link(lod)
    lod.parent = obj.parent
    lod.matrix_world = obj.matrix_world.copy()
    return lod
