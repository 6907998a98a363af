"""The exact geometry inside the .blend: a CAD file's (or a .tbp solid's) bytes, zlib-compressed, in an
ID property of a Text datablock that objects point to (Object.trimkit.source).
The Text's body only describes it; it survives save, reload and moving the file.
"""
import bpy

from . import io

KEY = "trimkit_source"
PATH_KEY = "trimkit_path"


def store(name, data, path=None):
    """A new Text datablock holding `data` (the file's bytes) for `name`, and the path
    it was read from (Reload from Disk reads it again)."""
    text = bpy.data.texts.new(f"trimkit {name}")
    text[KEY] = io.compress(data)
    text["trimkit_file"] = name
    if path is not None:
        text[PATH_KEY] = str(path)
    text.use_fake_user = True
    text.write(f"trimkit: the file {name} ({len(data)} bytes, zlib-compressed) is stored in\n"
               f"this datablock's custom property '{KEY}'. Objects re-mesh from it.\n")
    return text


def load(text):
    """The stored file's bytes; ValueError if `text` holds none."""
    if text is None or KEY not in text:
        raise ValueError("no stored CAD geometry (Object.trimkit.source is empty)")
    return io.decompress(bytes(text[KEY]))


def file_name(text):
    return text.get("trimkit_file", text.name)


def source_path(text):
    """The path the stored file was read from; '' when unknown."""
    return text.get(PATH_KEY, "") if text is not None else ""


def replace(text, data):
    """Stores new bytes of the same file in `text` (Reload from Disk)."""
    text[KEY] = io.compress(data)
