"""What a conversion is asked for, declared once: the command line fills it, every task
reads it, and the manifest stores it with each input so that a rerun skips a file only
when it was converted with equal settings.

Lengths: `tolerance` is in each file's own units, or with `relative` a fraction of the
diagonal of the model's bounding box (instances placed), as `trimkit mesh --relative`.
`angle` is in degrees. `levels` and `lod` apply to .tbp inputs only (`trimkit tbp mesh`).
Settings that change nothing in an output or its manifest line (workers, timeout) are
not part of it.
"""
import dataclasses

MESH_FORMATS = ("glb", "ply", "obj", "stl")
FORMATS = MESH_FORMATS + ("blend",)
MODES = ("guaranteed", "approximate")
TRIM_METHODS = ("bezier3d", "yang", "param")
SPLITS = ("files", "parts")

# Without --tolerance: 0.1 % of each model's diagonal (scripts/demo's choice).
DEFAULT_RELATIVE_TOLERANCE = 0.001


@dataclasses.dataclass(frozen=True)
class Settings:
    format: str = "glb"
    tolerance: float = DEFAULT_RELATIVE_TOLERANCE
    relative: bool = True
    angle: float = 30.0          # sharp-edge angle, degrees
    mode: str = "guaranteed"
    trim_method: str = "bezier3d"
    split: str = "files"         # "files": one task per file; "parts": one per unique assembly part
    check: bool = False          # measure each mesh's two-sided deviation (trimkit check)
    levels: int = 2              # .tbp inputs: hierarchy level L ...
    lod: int = 3                 # ... and lod K, (K+1)^L segments per patch edge

    def __post_init__(self):
        for name, value, allowed in (("format", self.format, FORMATS), ("mode", self.mode, MODES),
                                     ("trim_method", self.trim_method, TRIM_METHODS),
                                     ("split", self.split, SPLITS)):
            if value not in allowed:
                raise ValueError(f"Settings: {name} = {value!r}; expected one of {', '.join(allowed)}")
        if not self.tolerance > 0.0:
            raise ValueError(f"Settings: tolerance = {self.tolerance}; it must be > 0")
        if self.split == "parts" and self.format == "blend":
            raise ValueError("Settings: --split parts writes mesh files (glb, ply, obj, stl); a .blend "
                             "already keeps each part once, placed by linked duplicates")

    def as_dict(self):
        return dataclasses.asdict(self)

    @property
    def suffix(self):
        return "." + self.format
