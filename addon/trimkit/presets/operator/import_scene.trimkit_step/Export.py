import bpy
import math
op = bpy.context.active_operator

op.relative = True
op.relative_tolerance = 0.001
op.angle = math.radians(30)
op.mode = 'guaranteed'
op.trim_method = 'bezier3d'
op.smooth = True
