"""Command-line conversion inside Blender, calling what the operators call.

    blender -b -P addon/trimkit/batch.py -- --input A.igs [--input B.igs] \\
        --tolerance 0.1 [--relative] --output OUT.(blend|glb|obj)

--tolerance is in the files' units (a fraction of the model's size with
--relative). Prints one line per file; exits 1 with "trimkit batch: FILE: reason"
on failure. From a studio's own script:

    blender -b --python-expr "import trimkit.batch as b; b.convert(['A.igs'], 'A.blend', 0.1)"

.glb and .obj are written by trimkit's own writers (Debian's Blender 3.4 glTF
exporter fails with numpy >= 1.24, which removed np.bool).
"""
import argparse
import math
import pathlib
import sys

if __package__ in (None, ""):  # run as a script: import the package this file is in
    _here = pathlib.Path(__file__).resolve().parent
    sys.path.insert(0, str(_here.parent))
    _build = _here.parents[1] / "build" / "python"  # development checkout: the built module
    if _build.is_dir():
        sys.path.append(str(_build))
    __package__ = _here.name
    import importlib
    importlib.import_module(__package__)

import bpy

from . import importer, io
from . import lods as lods_module
from .settings import DEFAULTS


def ensure_registered():
    """Registers the add-on's classes when the package was imported, not enabled."""
    if not hasattr(bpy.types.Object, "trimkit"):
        sys.modules[__package__].register()


def convert(inputs, output, tolerance, relative=False, angle=math.degrees(DEFAULTS.angle), mode=DEFAULTS.mode,
            trim_method=DEFAULTS.trim_method, split=DEFAULTS.split, clear_scene=True, report=print,
            units=DEFAULTS.units, uv_mode=DEFAULTS.uv_mode, lods=0, lod_factor=4.0, origin=DEFAULTS.origin):
    """Converts CAD files to one output (.blend, .glb or .obj).

    tolerance: in the files' units, or a fraction of each model's diagonal when
    `relative`; angle in degrees. Returns one summary dict per input (failed_faces:
    how many; failed_face_reasons: [(model face id, reason)]; unread_faces: the reasons of
    the faces the reader left out); raises
    RuntimeError/ValueError naming the file on the first failure, before the
    output is written. units: what the files' numbers are ("FILE": their declared
    unit, or MM, CM, M, INCH). lods: with N > 1 (.blend only), each object also gets
    the chain <name>_LOD0.._LOD{N-1} at tolerances growing by lod_factor (lods.py).
    origin (.blend only): "FILE" (the file's) or "BOX" (each object's at its part's box centre).
    """
    output = pathlib.Path(output)
    suffix = output.suffix.lower()
    if suffix not in (".blend", ".glb", ".obj"):
        raise ValueError(f"{output}: expected a .blend, .glb or .obj output")
    if lods > 1 and suffix != ".blend":
        raise ValueError(f"{output}: --lods needs a .blend output")
    summaries, parts = [], []
    if suffix == ".blend":
        ensure_registered()
        if clear_scene:
            bpy.ops.wm.read_homefile(use_empty=True)
    for path in inputs:
        try:
            if suffix == ".blend":
                settings = importer.ImportSettings(relative=relative, relative_tolerance=tolerance,
                                                   angle=math.radians(angle), mode=mode, units=units,
                                                   trim_method=trim_method, split=split, uv_mode=uv_mode,
                                                   origin=origin)
                model, _ = io.read_source(path)
                scale = importer.scene_scale(model, bpy.context.scene, 0.0, units)
                settings.tolerance = tolerance * scale
                objects, result, lines = importer.import_file(bpy.context, path, settings)
                count = len(objects)
                for line in lines[1:] if report else []:
                    report(f"warning: {line}")
                if lods > 1:
                    for obj in objects:
                        lods_module.make_lods(bpy.context, obj, lods, lod_factor)
                        if report:
                            report(f"{obj.name}: {obj.trimkit.lod_report}")
            else:
                model, _ = io.read_source(path)
                metres = importer.model_metres(model, units)
                result = io.tessellate(model, tolerance, relative=relative, angle=math.radians(angle),
                                       mode=mode, trim_method=trim_method, scale=metres,
                                       split=split, stem=pathlib.Path(path).stem, uv_mode=uv_mode, metres=metres)
                placed = io.placed_parts(result.parts, io.placements(model, metres))
                parts += placed
                count = len(placed)
        except (RuntimeError, ValueError, OSError) as err:
            raise type(err)(f"{path}: {err}") from err
        summary = dict(file=str(path), objects=count, faces=result.faces, triangles=result.triangles,
                       failed_faces=len(result.failed_faces), failed_face_reasons=list(result.failed_faces),
                       unread_faces=list(model.unread_faces),
                       tolerance=result.tolerance, seconds=result.seconds)
        summaries.append(summary)
        if report:
            report(f"{pathlib.Path(path).name}: {count} objects, {result.triangles} triangles, "
                   f"{result.faces - len(result.failed_faces)}/{result.faces} faces, "
                   f"tolerance {result.tolerance:.6g}, {result.seconds:.2f} s")
    output.parent.mkdir(parents=True, exist_ok=True)
    if suffix == ".blend":
        bpy.ops.wm.save_as_mainfile(filepath=str(output.resolve()))
    else:
        io.write_mesh(output, parts)
    return summaries


def parse(argv):
    parser = argparse.ArgumentParser(prog="blender -b -P batch.py --",
                                     description="Convert CAD files to .blend, .glb or .obj with trimkit.")
    parser.add_argument("--input", action="append", required=True, help="IGES, STEP or .brep file (repeatable)")
    parser.add_argument("--output", required=True, help="OUT.blend, OUT.glb or OUT.obj")
    parser.add_argument("--tolerance", type=float, required=True,
                        help="in the files' units, or a fraction of the model's size with --relative")
    parser.add_argument("--relative", action="store_true",
                        help="--tolerance is a fraction of each model's diagonal (the importer's default is "
                             f"{DEFAULTS.relative_tolerance:g} of it)")
    parser.add_argument("--angle", type=float, default=math.degrees(DEFAULTS.angle), help="sharp-edge angle, degrees")
    parser.add_argument("--mode", choices=["guaranteed", "approximate"], default=DEFAULTS.mode)
    parser.add_argument("--trim-method", choices=["bezier3d", "yang", "param"], default=DEFAULTS.trim_method)
    parser.add_argument("--split", choices=["BODY", "FACE", "MODEL"], default=DEFAULTS.split)
    parser.add_argument("--units", choices=["FILE", "MM", "CM", "M", "INCH"], default=DEFAULTS.units,
                        help="what the files' numbers are (default: the unit each file declares)")
    parser.add_argument("--uvs", choices=["REAL", "FACE"], default=DEFAULTS.uv_mode,
                        help="REAL: 1 UV unit = 1 m of surface, islands packed; FACE: each CAD face 0-1")
    parser.add_argument("--lods", type=int, default=0, metavar="N",
                        help="also make N levels of detail <name>_LOD0.. per object (.blend output)")
    parser.add_argument("--lod-factor", type=float, default=4.0, help="tolerance factor between levels")
    parser.add_argument("--origin", choices=["FILE", "BOX"], default=DEFAULTS.origin,
                        help="object origins (.blend output): the file's, or each part's bounding-box centre")
    return parser.parse_args(argv)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = parse(argv)
    try:
        convert(args.input, args.output, args.tolerance, relative=args.relative, angle=args.angle,
                mode=args.mode, trim_method=args.trim_method, split=args.split, units=args.units,
                uv_mode=args.uvs, lods=args.lods, lod_factor=args.lod_factor, origin=args.origin)
    except (RuntimeError, ValueError, OSError, ImportError) as err:
        print(f"trimkit batch: {err}", file=sys.stderr)
        sys.exit(1)
    print(f"trimkit batch: wrote {args.output}")


if __name__ == "__main__":
    main()
