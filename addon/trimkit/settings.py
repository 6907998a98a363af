"""The CAD import settings, declared once: the import operators take their property
defaults from ImportSettings(), the object settings (Object.trimkit) theirs too, and
importer.import_file and batch.convert take an ImportSettings. No bpy.
Lengths in Blender units; angles in radians."""
import dataclasses
import math


@dataclasses.dataclass
class ImportSettings:
    tolerance: float = 0.001          # Blender units, when not relative
    relative: bool = True
    relative_tolerance: float = 0.001  # fraction of the model's diagonal
    render_tolerance: float = 0.0     # Blender units; 0: the viewport tolerance
    angle: float = math.radians(30.0)  # radians
    mode: str = "guaranteed"
    trim_method: str = "bezier3d"
    units: str = "FILE"               # what the file's numbers are: properties.UNIT_ITEMS
    scale: float = 0.0                # model units -> Blender units; 0: from `units`
    split: str = "BODY"               # "BODY", "FACE" or "MODEL"
    origin: str = "FILE"              # object origins: properties.ORIGIN_ITEMS
    smooth: bool = True
    exact_normals: bool = True        # custom split normals from the exact surface
    uv_mode: str = "REAL"             # properties.UV_ITEMS
    read_timeout: float = 120.0       # seconds for reading a file (0: no limit); _trimkit.DEFAULT_READ_TIMEOUT
    face_timeout: float = 30.0        # seconds per CAD face (0: no limit); a slower face fails ("timeout")


DEFAULTS = ImportSettings()
