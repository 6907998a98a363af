"""Object.trimkit: the settings and statistics of a mesh made from CAD geometry."""
import math

import bpy
from bpy.props import (BoolProperty, EnumProperty, FloatProperty, FloatVectorProperty, IntProperty,
                       PointerProperty, StringProperty)

from .settings import DEFAULTS

MODE_ITEMS = [
    ('guaranteed', "Guaranteed", "Every mesh point within the tolerance of the exact surface (conservative bound)"),
    ('approximate', "Approximate", "The same bound from surface samples: fewer triangles, no strict guarantee"),
]
TRIM_ITEMS = [
    ('bezier3d', "Bézier 3D", "Trim curves lifted to 3D Bézier curves, line-distance bound"),
    ('yang', "Yang", "Trim curve step length from derivative bounds"),
    ('param', "Parameter", "Chords in parameter space (baseline, no 3D guarantee)"),
]
KIND_ITEMS = [
    ('CAD', "CAD", "Meshed from a CAD file (IGES, STEP)"),
    ('TBP', "TBP Solid", "Polygonized from a solid of triangular Bézier patches"),
    ('TBP_TRIM', "Trimmed TBP", "A TBP solid's patches trimmed against another TBP solid"),
]
KEEP_ITEMS = [
    ('outside', "Outside", "Keep the part of the patches outside the tool solid"),
    ('inside', "Inside", "Keep the part of the patches inside the tool solid"),
]
UNIT_ITEMS = [
    ('FILE', "File", "The length unit the file declares"),
    ('MM', "Millimetres", "The file's numbers are millimetres"),
    ('CM', "Centimetres", "The file's numbers are centimetres"),
    ('M', "Metres", "The file's numbers are metres"),
    ('INCH', "Inches", "The file's numbers are inches"),
]
UNIT_METRES = {'MM': 0.001, 'CM': 0.01, 'M': 1.0, 'INCH': 0.0254}
UV_ITEMS = [
    ('REAL', "Real-World Scale", "1 UV unit = 1 metre of surface (measured on the exact surface), "
                                 "one island per CAD face, packed without overlap"),
    ('FACE', "Per Face 0-1", "Each CAD face's surface parameters stretched to 0-1 (islands overlap)"),
]
ORIGIN_ITEMS = [
    ('FILE', "File Origin", "Each object's origin where the file puts its part's origin (the file's zero)"),
    ('BOX', "Part Box Centre", "Each object's origin at the centre of its part's bounding box, the mesh "
                               "shifted so that it stays where the file puts it"),
]
PART_ITEMS = [
    ('MODEL', "Model", "All faces (or the faces in no body)"),
    ('BODY', "Body", "One body"),
    ('FACE', "Face", "One face"),
]


def tolerance_property(name, description, default=0.001):
    return FloatProperty(name=name, description=description, default=default, min=0.0,
                         soft_min=1e-6, precision=5, step=0.01, subtype='DISTANCE', unit='LENGTH')


def angle_property():
    return FloatProperty(name="Angle", description="Edges where the surface normals turn more than this are sharp",
                         default=DEFAULTS.angle, min=0.0, max=math.pi, subtype='ANGLE')


class TRIMKIT_PG_object(bpy.types.PropertyGroup):
    source: PointerProperty(type=bpy.types.Text, name="Source",
                            description="Text datablock holding the CAD file (compressed) this mesh was made from")
    source_name: StringProperty(name="File", description="Name of the CAD file")
    kind: EnumProperty(name="Kind", items=KIND_ITEMS, default='CAD')
    tbp_levels: IntProperty(name="Levels", default=2, min=0, soft_max=4,
                            description="TBP hierarchy levels L: (lod+1)^L segments per patch edge")
    tbp_lod: IntProperty(name="LOD", default=1, min=0, soft_max=7,
                         description="TBP subdivisions per level K: each node splits into (K+1)^2 subpatches")
    keep: EnumProperty(name="Keep", items=KEEP_ITEMS, default='outside')
    tool_source: PointerProperty(type=bpy.types.Text, name="Tool",
                                 description="Text datablock holding the tool solid (.tbp) of a trimmed TBP")
    tool_name: StringProperty(name="Tool Name", description="Name of the tool object when trimmed")
    tool_matrix: FloatVectorProperty(name="Tool Matrix", size=16, default=[float(i % 5 == 0) for i in range(16)],
                                     description="Tool coordinates to this object's, row-major 4x4")
    part: EnumProperty(name="Part", items=PART_ITEMS, default='MODEL')
    part_index: IntProperty(name="Part Index", default=-1)
    scale: FloatProperty(name="Scale", description="Model units to Blender units", default=1.0, min=0.0)
    origin: FloatVectorProperty(name="Origin Offset", size=3, default=(0.0, 0.0, 0.0), subtype='TRANSLATION',
                                description="Where the object's origin is in its part's coordinates (Blender "
                                            "units): the mesh is the part's minus this (Part Box Centre origins)")

    tolerance: tolerance_property("Tolerance", "Largest distance from the mesh to the exact surface (viewport)",
                                  DEFAULTS.tolerance)
    render_tolerance: tolerance_property(
        "Render Tolerance", "Tolerance for final renders (F12, blender -b -f); 0 uses the viewport tolerance", 0.0)
    relative: BoolProperty(name="Relative", description="Tolerance as a fraction of the model's size",
                           default=DEFAULTS.relative)
    relative_tolerance: FloatProperty(name="Relative Tolerance", description="Fraction of the model's diagonal",
                                      default=DEFAULTS.relative_tolerance, min=0.0, soft_min=1e-6, soft_max=0.1, precision=5, step=0.01)
    angle: angle_property()
    mode: EnumProperty(name="Mode", items=MODE_ITEMS, default=DEFAULTS.mode)
    trim_method: EnumProperty(name="Trim Method", items=TRIM_ITEMS, default=DEFAULTS.trim_method)
    smooth: BoolProperty(name="Smooth", description="Smooth shading", default=DEFAULTS.smooth)
    exact_normals: BoolProperty(name="Exact Normals", default=DEFAULTS.exact_normals,
                                description="Custom split normals from the exact surface (slow above ~500k triangles)")

    units: EnumProperty(name="Units", items=UNIT_ITEMS, default=DEFAULTS.units,
                        description="What the file's numbers are (the scale follows)")
    uv_mode: EnumProperty(name="UVs", items=UV_ITEMS, default=DEFAULTS.uv_mode)
    uv_layout: StringProperty(name="UV Layout", description="Each CAD face's UV mapping and place (JSON), "
                                                          "kept so that re-meshing keeps the UVs where they were")
    lod_level: IntProperty(name="LOD Level", default=-1, description="Level in an LOD chain; -1: not an LOD")
    lod_source: StringProperty(name="LOD Of", description="The object an LOD chain was made from")
    lod_report: StringProperty(name="LODs", description="Triangles and tolerance of each level made from this object")
    import_report: StringProperty(name="Import", description="File unit, size and warnings at import")
    import_timing: StringProperty(name="Import Time",
                                  description="Time of the import and its parts: read, mesh, objects")

    faces: IntProperty(name="Faces", description="CAD faces in this object")
    triangles: IntProperty(name="Triangles")
    seconds: FloatProperty(name="Seconds", description="Time of the last tessellation", precision=3)
    failed_faces: IntProperty(name="Failed Faces")
    failed_report: StringProperty(name="Failures", description="Failed faces by id and reason")
    check_report: StringProperty(name="Check", description="Deviation from the exact faces at the last check")
    check_failed: StringProperty(name="Check Failures",
                                 description="Faces that failed the last check, one per line with the reason")


def register():
    bpy.utils.register_class(TRIMKIT_PG_object)
    bpy.types.Object.trimkit = PointerProperty(type=TRIMKIT_PG_object)


def unregister():
    del bpy.types.Object.trimkit
    bpy.utils.unregister_class(TRIMKIT_PG_object)
