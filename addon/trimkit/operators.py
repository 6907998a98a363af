"""Operators: File > Import > IGES (and STEP when the module has it), TBP and trimkit
compressed (.tkz), File > Export > trimkit compressed (.tkz), re-meshing and checking selected trimkit objects, a closed mesh to a TBP solid, and trimming
one TBP object by another. Each gathers its properties and delegates to
importer.py or tbp_objects.py."""
import math

import bpy
import pathlib
import time

from bpy.props import BoolProperty, CollectionProperty, EnumProperty, FloatProperty, IntProperty, StringProperty
from bpy_extras.io_utils import ExportHelper, ImportHelper

from . import cad_faces, importer, io, lods, mesh_check, modal_work, properties, stored_source, tbp_io, tbp_objects
from .settings import DEFAULTS

SPLIT_ITEMS = [
    ('BODY', "Per Body", "One object per body (solid or shell); faces in no body together"),
    ('FACE', "Per Face", "One object per CAD face"),
    ('MODEL', "Whole Model", "One object for the whole file"),
]


class ImportCadBase(ImportHelper, modal_work.ModalWork):
    """Shared options of the CAD importers, drawn in groups (IMPORT_PT_trimkit_* below)."""
    bl_options = {'REGISTER', 'UNDO', 'PRESET'}

    files: CollectionProperty(type=bpy.types.OperatorFileListElement, options={'HIDDEN', 'SKIP_SAVE'})
    directory: StringProperty(subtype='DIR_PATH', options={'HIDDEN', 'SKIP_SAVE'})

    relative: BoolProperty(name="Relative Tolerance", default=DEFAULTS.relative,
                           description="Tolerance as a fraction of the model's size instead of a length")
    relative_tolerance: FloatProperty(name="Fraction", default=DEFAULTS.relative_tolerance, min=1e-7, soft_max=0.05, precision=5,
                                      step=0.01, description="Tolerance as a fraction of the model's diagonal")
    tolerance: properties.tolerance_property(
        "Tolerance", "Largest distance from the mesh to the exact surface, in scene units", DEFAULTS.tolerance)
    angle: properties.angle_property()
    mode: EnumProperty(name="Mode", items=properties.MODE_ITEMS, default=DEFAULTS.mode)
    trim_method: EnumProperty(name="Trim Method", items=properties.TRIM_ITEMS, default=DEFAULTS.trim_method)
    units: EnumProperty(name="Units", items=properties.UNIT_ITEMS, default=DEFAULTS.units,
                        description="What the file's numbers are: the unit it declares, or one you choose")
    split: EnumProperty(name="Objects", items=SPLIT_ITEMS, default=DEFAULTS.split)
    origin: EnumProperty(name="Origin", items=properties.ORIGIN_ITEMS, default=DEFAULTS.origin,
                         description="Where each object's origin goes: the file's, or its part's box centre")
    smooth: BoolProperty(name="Smooth Shading", default=DEFAULTS.smooth,
                         description="Smooth shading with custom normals from the exact surface")
    exact_normals: BoolProperty(name="Exact Normals", default=DEFAULTS.exact_normals,
                                description="Custom split normals from the exact surface (slow above ~500k triangles)")
    uv_mode: EnumProperty(name="UVs", items=properties.UV_ITEMS, default=DEFAULTS.uv_mode)
    read_timeout: FloatProperty(name="Read Timeout", default=DEFAULTS.read_timeout, min=0.0, soft_max=600.0,
                                unit='TIME_ABSOLUTE',
                                description="Seconds a file may take to read (0: no limit); a file that takes "
                                            "longer is not imported")
    face_timeout: FloatProperty(name="Face Timeout", default=DEFAULTS.face_timeout, min=0.0, soft_max=300.0,
                                unit='TIME_ABSOLUTE',
                                description="Seconds one CAD face may take to mesh (0: no limit); a slower face "
                                            "is left out and reported, the rest is imported")

    run_modal: BoolProperty(name="In Background", default=False, options={'HIDDEN', 'SKIP_SAVE'},
                            description="Read and mesh in a working thread, with a progress bar and Esc to "
                                        "cancel (set when the import is started from the user interface)")

    def invoke(self, context, event):
        self.run_modal = True
        return ImportHelper.invoke(self, context, event)

    def settings(self):
        return importer.ImportSettings(
            tolerance=self.tolerance, relative=self.relative, relative_tolerance=self.relative_tolerance,
            angle=self.angle, mode=self.mode, trim_method=self.trim_method, units=self.units,
            split=self.split, origin=self.origin, smooth=self.smooth, exact_normals=self.exact_normals, uv_mode=self.uv_mode,
            read_timeout=self.read_timeout, face_timeout=self.face_timeout)

    def paths(self):
        """The chosen files: every one of `files` in `directory`, else `filepath`."""
        names = [f.name for f in self.files if f.name]
        if names and self.directory:
            return [str(pathlib.Path(self.directory) / name) for name in names]
        return [self.filepath]

    def draw(self, context):
        pass  # the options are drawn by the IMPORT_PT_trimkit_* panels, in groups as glTF's

    def execute(self, context):
        """Reads and meshes the files in a working thread (modal_work: progress bar,
        status text, Esc cancels with the scene unchanged), then makes the objects."""
        paths, settings = self.paths(), self.settings()
        metres_per_unit = importer.unit_scale(context.scene)

        def work(limits):
            prepared, errors = [], []
            for path in paths:
                try:
                    prepared.append(importer.prepare_file(path, settings, metres_per_unit, limits))
                except (RuntimeError, ValueError, OSError) as err:
                    if len(paths) == 1:
                        raise
                    errors.append(str(err))
            if not prepared:
                raise RuntimeError("; ".join(errors))
            return prepared, errors
        try:
            limits = modal_work.new_limits(settings.read_timeout, settings.face_timeout)
        except ImportError as err:
            self.report({'ERROR'}, str(err))
            return {'CANCELLED'}
        label = pathlib.Path(paths[0]).name if len(paths) == 1 else f"{len(paths)} files"
        return self.start_work(context, label, work, lambda context, value: self.link(context, settings, *value),
                               limits, modal=self.run_modal)

    def link(self, context, settings, prepared, errors):
        """The objects of the read and meshed files (main thread), and the reports."""
        done = [importer.link_file(context, p, settings) for p in prepared]
        for error in errors:
            self.report({'WARNING'}, f"skipped: {error}")
        objects = [o for objs, _, _, _ in done for o in objs]
        importer.select_only(context, objects)
        for _, result, lines, timing in done:
            for face, reason in result.failed_faces:
                self.report({'WARNING'}, f"face {face} not meshed: {reason}")
            self.report({'INFO'}, lines[0])
            for line in lines[1:]:
                self.report({'WARNING'}, line)
            self.report({'INFO'}, timing)
        triangles = sum(result.triangles for _, result, _, _ in done)
        faces = sum(result.faces for _, result, _, _ in done)
        failed = sum(len(result.failed_faces) for _, result, _, _ in done)
        self.report({'INFO'}, f"{len(prepared)} file(s), {len(objects)} objects, {triangles} triangles, "
                              f"{faces - failed}/{faces} faces in {time.perf_counter() - self._started:.2f} s")
        return {'FINISHED'}


class TrimkitImportPanel:
    """An option group of the trimkit CAD importers' file browser sidebar (as glTF's)."""
    bl_space_type = 'FILE_BROWSER'
    bl_region_type = 'TOOL_PROPS'
    bl_parent_id = "FILE_PT_operator"
    properties = ()

    @classmethod
    def poll(cls, context):
        operator = context.space_data.active_operator
        return operator is not None and operator.bl_idname in ("IMPORT_SCENE_OT_trimkit_iges",
                                                               "IMPORT_SCENE_OT_trimkit_step",
                                                               "IMPORT_SCENE_OT_trimkit_tkz")

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        operator = context.space_data.active_operator
        self.draw_options(layout, operator)

    def draw_options(self, layout, operator):
        for name in self.properties:
            layout.prop(operator, name)


class IMPORT_PT_trimkit_mesh(TrimkitImportPanel, bpy.types.Panel):
    bl_label = "Mesh"

    def draw_options(self, layout, operator):
        layout.prop(operator, "relative")
        layout.prop(operator, "relative_tolerance" if operator.relative else "tolerance")
        layout.prop(operator, "angle")
        layout.prop(operator, "mode")
        layout.prop(operator, "trim_method")


class IMPORT_PT_trimkit_units(TrimkitImportPanel, bpy.types.Panel):
    bl_label = "Units"
    properties = ("units",)


class IMPORT_PT_trimkit_objects(TrimkitImportPanel, bpy.types.Panel):
    bl_label = "Objects"
    properties = ("split", "origin")


class IMPORT_PT_trimkit_shading(TrimkitImportPanel, bpy.types.Panel):
    bl_label = "Shading & UVs"

    def draw_options(self, layout, operator):
        layout.prop(operator, "smooth")
        row = layout.row()
        row.enabled = operator.smooth
        row.prop(operator, "exact_normals")
        layout.prop(operator, "uv_mode")


class IMPORT_PT_trimkit_limits(TrimkitImportPanel, bpy.types.Panel):
    bl_label = "Limits"
    bl_options = {'DEFAULT_CLOSED'}
    properties = ("read_timeout", "face_timeout")


IMPORT_PANELS = [IMPORT_PT_trimkit_mesh, IMPORT_PT_trimkit_units, IMPORT_PT_trimkit_objects,
                 IMPORT_PT_trimkit_shading, IMPORT_PT_trimkit_limits]


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


class IMPORT_SCENE_OT_trimkit_tkz(bpy.types.Operator, ImportCadBase):
    """Import a trimkit compressed model (.tkz): faces rebuilt from their edges with G1, then meshed"""
    bl_idname = "import_scene.trimkit_tkz"
    bl_label = "Import trimkit compressed (.tkz)"
    filename_ext = ".tkz"
    filter_glob: StringProperty(default="*.tkz", options={'HIDDEN'})


class EXPORT_SCENE_OT_trimkit_tkz(bpy.types.Operator, ExportHelper):
    """Write the active object's CAD model as a trimkit compressed .tkz: faces that refit from their edges within the tolerance keep only their rule"""
    bl_idname = "export_scene.trimkit_tkz"
    bl_label = "Export trimkit compressed (.tkz)"
    filename_ext = ".tkz"
    filter_glob: StringProperty(default="*.tkz", options={'HIDDEN'})
    tolerance: FloatProperty(name="Tolerance", default=0.0, min=0.0,
                             description="Largest distance of a rebuilt face from its surface, in the file's units; "
                                         "0: 1 % of each face's size")

    @classmethod
    def poll(cls, context):
        o = context.active_object
        return o is not None and importer.is_trimkit(o) and o.trimkit.kind == 'CAD'

    def execute(self, context):
        props = context.active_object.trimkit

        def work(progress):
            data = stored_source.load(props.source)
            model = io.read_bytes(data, stored_source.file_name(props.source))
            packed, done, faces = io.compress_to_tkz(model, self.tolerance)
            pathlib.Path(self.filepath).write_bytes(packed)
            return len(data), len(packed), done, faces

        result = run_with_progress(self, context, work)
        if result is None:
            return {'CANCELLED'}
        stored, packed, done, faces = result
        tkz = props.source is not None and props.source.get(stored_source.FORM_KEY) == "tkz"
        form = "a lossless .tkz" if tkz else "its source file"
        self.report({'INFO'}, f"{self.filepath}: {done} of {faces} faces compressed, {packed} bytes "
                              f"(the .blend stores the model as {form}, {stored} bytes before zlib)")
        return {'FINISHED'}


def run_with_progress(operator, context, work, label=None):
    """work(progress) under a progress bar (and, with a label, status bar text); its
    errors are reported on `operator` and give None (the caller returns {'CANCELLED'})."""
    wm = context.window_manager
    workspace = getattr(context, "workspace", None)
    wm.progress_begin(0.0, 1.0)

    def progress(fraction):
        wm.progress_update(fraction)
        if label and workspace:
            workspace.status_text_set(f"trimkit: {label} {100.0 * fraction:.0f} %")
    try:
        return work(progress)
    except (RuntimeError, ValueError, OSError, ImportError) as err:
        operator.report({'ERROR'}, str(err))
        return None
    finally:
        wm.progress_end()
        if label and workspace:
            workspace.status_text_set(None)


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
        results = run_with_progress(self, context, lambda progress: importer.retessellate(objects, progress=progress),
                                    label=f"re-meshing {len(objects)} object(s)")
        if results is None:
            return {'CANCELLED'}
        for result in results:
            for face, reason in result.failed_faces:
                self.report({'WARNING'}, f"face {face} not meshed: {reason}")
        for obj in objects:
            if obj.trimkit.kind != 'CAD':
                report_tbp_warning(self, obj)
        triangles = sum(o.trimkit.triangles for o in objects)
        self.report({'INFO'}, f"{len(objects)} objects re-meshed, {triangles} triangles")
        return {'FINISHED'}


class OBJECT_OT_trimkit_check(bpy.types.Operator):
    """Check each CAD face of the selected trimkit objects against its exact face (deviation both ways, area, missing and failed faces), colour the faces by it and list the failures"""
    bl_idname = "object.trimkit_check"
    bl_label = "Check Deviation"
    bl_options = {'REGISTER', 'UNDO'}

    @classmethod
    def poll(cls, context):
        return any(importer.is_trimkit(o) and o.trimkit.kind == 'CAD' for o in context.selected_objects)

    def execute(self, context):
        objects = [o for o in context.selected_objects if importer.is_trimkit(o) and o.trimkit.kind == 'CAD']
        def work(progress):
            # Linked duplicates (instances of one part) share a mesh and its settings: one
            # check per mesh, its results copied to the other users.
            users = {}
            for obj in objects:
                users.setdefault(obj.data.as_pointer(), []).append(obj)
            checked = []
            for k, group in enumerate(users.values()):
                first = group[0]
                checked.append((first, *mesh_check.check_object(first, seconds)))
                for other in group[1:]:
                    other.trimkit.check_report = first.trimkit.check_report
                    other.trimkit.check_failed = first.trimkit.check_failed
                progress((k + 1) / len(users))
            return checked
        start, seconds = time.perf_counter(), {}
        checked = run_with_progress(self, context, work, label=f"checking {len(objects)} object(s)")
        if checked is None:
            return {'CANCELLED'}
        for obj, report, tolerance, faces in checked:
            bad = [c for c in faces if not c.passed]
            self.report({'WARNING' if bad else 'INFO'}, f"{obj.name}: {obj.trimkit.check_report}")
            for c in bad[:20]:
                self.report({'WARNING'}, f"{obj.name}: {c.reason}")
        self.report({'INFO'}, check_timing(len(checked), time.perf_counter() - start, seconds))
        return {'FINISHED'}


def check_timing(meshes, total, seconds):
    """'checked 2 mesh(es) in 1.23 s (read 0.10 s, check 1.10 s, other 0.03 s)': read is the
    stored files, check the measuring and colouring, other the rest (progress, reports)."""
    read, check = seconds.get("read", 0.0), seconds.get("check", 0.0)
    return (f"checked {meshes} mesh(es) in {total:.2f} s (read {read:.2f} s, check {check:.2f} s, "
            f"other {max(0.0, total - read - check):.2f} s)")


def report_tbp_warning(operator, obj):
    """The warning of a TBP object's triangle estimate (the second line of its import_report), if any."""
    for line in obj.trimkit.import_report.splitlines()[1:]:
        operator.report({'WARNING'}, line)


def levels_property(default=2, options=None):
    return IntProperty(name="Levels", default=default, min=0, soft_max=4, options=options or set(),
                       description="Hierarchy levels L: (lod+1)^L segments per patch edge")


def lod_property(default=1, options=None):
    return IntProperty(name="LOD", default=default, min=0, soft_max=7, options=options or set(),
                       description="Subdivisions per level K: each node splits into (K+1)^2 subpatches")


class IMPORT_SCENE_OT_trimkit_tbp(bpy.types.Operator, ImportHelper):
    """Import a solid of triangular Bézier patches (.tbp) as a mesh at a level of detail; the solid is kept in the .blend"""
    bl_idname = "import_scene.trimkit_tbp"
    bl_label = "Import TBP (trimkit)"
    bl_options = {'REGISTER', 'UNDO', 'PRESET'}  # presets/operator/import_scene.trimkit_tbp
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
        report_tbp_warning(self, obj)
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
    sharp_angle: FloatProperty(name="Sharp Angle", default=tbp_io.TBP_SHARP_ANGLE, min=0.0, max=math.pi, subtype='ANGLE',
                               description="Sides whose faces meet at more than this stay sharp creases of the solid "
                                           "(a cube stays a cube); 180 degrees smooths every side")
    use_marked_sharp: BoolProperty(name="Keep Marked Sharp", default=True,
                                   description="Edges marked sharp (Edge > Mark Sharp) stay creases whatever the "
                                               "Sharp Angle")

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == 'MESH'

    def execute(self, context):
        source = context.active_object

        def work(progress):
            progress(0.1)
            return tbp_objects.mesh_to_tbp(context, source, self.levels, self.lod, self.sharp_angle,
                                           self.use_marked_sharp)
        done = run_with_progress(self, context, work)
        if done is None:
            return {'CANCELLED'}
        obj, meshing = done
        report_tbp_warning(self, obj)
        self.report({'INFO'}, f"{obj.name}: {meshing.patches} PN patches, {meshing.triangles} triangles")
        return {'FINISHED'}


class OBJECT_OT_trimkit_trim(bpy.types.Operator):
    """Trim the active TBP object by the other selected TBP solid; the result is a new object and the active one is hidden"""
    bl_idname = "object.trimkit_trim"
    bl_label = "Trim by TBP Solid"
    bl_options = {'REGISTER', 'UNDO'}
    keep: EnumProperty(name="Keep", items=properties.KEEP_ITEMS, default='outside')
    # Not given (and not remembered from the last trim): the active object's own levels/lod.
    levels: levels_property(2, {'SKIP_SAVE'})
    lod: lod_property(1, {'SKIP_SAVE'})

    @staticmethod
    def tool(context):
        tools = [o for o in context.selected_objects if o != context.active_object and tbp_objects.is_tbp(o)]
        return tools[0] if len(tools) == 1 else None

    @classmethod
    def poll(cls, context):
        return tbp_objects.is_tbp(context.active_object) and cls.tool(context) is not None

    def resolve_resolution(self, target):
        """levels/lod not given: the target's own (tbp_objects.source_resolution)."""
        levels, lod = tbp_objects.source_resolution(target)
        if not self.properties.is_property_set("levels"):
            self.levels = levels
        if not self.properties.is_property_set("lod"):
            self.lod = lod

    def invoke(self, context, event):
        """Above tbp_io.TBP_WARN_TRIANGLES estimated, asks before the work (a dialog with
        the estimate and the warning, where Levels and LOD can be lowered)."""
        self.resolve_resolution(context.active_object)
        _, warning = tbp_objects.trim_estimate(context.active_object, self.levels, self.lod)
        if warning:
            return context.window_manager.invoke_props_dialog(self, width=560)
        return self.execute(context)

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        for name in ("keep", "levels", "lod"):
            layout.prop(self, name)
        target = context.active_object
        if tbp_objects.is_tbp(target):
            estimate, warning = tbp_objects.trim_estimate(target, self.levels, self.lod)
            col = layout.column(align=True)
            col.label(text=estimate, icon='INFO')
            if warning:
                col.label(text=warning, icon='ERROR')

    def execute(self, context):
        target, tool = context.active_object, self.tool(context)
        self.resolve_resolution(target)
        estimate, warning = tbp_objects.trim_estimate(target, self.levels, self.lod)
        self.report({'INFO'}, f"{target.name}: {estimate}")
        if warning:
            self.report({'WARNING'}, warning)

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


class OBJECT_OT_trimkit_reload(bpy.types.Operator):
    """Read the CAD file of the selected trimkit objects again from where it was imported, store it, and re-mesh every object made from it"""
    bl_idname = "object.trimkit_reload"
    bl_label = "Reload from Disk"
    bl_options = {'REGISTER', 'UNDO'}

    @classmethod
    def poll(cls, context):
        return any(importer.is_trimkit(o) and o.trimkit.kind == 'CAD' for o in context.selected_objects)

    def execute(self, context):
        texts = {o.trimkit.source for o in context.selected_objects
                 if importer.is_trimkit(o) and o.trimkit.kind == 'CAD'}
        done = run_with_progress(self, context, lambda progress: [importer.reload(text) for text in texts])
        if done is None:
            return {'CANCELLED'}
        for path, objects in done:
            self.report({'INFO'}, f"{path}: reloaded, {len(objects)} objects re-meshed, "
                                  f"{sum(o.trimkit.triangles for o in objects)} triangles")
        return {'FINISHED'}


class OBJECT_OT_trimkit_rebuild_faces(bpy.types.Operator):
    """Rebuild the selected CAD faces from their boundary edges with G1 to their neighbours (repairs a damaged surface), then re-mesh"""
    bl_idname = "object.trimkit_rebuild_faces"
    bl_label = "Rebuild CAD Faces from Edges"
    bl_options = {'REGISTER', 'UNDO'}

    @classmethod
    def poll(cls, context):
        o = context.active_object
        return context.mode == 'EDIT_MESH' and importer.is_trimkit(o) and o.trimkit.kind == 'CAD'

    def execute(self, context):
        obj = context.active_object
        try:
            faces = cad_faces.selected_cad_faces(obj)
        except ValueError as err:
            self.report({'ERROR'}, str(err))
            return {'CANCELLED'}
        if not faces:
            self.report({'ERROR'}, f"{obj.name}: select faces of the CAD faces to rebuild")
            return {'CANCELLED'}
        bpy.ops.object.mode_set(mode='OBJECT')
        rows = run_with_progress(self, context, lambda progress: importer.rebuild_faces(obj, faces))
        bpy.ops.object.mode_set(mode='EDIT')
        if rows is None:
            return {'CANCELLED'}
        rebuilt = [f for f, done, _, _ in rows if done]
        for f, done, reason, error in rows:
            if not done:
                self.report({'WARNING'}, f"CAD face {f} not rebuilt: {reason}")
        self.report({'INFO'}, f"{obj.name}: CAD faces {rebuilt} rebuilt from their edges and re-meshed")
        return {'FINISHED'} if rebuilt else {'CANCELLED'}


class MESH_OT_trimkit_select_cad_face(bpy.types.Operator):
    """Select every face of the CAD face the active face belongs to (its cad_face)"""
    bl_idname = "mesh.trimkit_select_cad_face"
    bl_label = "Select CAD Face"
    bl_options = {'REGISTER', 'UNDO'}
    extend: BoolProperty(name="Extend", default=False, description="Keep the current selection")

    @classmethod
    def poll(cls, context):
        obj = context.edit_object
        return obj is not None and obj.type == 'MESH' and "cad_face" in obj.data.attributes

    def execute(self, context):
        try:
            faces, count = cad_faces.select_cad_face(context.edit_object, self.extend)
        except ValueError as err:
            self.report({'ERROR'}, str(err))
            return {'CANCELLED'}
        self.report({'INFO'}, f"CAD face {faces[0]}: {count} mesh faces selected")
        return {'FINISHED'}


class MESH_OT_trimkit_select_similar_cad_faces(bpy.types.Operator):
    """Select the CAD faces like the selected ones: the same kind of surface and about the same area"""
    bl_idname = "mesh.trimkit_select_similar_cad_faces"
    bl_label = "Select Similar CAD Faces"
    bl_options = {'REGISTER', 'UNDO'}
    threshold: FloatProperty(name="Area Threshold", default=0.02, min=0.0, max=1.0, subtype='FACTOR',
                             description="Largest relative difference of area")
    kind_only: BoolProperty(name="Surface Kind Only", default=False,
                            description="Every CAD face of the same kind of surface, whatever its area")

    @classmethod
    def poll(cls, context):
        return MESH_OT_trimkit_select_cad_face.poll(context) and importer.is_trimkit(context.edit_object)

    def execute(self, context):
        try:
            faces, count = cad_faces.select_similar(context.edit_object, self.threshold, self.kind_only)
        except (ValueError, RuntimeError) as err:
            self.report({'ERROR'}, str(err))
            return {'CANCELLED'}
        self.report({'INFO'}, f"{len(faces)} CAD faces, {count} mesh faces selected")
        return {'FINISHED'}


class OBJECT_OT_trimkit_make_lods(bpy.types.Operator):
    """Make a chain of levels of detail of the selected CAD objects, named <name>_LOD0, _LOD1, ... (as Unreal and Unity import them): each a new object at its own tolerance, the tolerance growing by a factor per level; UV layout and materials shared"""
    bl_idname = "object.trimkit_make_lods"
    bl_label = "Make LODs"
    bl_options = {'REGISTER', 'UNDO'}
    count: IntProperty(name="Levels", default=3, min=2, soft_max=6, description="Meshes in the chain")
    factor: FloatProperty(name="Factor", default=4.0, min=1.1, soft_max=16.0,
                          description="Each level's tolerance is the previous one's times this")

    @classmethod
    def poll(cls, context):
        return any(importer.is_trimkit(o) and o.trimkit.kind == 'CAD' for o in context.selected_objects)

    def execute(self, context):
        sources = [o for o in context.selected_objects if importer.is_trimkit(o) and o.trimkit.kind == 'CAD']
        done = run_with_progress(self, context, lambda progress: [
            lods.make_lods(context, o, self.count, self.factor) for o in sources])
        if done is None:
            return {'CANCELLED'}
        for source, chain in zip(sources, done):
            counts = [o.trimkit.triangles for o in chain]
            level = 'INFO' if all(a > b for a, b in zip(counts, counts[1:])) else 'WARNING'
            self.report({level}, f"{source.name}: {source.trimkit.lod_report}")
        return {'FINISHED'}


def menu_import(self, context):
    self.layout.operator(IMPORT_SCENE_OT_trimkit_iges.bl_idname, text="IGES (.igs, .iges) [trimkit]")
    if io.has_step():
        self.layout.operator(IMPORT_SCENE_OT_trimkit_step.bl_idname, text="STEP (.stp, .step, .brep) [trimkit]")
    self.layout.operator(IMPORT_SCENE_OT_trimkit_tbp.bl_idname, text="TBP (.tbp) [trimkit]")
    self.layout.operator(IMPORT_SCENE_OT_trimkit_tkz.bl_idname, text="trimkit compressed (.tkz)")


def menu_export(self, context):
    self.layout.operator(EXPORT_SCENE_OT_trimkit_tkz.bl_idname, text="trimkit compressed (.tkz)")


def menu_object(self, context):
    self.layout.separator()
    self.layout.operator(OBJECT_OT_trimkit_mesh_to_tbp.bl_idname)
    self.layout.operator(OBJECT_OT_trimkit_trim.bl_idname)
    self.layout.operator(OBJECT_OT_trimkit_make_lods.bl_idname)
    self.layout.operator(OBJECT_OT_trimkit_reload.bl_idname)


def menu_faces_edit(self, context):
    self.layout.separator()
    self.layout.operator(OBJECT_OT_trimkit_rebuild_faces.bl_idname)


def menu_select_edit(self, context):
    self.layout.separator()
    self.layout.operator(MESH_OT_trimkit_select_cad_face.bl_idname)
    self.layout.operator(MESH_OT_trimkit_select_similar_cad_faces.bl_idname)


def classes():
    """The operator classes to register: STEP only when _trimkit can read it."""
    found = [IMPORT_SCENE_OT_trimkit_iges, IMPORT_SCENE_OT_trimkit_tkz, EXPORT_SCENE_OT_trimkit_tkz, OBJECT_OT_trimkit_retessellate, OBJECT_OT_trimkit_check,
             IMPORT_SCENE_OT_trimkit_tbp,
             OBJECT_OT_trimkit_mesh_to_tbp, OBJECT_OT_trimkit_trim, OBJECT_OT_trimkit_reload,
             MESH_OT_trimkit_select_cad_face, MESH_OT_trimkit_select_similar_cad_faces, OBJECT_OT_trimkit_rebuild_faces,
             OBJECT_OT_trimkit_make_lods, *IMPORT_PANELS]
    if io.has_step():
        found.insert(1, IMPORT_SCENE_OT_trimkit_step)
    return found


def register():
    for cls in classes():
        bpy.utils.register_class(cls)
    bpy.types.TOPBAR_MT_file_import.append(menu_import)
    bpy.types.TOPBAR_MT_file_export.append(menu_export)
    bpy.types.VIEW3D_MT_object.append(menu_object)
    bpy.types.VIEW3D_MT_select_edit_mesh.append(menu_select_edit)
    bpy.types.VIEW3D_MT_edit_mesh_faces.append(menu_faces_edit)


def unregister():
    bpy.types.VIEW3D_MT_edit_mesh_faces.remove(menu_faces_edit)
    bpy.types.VIEW3D_MT_select_edit_mesh.remove(menu_select_edit)
    bpy.types.VIEW3D_MT_object.remove(menu_object)
    bpy.types.TOPBAR_MT_file_export.remove(menu_export)
    bpy.types.TOPBAR_MT_file_import.remove(menu_import)
    for cls in reversed(classes()):
        bpy.utils.unregister_class(cls)
