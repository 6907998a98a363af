"""Object properties > trimkit: settings, re-mesh button and last-run statistics."""
import bpy

from . import importer, stored_source


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
        stored = stored_line(props.source)
        if stored:
            layout.label(text=stored, icon='PACKAGE')
        draw_import_report(layout, props.import_report)
        if props.import_timing:
            layout.label(text=props.import_timing.partition(": ")[2], icon='TIME')
        col = layout.column()
        col.prop(props, "relative")
        col.prop(props, "relative_tolerance" if props.relative else "tolerance", text="Viewport")
        col.prop(props, "render_tolerance", text="Render")
        col.prop(props, "angle")
        col.prop(props, "mode")
        col.prop(props, "trim_method")
        col.prop(props, "smooth")
        col.prop(props, "exact_normals")
        col.prop(props, "uv_mode")
        row = layout.row()
        row.operator("object.trimkit_retessellate", icon='FILE_REFRESH')
        row.operator("object.trimkit_check", icon='VIEWZOOM')
        row = layout.row()
        row.operator("object.trimkit_reload", icon='FILE_REFRESH')
        row.operator("object.trimkit_make_lods", icon='MOD_DECIM')
        box = layout.box()
        box.label(text=f"{props.faces} faces, {props.triangles} triangles, {props.seconds:.2f} s")
        if props.lod_level >= 0:
            box.label(text=f"LOD{props.lod_level} of {props.lod_source}", icon='MOD_DECIM')
        for line in props.lod_report.split("; ") if props.lod_report else []:
            box.label(text=line, icon='MOD_DECIM')
        if props.failed_faces:
            box.label(text=f"{props.failed_faces} failed faces", icon='ERROR')
            box.label(text=props.failed_report[:120])
        if props.check_report:
            verdict, _, figures = props.check_report.partition(": ")
            col = box.column(align=True)
            col.label(text=f"Check: {verdict}", icon='ERROR' if props.check_failed else 'CHECKMARK')
            for part in figures.split(", "):
                col.label(text="    " + part)
        draw_check_failures(box, context.object, context)

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
        for k, line in enumerate(props.import_report.splitlines()):  # the triangle estimate, and its warning
            box.label(text=line, icon='INFO' if k == 0 else 'ERROR')


def draw_import_report(layout, report):
    """The import report's first line as file / unit / size, then its warnings in full."""
    lines = report.splitlines()
    if not lines:
        return
    col = layout.column(align=True)
    head, _, size = lines[0].partition(", size ")
    _, _, unit = head.partition(": unit ")
    col.label(text=f"Unit: {unit}", icon='INFO')
    col.label(text=f"Size: {size}")
    for line in lines[1:4]:
        col.label(text=line, icon='ERROR')


# Failed faces listed per object at most (the rest are counted).
LISTED_FAILURES = 12


def draw_check_failures(layout, active, context):
    """The failed faces of the last check, with reasons, for the active object and every
    other selected trimkit object."""
    others = [o for o in getattr(context, "selected_objects", None) or []
              if o is not active and importer.is_trimkit(o) and o.trimkit.check_failed]
    for obj in [active] + sorted(others, key=lambda o: o.name):
        lines = obj.trimkit.check_failed.splitlines()
        if not lines:
            continue
        col = layout.column(align=True)
        col.label(text=f"{obj.name}: {len(lines)} faces fail the check", icon='ERROR')
        for line in lines[:LISTED_FAILURES]:
            col.label(text="    " + line)
        if len(lines) > LISTED_FAILURES:
            col.label(text=f"    ... and {len(lines) - LISTED_FAILURES} more")


def register():
    bpy.utils.register_class(OBJECT_PT_trimkit)


def unregister():
    bpy.utils.unregister_class(OBJECT_PT_trimkit)


def stored_line(text):
    """What the .blend holds of the object's geometry: "Stored: lossless .tkz 55 KB
    (file 1.0 MB, zlib 165 KB)"; "" when the datablock predates the sizes."""
    sizes = stored_source.sizes(text)
    if sizes is None:
        return ""
    form, stored, source, source_zlib = sizes
    what = "lossless .tkz" if form == "tkz" else "file, zlib"
    return f"Stored: {what} {kilobytes(stored)} (file {kilobytes(source)}, zlib {kilobytes(source_zlib)})"


def kilobytes(n):
    return f"{n / 1e6:.1f} MB" if n >= 1e6 else f"{n / 1e3:.0f} KB"
