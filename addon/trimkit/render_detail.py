"""Render detail: final renders (F12, blender -b -f) mesh trimkit objects at their
render tolerance; the viewport meshes come back afterwards. render_pre swaps in
render meshes, render_post / render_cancel restore the originals."""
import bpy
from bpy.app.handlers import persistent

from . import importer

_saved = {}  # object name -> viewport mesh


def render_objects(scene):
    return [o for o in scene.objects
            if importer.is_trimkit(o) and 0.0 < o.trimkit.render_tolerance != o.trimkit.tolerance]


@persistent
def render_pre(scene, _depsgraph=None):
    objects = render_objects(scene)
    for obj in objects:
        obj.data.use_fake_user = True  # keeps it when replace_mesh drops it
        _saved[obj.name] = obj.data
    if objects:
        importer.retessellate(objects, render=True)


@persistent
def render_post(scene, _depsgraph=None):
    for name, mesh in list(_saved.items()):
        obj = scene.objects.get(name)
        if obj is not None and obj.data is not mesh:
            render_mesh = obj.data
            obj.data = mesh
            if render_mesh.users == 0:
                bpy.data.meshes.remove(render_mesh)
        mesh.use_fake_user = False
    _saved.clear()


HANDLERS = [(bpy.app.handlers.render_pre, render_pre), (bpy.app.handlers.render_post, render_post),
            (bpy.app.handlers.render_cancel, render_post)]


def register():
    for handlers, handler in HANDLERS:
        handlers.append(handler)


def unregister():
    for handlers, handler in HANDLERS:
        if handler in handlers:
            handlers.remove(handler)
