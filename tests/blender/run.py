"""Blender tests of the trimkit add-on, run inside headless Blender:

    blender -b --factory-startup --python-exit-code 1 --python tests/blender/run.py -- \
        --zip build/trimkit-addon.zip --out build/blender [--cad ../shared/data/cad]

Installs the add-on zip into the user scripts folder (run_all points
BLENDER_USER_SCRIPTS at a temporary one), enables it, and runs every test_*
function; prints PASS/SKIP/FAIL per test and exits 1 if any failed.
"""
import argparse
import math
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time
import traceback

import bpy
import mathutils

ROOT = pathlib.Path(__file__).resolve().parents[2]


class Skip(Exception):
    pass


def parse():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="tests/blender/run.py")
    parser.add_argument("--zip", default=str(ROOT / "build" / "trimkit-addon.zip"))
    parser.add_argument("--out", default=str(ROOT / "build" / "blender"))
    parser.add_argument("--cad", default=str(ROOT.parent / "shared" / "data" / "cad"))
    parser.add_argument("-k", default="", help="run only tests whose name contains this")
    return parser.parse_args(argv)


ARGS = parse()
TMP = pathlib.Path(tempfile.mkdtemp(prefix="trimkit-blender-"))
BRACKET = ROOT / "samples" / "bracket.igs"


def cad_sample(name):
    path = pathlib.Path(ARGS.cad) / "iges" / name
    if not path.exists():
        raise Skip(f"CAD sample {name} not found under {ARGS.cad}")
    return path


def empty_scene():
    bpy.ops.wm.read_homefile(use_empty=True)


def import_iges(path, **options):
    before = set(bpy.data.objects)
    result = bpy.ops.import_scene.trimkit_iges(filepath=str(path), **options)
    assert result == {'FINISHED'}, f"import of {path} returned {result}"
    return sorted((o for o in bpy.data.objects if o not in before), key=lambda o: o.name)


def triangles(objects):
    return sum(len(o.data.polygons) for o in objects)


def face_ids(obj):
    attribute = obj.data.attributes["cad_face"]
    assert attribute.domain == 'FACE' and attribute.data_type == 'INT'
    values = [0] * len(obj.data.polygons)
    attribute.data.foreach_get("value", values)
    return set(values)


def check_mesh(obj):
    """What every created mesh carries."""
    me = obj.data
    assert len(me.polygons) > 0 and all(p.loop_total == 3 for p in me.polygons[:10])
    assert obj.trimkit.triangles == len(me.polygons)
    assert "UVMap" in me.uv_layers, "no UV map"
    uv = me.uv_layers["UVMap"].data
    assert 0.0 <= min(d.uv[0] for d in uv) and max(d.uv[0] for d in uv) <= 1.0 + 1e-4
    assert me.has_custom_normals, "no custom normals"
    assert any(e.use_seam for e in me.edges), "no UV seams on face boundaries"
    assert len(me.materials) >= 1 and me.materials[0] is not None
    assert obj.trimkit.source is not None and obj.trimkit.source_name
    return face_ids(obj)


def select_only(objects):
    for o in bpy.context.view_layer.objects:
        o.select_set(False)
    for o in objects:
        o.select_set(True)
    bpy.context.view_layer.objects.active = objects[0]


def retessellate_with_tolerance(objects, factor):
    for o in objects:
        o.trimkit.relative = False
        o.trimkit.tolerance *= factor
    select_only(objects)
    assert bpy.ops.object.trimkit_retessellate() == {'FINISHED'}
    return triangles(objects)


# -- tests ------------------------------------------------------------------

def test_addon_installs_and_enables_from_zip():
    zip_path = pathlib.Path(ARGS.zip)
    assert zip_path.exists(), f"{zip_path} missing: run scripts/build"
    bpy.ops.preferences.addon_install(filepath=str(zip_path), overwrite=True)
    assert bpy.ops.preferences.addon_enable(module="trimkit") == {'FINISHED'}
    assert hasattr(bpy.types.Object, "trimkit")
    assert hasattr(bpy.ops.import_scene, "trimkit_iges") and hasattr(bpy.ops.object, "trimkit_retessellate")
    presets = bpy.utils.preset_paths("operator/import_scene.trimkit_iges")
    names = {p.name for folder in presets for p in pathlib.Path(folder).glob("*.py")}
    assert {"Preview.py", "Render.py", "Export.py"} <= names, names


def test_bracket_per_face_objects_carry_uvs_normals_cad_face_materials():
    empty_scene()
    objects = import_iges(BRACKET, split='FACE', relative=False, tolerance=0.0001)  # 0.1 mm
    assert [o.name for o in objects] == ["Face.0", "Face.1"]
    assert [check_mesh(o) for o in objects] == [{0}, {1}]
    assert abs(max(max(abs(c) for c in o.dimensions) for o in objects) - 0.12) < 0.03, "mm -> m scale"
    print(f"    bracket per face: {triangles(objects)} triangles")


def test_bracket_one_object_covers_every_face_and_remeshes_both_ways():
    empty_scene()
    objects = import_iges(BRACKET)
    assert len(objects) == 1
    assert check_mesh(objects[0]) == {0, 1}
    start = triangles(objects)
    finer = retessellate_with_tolerance(objects, 0.1)
    coarser = retessellate_with_tolerance(objects, 100.0)
    assert finer > start > coarser, (start, finer, coarser)
    check_mesh(objects[0])
    print(f"    bracket: {start} triangles, x0.1 tolerance {finer}, x10 {coarser}")


def test_bearing_imports_with_every_face_covered():
    path = cad_sample("bearing.iges")
    empty_scene()
    start = time.perf_counter()
    objects = import_iges(path)
    seconds = time.perf_counter() - start
    ids = set()
    for o in objects:
        ids |= check_mesh(o)
    failed = sum(o.trimkit.failed_faces for o in objects)
    assert len(ids) + failed == objects[0].trimkit.faces, (len(ids), failed)
    assert ids == set(range(max(ids) + 1)) or failed
    start_tris = triangles(objects)
    coarser = retessellate_with_tolerance(objects, 4.0)
    assert coarser < start_tris
    print(f"    bearing: {len(objects)} objects, {len(ids)} faces, {start_tris} triangles, "
          f"import {seconds:.2f} s; x4 tolerance: {coarser} triangles")


def test_saved_blend_remeshes_after_moving_it_and_the_source():
    empty_scene()
    source = TMP / "moved_source" / "bracket.igs"
    source.parent.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(BRACKET, source)
    objects = import_iges(source)
    first = triangles(objects)
    saved = TMP / "a" / "scene.blend"
    saved.parent.mkdir(parents=True, exist_ok=True)
    assert bpy.ops.wm.save_as_mainfile(filepath=str(saved)) == {'FINISHED'}
    moved = TMP / "b" / "elsewhere.blend"
    moved.parent.mkdir(parents=True, exist_ok=True)
    shutil.move(str(saved), str(moved))
    shutil.rmtree(source.parent)  # the CAD file is gone: only the .blend holds the geometry
    bpy.ops.wm.open_mainfile(filepath=str(moved))
    objects = [o for o in bpy.data.objects if o.trimkit.source is not None]
    assert len(objects) == 1 and triangles(objects) == first
    finer = retessellate_with_tolerance(objects, 0.25)
    assert finer > first, (first, finer)
    check_mesh(objects[0])


def test_damaged_file_reports_error_and_leaves_scene_unchanged():
    empty_scene()
    damaged = TMP / "damaged.igs"
    damaged.write_bytes(BRACKET.read_bytes()[:2000])
    counts = (len(bpy.data.objects), len(bpy.data.meshes), len(bpy.data.texts))
    try:
        bpy.ops.import_scene.trimkit_iges(filepath=str(damaged))
    except RuntimeError as err:
        message = str(err)
    else:
        raise AssertionError("no error for a damaged file")
    assert "damaged.igs" in message, message
    assert (len(bpy.data.objects), len(bpy.data.meshes), len(bpy.data.texts)) == counts
    print(f"    damaged file: {message.strip().splitlines()[-1]}")


def run_batch(*args):
    batch = pathlib.Path(bpy.utils.user_resource('SCRIPTS', path="addons")) / "trimkit" / "batch.py"
    command = [bpy.app.binary_path, "-b", "--factory-startup", "-P", str(batch), "--", *map(str, args)]
    return subprocess.run(command, capture_output=True, text=True, timeout=300)


def test_batch_converts_two_files_to_glb_and_blend():
    second = cad_sample("hammer.iges") if (pathlib.Path(ARGS.cad) / "iges" / "hammer.iges").exists() else BRACKET
    for suffix in (".glb", ".blend"):
        out = TMP / f"batch{suffix}"
        run = run_batch("--input", BRACKET, "--input", second, "--tolerance", "0.001", "--relative",
                        "--output", out)
        assert run.returncode == 0, run.stderr[-2000:]
        lines = [l for l in run.stdout.splitlines() if "triangles" in l]
        assert len(lines) == 2, run.stdout
        assert out.exists() and out.stat().st_size > 1000
        print(f"    batch {suffix}: " + " | ".join(lines))


def test_batch_fails_clearly_on_a_damaged_file():
    damaged = TMP / "broken.igs"
    damaged.write_text("not an IGES file\n")
    run = run_batch("--input", damaged, "--tolerance", "0.1", "--output", TMP / "broken.glb")
    assert run.returncode != 0
    assert "trimkit batch:" in run.stderr and "broken.igs" in run.stderr, run.stderr
    assert not (TMP / "broken.glb").exists()
    print(f"    batch damaged: {run.stderr.strip().splitlines()[-1]}")


def frame_camera(scene, objects):
    corners = [o.matrix_world @ mathutils.Vector(c) for o in objects for c in o.bound_box]
    low = mathutils.Vector([min(c[i] for c in corners) for i in range(3)])
    high = mathutils.Vector([max(c[i] for c in corners) for i in range(3)])
    center, size = (low + high) / 2, (high - low).length
    camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    scene.collection.objects.link(camera)
    direction = mathutils.Vector((1.0, -1.2, 0.8)).normalized()
    camera.location = center + direction * size * 2.4
    camera.rotation_euler = (-direction).to_track_quat('-Z', 'Y').to_euler()
    camera.data.clip_end = size * 10
    scene.camera = camera
    scene.world = bpy.data.worlds.new("World")
    scene.world.color = (0.6, 0.62, 0.65)


def test_workbench_render_of_hammer_uses_render_tolerance():
    path = cad_sample("hammer.iges")
    empty_scene()
    objects = import_iges(path)
    viewport = triangles(objects)
    rendered = {}

    def count(scene, _depsgraph=None):
        rendered["triangles"] = triangles(objects)
    for o in objects:
        o.trimkit.render_tolerance = o.trimkit.tolerance * 0.25
    scene = bpy.context.scene
    frame_camera(scene, objects)
    scene.render.engine = 'BLENDER_WORKBENCH'
    scene.display.shading.light = 'STUDIO'
    scene.display.shading.color_type = 'MATERIAL'
    scene.render.resolution_x, scene.render.resolution_y = 640, 480
    scene.render.resolution_percentage = 100
    out = pathlib.Path(ARGS.out) / "hammer.png"
    out.parent.mkdir(parents=True, exist_ok=True)
    if out.exists():
        out.unlink()
    scene.render.filepath = str(out)
    bpy.app.handlers.render_post.insert(0, count)
    try:
        bpy.ops.render.render(write_still=True)
    finally:
        bpy.app.handlers.render_post.remove(count)
    assert out.exists() and out.stat().st_size > 10000, f"{out} not written"
    assert rendered["triangles"] > viewport, (rendered, viewport)
    assert triangles(objects) == viewport, "viewport mesh not restored after the render"
    print(f"    hammer: {viewport} triangles viewport, {rendered['triangles']} render -> {out}")


def main():
    tests = [(n, f) for n, f in globals().items() if n.startswith("test_") and ARGS.k in n]
    if ARGS.k and tests[0][0] != "test_addon_installs_and_enables_from_zip":
        tests.insert(0, ("test_addon_installs_and_enables_from_zip", test_addon_installs_and_enables_from_zip))
    failed = skipped = 0
    for name, test in tests:
        start = time.perf_counter()
        try:
            test()
            print(f"PASS {name} ({time.perf_counter() - start:.1f} s)")
        except Skip as why:
            skipped += 1
            print(f"SKIP {name}: {why}")
        except Exception:  # report every failure, keep running the rest
            failed += 1
            print(f"FAIL {name}\n{traceback.format_exc()}")
    shutil.rmtree(TMP, ignore_errors=True)
    print(f"blender tests: {len(tests) - failed - skipped} passed, {skipped} skipped, {failed} failed")
    sys.stdout.flush()
    if failed:
        sys.exit(1)


main()
