"""Operators: File > Import > IGES (and STEP when the module has it) and TBP,
re-meshing and checking selected trimkit objects, a closed mesh to a TBP solid, and trimming
one TBP object by another. Each gathers its properties and delegates to
importer.py or tbp_objects.py."""
import math

import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, StringProperty
from bpy_extras.io_utils import ImportHelper

from . import importer, io, mesh_check, properties, tbp_objects

SPLIT_ITEMS = [
    ('BODY', "Per Body", "One object per body (solid or shell); faces in no body together"),
    ('FACE', "Per Face", "One object per CAD face"),
    ('MODEL', "Whole Model", "One object for the whole file"),
]


class ImportCadBase(ImportHelper):
    """Shared options of the CAD importers."""
    bl_options = {'REGISTER', 'UNDO', 'PRESET'}

    relative: BoolProperty(name="Relative Tolerance", default=True,
                           description="Tolerance as a fraction of the model's size instead of a length")
    relative_tolerance: FloatProperty(name="Fraction", default=0.001, min=1e-7, soft_max=0.05, precision=5,
                                      step=0.01, description="Tolerance as a fraction of the model's diagonal")
    tolerance: properties.tolerance_property(
        "Tolerance", "Largest distance from the mesh to the exact surface, in scene units")
    angle: properties.angle_property()
    mode: EnumProperty(name="Mode", items=properties.MODE_ITEMS, default='guaranteed')
    trim_method: EnumProperty(name="Trim Method", items=properties.TRIM_ITEMS, default='bezier3d')
    use_file_units: BoolProperty(name="File Units", default=True,
                                 description="Scale from the file's units to metres")
    scale: FloatProperty(name="Scale", default=1.0, min=1e-9, soft_max=1000.0,
                         description="Model units to scene units, when not using the file's units")
    split: EnumProperty(name="Objects", items=SPLIT_ITEMS, default='BODY')
    smooth: BoolProperty(name="Smooth Shading", default=True,
                         description="Smooth shading with custom normals from the exact surface")

    exact_normals: BoolProperty(name="Exact Normals", default=True,
                                description="Custom split normals from the exact surface (slow above ~500k triangles)")

    def settings(self):
        return importer.ImportSettings(
            tolerance=self.tolerance, relative=self.relative, relative_tolerance=self.relative_tolerance,
            angle=self.angle, mode=self.mode, trim_method=self.trim_method,
            scale=0.0 if self.use_file_units else self.scale, split=self.split, smooth=self.smooth,
            exact_normals=self.exact_normals)

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.prop(self, "relative")
        layout.prop(self, "relative_tolerance" if self.relative else "tolerance")
        layout.prop(self, "angle")
        layout.prop(self, "mode")
        layout.prop(self, "trim_method")
        layout.prop(self, "use_file_units")
        row = layout.row()
        row.enabled = not self.use_file_units
        row.prop(self, "scale")
        layout.prop(self, "split")
        layout.prop(self, "smooth")
        row = layout.row()
        row.enabled = self.smooth
        row.prop(self, "exact_normals")

    def execute(self, context):
        done = run_with_progress(
            self, context, lambda progress: importer.import_file(context, self.filepath, self.settings(),
                                                                 progress=progress))
        if done is None:
            return {'CANCELLED'}
        objects, result = done
        for face, reason in result.failed_faces:
            self.report({'WARNING'}, f"face {face} not meshed: {reason}")
        self.report({'INFO'}, f"{len(objects)} objects, {result.triangles} triangles, "
                              f"{result.faces - len(result.failed_faces)}/{result.faces} faces in "
                              f"{result.seconds:.2f} s")
        return {'FINISHED'}


class IMPORT_SCENE_OT_trimkit_iges(bpy.types.Operator, ImportCadBase):
    """Import an IGES file as meshes within a tolerance of the exact surfaces"""
    bl_idname = "import_scene.trimkit_iges"
    bl_label = "Import IGES (trimkit)"
    filename_ext = ".igs"
    filter_glob: StringProperty(default="*.igs;*.iges", options={'HIDDEN'})


class IMPORT_SCENE_OT_trimkit_step(bpy.types.Operator, ImportCadBase):
    """Import a STEP or Open CASCADE .brep file as meshes within a tolerance of the exact surfaces"""
    bl_idname = "import_scene.trimkit_step"
    bl_label = "Import STEP (trimkit)"
    filename_ext = ".stp"
    filter_glob: StringProperty(default="*.stp;*.step;*.brep;*.brp", options={'HIDDEN'})


def run_with_progress(operator, context, work):
    """work(progress) under a progress bar; its errors are reported on `operator` and
    give None (the caller returns {'CANCELLED'})."""
    wm = context.window_manager
    wm.progress_begin(0.0, 1.0)
    try:
        return work(wm.progress_update)
    except (RuntimeError, ValueError, OSError, ImportError) as err:
        operator.report({'ERROR'}, str(err))
        return None
    finally:
        wm.progress_end()


class OBJECT_OT_trimkit_retessellate(bpy.types.Operator):
    """Re-mesh the selected trimkit objects from their stored CAD geometry with their own settings"""
    bl_idname = "object.trimkit_retessellate"
    bl_label = "Re-tessellate"
    bl_options = {'REGISTER', 'UNDO'}

    @classmethod
    def poll(cls, context):
        return any(importer.is_trimkit(o) for o in context.selected_objects) or \
            importer.is_trimkit(context.active_object)

    def execute(self, context):
        objects = [o for o in context.selected_objects if importer.is_trimkit(o)]
        if not objects and importer.is_trimkit(context.active_object):
            objects = [context.active_object]
        results = run_with_progress(self, context, lambda progress: importer.retessellate(objects, progress=progress))
        if results is None:
            return {'CANCELLED'}
        for result in results:
            for face, reason in result.failed_faces:
                self.report({'WARNING'}, f"face {face} not meshed: {reason}")
        triangles = sum(o.trimkit.triangles for o in objects)
        self.report({'INFO'}, f"{len(objects)} objects re-meshed, {triangles} triangles")
        return {'FINISHED'}


class OBJECT_OT_trimkit_check(bpy.types.Operator):
    """Measure how far the selected trimkit objects' meshes are from their exact CAD faces and colour the faces by it"""
    bl_idname = "object.trimkit_check"
    bl_label = "Check Deviation"
    bl_options = {'REGISTER', 'UNDO'}

    @classmethod
    def poll(cls, context):
        return any(importer.is_trimkit(o) and o.trimkit.kind == 'CAD' for o in context.selected_objects)

    def execute(self, context):
        objects = [o for o in context.selected_objects if importer.is_trimkit(o) and o.trimkit.kind == 'CAD']
        def work(progress):
            checked = []
            for k, obj in enumerate(objects):
                checked.append((obj, *mesh_check.check_object(obj)))
                progress((k + 1) / len(objects))
            return checked
        checked = run_with_progress(self, context, work)
        if checked is None:
            return {'CANCELLED'}
        for obj, report, tolerance in checked:
            level = 'INFO' if max(report.mesh_to_surface, report.surface_to_mesh) <= tolerance else 'WARNING'
            self.report({level}, f"{obj.name}: {obj.trimkit.check_report}")
        return {'FINISHED'}


def levels_property(default=2):
    return IntProperty(name="Levels", default=default, min=0, soft_max=4,
                       description="Hierarchy levels L: (lod+1)^L segments per patch edge")


def lod_property(default=1):
    return IntProperty(name="LOD", default=default, min=0, soft_max=7,
                       description="Subdivisions per level K: each node splits into (K+1)^2 subpatches")


class IMPORT_SCENE_OT_trimkit_tbp(bpy.types.Operator, ImportHelper):
    """Import a solid of triangular Bézier patches (.tbp) as a mesh at a level of detail; the solid is kept in the .blend"""
    bl_idname = "import_scene.trimkit_tbp"
    bl_label = "Import TBP (trimkit)"
    bl_options = {'REGISTER', 'UNDO'}
    filename_ext = ".tbp"
    filter_glob: StringProperty(default="*.tbp", options={'HIDDEN'})
    levels: levels_property()
    lod: lod_property()

    def execute(self, context):
        def work(progress):
            progress(0.1)
            return tbp_objects.import_tbp(context, self.filepath, self.levels, self.lod)
        done = run_with_progress(self, context, work)
        if done is None:
            return {'CANCELLED'}
        obj, meshing = done
        self.report({'INFO'}, f"{obj.name}: {meshing.patches} patches, {meshing.triangles} triangles, "
                              f"{meshing.open_edges} open edges in {meshing.seconds:.2f} s")
        return {'FINISHED'}


class OBJECT_OT_trimkit_mesh_to_tbp(bpy.types.Operator):
    """Make a TBP solid (cubic PN triangles) from the active closed mesh, as a new object"""
    bl_idname = "object.trimkit_mesh_to_tbp"
    bl_label = "Mesh to TBP Solid"
    bl_options = {'REGISTER', 'UNDO'}
    levels: levels_property(1)
    lod: lod_property(1)

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == 'MESH'

    def execute(self, context):
        source = context.active_object

        def work(progress):
            progress(0.1)
            return tbp_objects.mesh_to_tbp(context, source, self.levels, self.lod)
        done = run_with_progress(self, context, work)
        if done is None:
            return {'CANCELLED'}
        obj, meshing = done
        self.report({'INFO'}, f"{obj.name}: {meshing.patches} PN patches, {meshing.triangles} triangles")
        return {'FINISHED'}


class OBJECT_OT_trimkit_trim(bpy.types.Operator):
    """Trim the active TBP object by the other selected TBP solid; the result is a new object and the active one is hidden"""
    bl_idname = "object.trimkit_trim"
    bl_label = "Trim by TBP Solid"
    bl_options = {'REGISTER', 'UNDO'}
    keep: EnumProperty(name="Keep", items=properties.KEEP_ITEMS, default='outside')
    levels: levels_property(2)
    lod: lod_property(3)

    @staticmethod
    def tool(context):
        tools = [o for o in context.selected_objects if o != context.active_object and tbp_objects.is_tbp(o)]
        return tools[0] if len(tools) == 1 else None

    @classmethod
    def poll(cls, context):
        return tbp_objects.is_tbp(context.active_object) and cls.tool(context) is not None

    def execute(self, context):
        target, tool = context.active_object, self.tool(context)

        def work(progress):
            progress(0.1)
            return tbp_objects.trim(context, target, tool, self.keep, self.levels, self.lod)
        done = run_with_progress(self, context, work)
        if done is None:
            return {'CANCELLED'}
        obj, result = done
        self.report({'INFO'}, f"{obj.name}: {result.triangles} triangles, area {result.area:.6g}, "
                              f"{result.boundary_loops} boundary loops, {result.triangle_tests} triangle tests "
                              f"in {result.seconds:.2f} s")
        return {'FINISHED'}


def menu_import(self, context):
    self.layout.operator(IMPORT_SCENE_OT_trimkit_iges.bl_idname, text="IGES (.igs, .iges) [trimkit]")
    if io.has_step():
        self.layout.operator(IMPORT_SCENE_OT_trimkit_step.bl_idname, text="STEP (.stp, .step, .brep) [trimkit]")
    self.layout.operator(IMPORT_SCENE_OT_trimkit_tbp.bl_idname, text="TBP (.tbp) [trimkit]")


def menu_object(self, context):
    self.layout.separator()
    self.layout.operator(OBJECT_OT_trimkit_mesh_to_tbp.bl_idname)
    self.layout.operator(OBJECT_OT_trimkit_trim.bl_idname)


def classes():
    """The operator classes to register: STEP only when _trimkit can read it."""
    found = [IMPORT_SCENE_OT_trimkit_iges, OBJECT_OT_trimkit_retessellate, OBJECT_OT_trimkit_check,
             IMPORT_SCENE_OT_trimkit_tbp,
             OBJECT_OT_trimkit_mesh_to_tbp, OBJECT_OT_trimkit_trim]
    if io.has_step():
        found.insert(1, IMPORT_SCENE_OT_trimkit_step)
    return found


def register():
    for cls in classes():
        bpy.utils.register_class(cls)
    bpy.types.TOPBAR_MT_file_import.append(menu_import)
    bpy.types.VIEW3D_MT_object.append(menu_object)


def unregister():
    bpy.types.VIEW3D_MT_object.remove(menu_object)
    bpy.types.TOPBAR_MT_file_import.remove(menu_import)
    for cls in reversed(classes()):
        bpy.utils.unregister_class(cls)
