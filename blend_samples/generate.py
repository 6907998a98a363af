"""Writes the sample .blend files in this folder: each CAD sample imported with the
trimkit add-on at its default settings (0.1 % of the model's size), the exact
geometry stored inside, saved compressed.

    blender -b --factory-startup -P blend_samples/generate.py [-- --cad ../shared/data/cad]
"""
import argparse
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "addon"), str(ROOT / "build" / "python")]

import bpy  # noqa: E402

import trimkit  # noqa: E402


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser()
    parser.add_argument("--cad", default=str(ROOT.parent / "shared" / "data" / "cad"))
    args = parser.parse_args(argv)
    trimkit.register()
    samples = [ROOT / "samples" / "bracket.igs", pathlib.Path(args.cad) / "iges" / "hammer.iges"]
    for path in samples:
        if not path.exists():
            print(f"blend_samples: {path.name} skipped, not found")
            continue
        bpy.ops.wm.read_homefile(use_empty=True)
        if bpy.ops.import_scene.trimkit_iges(filepath=str(path)) != {'FINISHED'}:
            sys.exit(f"blend_samples: import of {path} failed")
        out = ROOT / "blend_samples" / (path.stem + ".blend")
        bpy.ops.wm.save_as_mainfile(filepath=str(out), compress=True)
        triangles = sum(len(o.data.polygons) for o in bpy.data.objects if o.type == 'MESH')
        print(f"blend_samples: {out.relative_to(ROOT)}: {triangles} triangles, {out.stat().st_size // 1024} KB")


main()
