import bpy
op = bpy.context.active_operator

# (lod+1)^levels = 2 segments per patch edge: 4 triangles a patch
op.levels = 1
op.lod = 1
