"""trimkit: import CAD (IGES, STEP) as meshes within a tolerance of the exact surfaces, and
solids of triangular Bézier patches (TBP) at any level of detail, trimmed against each other."""

bl_info = {
    "name": "trimkit CAD import",
    "author": "trimkit",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > IGES / STEP / TBP [trimkit]; Object > Mesh to TBP Solid, Trim by TBP Solid, "
                "Make LODs, Reload from Disk; Edit Mode > Select > Select CAD Face; Properties > Object > trimkit",
    "description": "Trimmed NURBS to meshes with a guaranteed tolerance; re-mesh from the stored geometry",
    "category": "Import-Export",
}


def modules():
    from . import operators, panels, presets, properties, render_detail
    return [properties, operators, panels, render_detail, presets]


def register():
    for module in modules():
        module.register()


def unregister():
    for module in reversed(modules()):
        module.unregister()
