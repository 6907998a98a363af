"""Object properties > trimkit: settings, re-mesh button and last-run statistics."""
import bpy

from . import importer


class OBJECT_PT_trimkit(bpy.types.Panel):
    bl_label = "trimkit"
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    bl_context = "object"

    @classmethod
    def poll(cls, context):
        return importer.is_trimkit(context.object)

    def draw(self, context):
        props = context.object.trimkit
        layout = self.layout
        layout.use_property_split = True
        if props.kind != 'CAD':
            self.draw_tbp(props, layout)
            return
        layout.label(text=f"{props.source_name} ({props.part.lower()} {props.part_index})", icon='FILE')
        col = layout.column()
        col.prop(props, "relative")
        col.prop(props, "relative_tolerance" if props.relative else "tolerance", text="Viewport")
        col.prop(props, "render_tolerance", text="Render")
        col.prop(props, "angle")
        col.prop(props, "mode")
        col.prop(props, "trim_method")
        col.prop(props, "smooth")
        col.prop(props, "exact_normals")
        row = layout.row()
        row.operator("object.trimkit_retessellate", icon='FILE_REFRESH')
        row.operator("object.trimkit_check", icon='VIEWZOOM')
        box = layout.box()
        box.label(text=f"{props.faces} faces, {props.triangles} triangles, {props.seconds:.2f} s")
        if props.failed_faces:
            box.label(text=f"{props.failed_faces} failed faces", icon='ERROR')
            box.label(text=props.failed_report[:120])
        if props.check_report:
            box.label(text=props.check_report, icon='CHECKMARK')

    @staticmethod
    def draw_tbp(props, layout):
        if props.kind == 'TBP_TRIM':
            layout.label(text=f"{props.source_name} trimmed by {props.tool_name}", icon='MOD_BOOLEAN')
        else:
            layout.label(text=f"{props.source_name} (TBP solid)", icon='FILE')
        col = layout.column()
        col.prop(props, "tbp_levels")
        col.prop(props, "tbp_lod")
        if props.kind == 'TBP_TRIM':
            col.prop(props, "keep")
        col.prop(props, "smooth")
        col.prop(props, "exact_normals")
        layout.operator("object.trimkit_retessellate", text="Re-mesh", icon='FILE_REFRESH')
        box = layout.box()
        box.label(text=f"{props.faces} patches, {props.triangles} triangles, {props.seconds:.2f} s")


def register():
    bpy.utils.register_class(OBJECT_PT_trimkit)


def unregister():
    bpy.utils.unregister_class(OBJECT_PT_trimkit)
