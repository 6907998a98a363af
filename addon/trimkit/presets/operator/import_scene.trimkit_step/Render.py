import bpy
import math
op = bpy.context.active_operator

op.relative = True
op.relative_tolerance = 0.0005
op.angle = math.radians(20)
op.mode = 'guaranteed'
op.trim_method = 'bezier3d'
op.smooth = True
