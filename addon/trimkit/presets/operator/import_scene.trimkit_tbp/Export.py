import bpy
op = bpy.context.active_operator

# (lod+1)^levels = 9 segments per patch edge: 81 triangles a patch
op.levels = 2
op.lod = 2
