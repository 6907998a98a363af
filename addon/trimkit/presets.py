"""Operator presets (Preview, Render, Export) shipped in presets/ and copied into
the user's preset folder on registration, where Blender's preset menu finds them.
Existing user files are never overwritten."""
import pathlib
import shutil

import bpy

SHIPPED = pathlib.Path(__file__).parent / "presets"


def install():
    for source in SHIPPED.glob("operator/*/*.py"):
        folder = pathlib.Path(bpy.utils.user_resource(
            'SCRIPTS', path=f"presets/operator/{source.parent.name}", create=True))
        target = folder / source.name
        if not target.exists():
            shutil.copyfile(source, target)


def register():
    try:
        install()
    except OSError as err:  # read-only user folder: presets are optional
        print(f"trimkit: operator presets not installed: {err}")


def unregister():
    pass
