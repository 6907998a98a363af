"""The exact geometry inside the .blend: a CAD file's (or a .tbp solid's) bytes, zlib-compressed, in an
ID property of a Text datablock that objects point to (Object.trimkit.source).
The Text's body only describes it; it survives save, reload and moving the file.

A CAD file is stored as its model in .tkz form with every surface kept (docs/tkz.md)
when that is smaller: lossless (it reads back as the same model, so re-meshing gives the
same mesh and the same guarantee), and 2-3x smaller than the zlib-compressed IGES or
STEP text on the shared files. The sizes are kept for the panel (sizes()).
"""
import bpy

from . import io

KEY = "trimkit_source"
PATH_KEY = "trimkit_path"


FORM_KEY = "trimkit_stored_form"      # "source" or "tkz"
SOURCE_BYTES_KEY = "trimkit_source_bytes"  # the source file's size, and zlib-compressed
SOURCE_ZLIB_KEY = "trimkit_source_zlib_bytes"
STORED_BYTES_KEY = "trimkit_stored_bytes"  # len(text[KEY]), so the panel need not copy it


def store(name, data, path=None, model=None):
    """A new Text datablock holding `data` (the file's bytes) for `name`, or `model`'s
    lossless .tkz when that is smaller, and the path it was read from (Reload from
    Disk reads it again)."""
    text = bpy.data.texts.new(f"trimkit {name}")
    text["trimkit_file"] = name
    if path is not None:
        text[PATH_KEY] = str(path)
    text.use_fake_user = True
    replace(text, data, model)
    return text


def stored_form(data, model):
    """(form, zlib bytes, zlib bytes of the source): the model's lossless .tkz when it
    is smaller than the source, else the source itself."""
    source = io.compress(data)
    if model is not None:
        tkz = io.compress(io.lossless_tkz(model))
        if len(tkz) < len(source):
            return "tkz", tkz, source
    return "source", source, source


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


def replace(text, data, model=None):
    """Stores new bytes of the same file in `text` (Reload from Disk), as the model's
    lossless .tkz when `model` is given and that is smaller."""
    form, stored, source = stored_form(data, model)
    text[KEY] = stored
    text[FORM_KEY] = form
    text[SOURCE_BYTES_KEY] = len(data)
    text[SOURCE_ZLIB_KEY] = len(source)
    text[STORED_BYTES_KEY] = len(stored)
    name = file_name(text)
    what = (f"its model as a lossless .tkz ({len(stored)} bytes zlib-compressed; the file: {len(data)} bytes, "
            f"{len(source)} zlib-compressed)" if form == "tkz" else f"the file ({len(data)} bytes, zlib-compressed)")
    text.clear()
    text.write(f"trimkit: {name} is stored in this datablock's custom property '{KEY}' as\n"
               f"{what}. Objects re-mesh from it.\n")


def sizes(text):
    """(form, stored bytes, source bytes, source zlib bytes) for the panel; None for a
    datablock stored before the sizes were kept."""
    if text is None or FORM_KEY not in text or STORED_BYTES_KEY not in text:
        return None
    return text[FORM_KEY], text[STORED_BYTES_KEY], text.get(SOURCE_BYTES_KEY, 0), text.get(SOURCE_ZLIB_KEY, 0)
