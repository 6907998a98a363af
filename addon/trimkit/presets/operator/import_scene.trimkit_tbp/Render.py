import bpy
op = bpy.context.active_operator

# (lod+1)^levels = 16 segments per patch edge: 256 triangles a patch
op.levels = 2
op.lod = 3
