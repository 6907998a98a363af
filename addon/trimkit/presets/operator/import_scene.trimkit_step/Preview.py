import bpy
import math
op = bpy.context.active_operator

op.relative = True
op.relative_tolerance = 0.005
op.angle = math.radians(40)
op.mode = 'approximate'
op.trim_method = 'bezier3d'
op.smooth = True
