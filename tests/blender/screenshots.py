"""Screenshots of the trimkit add-on in a real Blender window (run under Xvfb by
run.py's test_screenshots_of_panel_import_options_and_checked_assembly):

    xvfb-run -a -s "-screen 0 1600x1000x24" blender --factory-startup -p 0 0 1600 1000 \
        --python tests/blender/screenshots.py -- --out build/blender --input as1-oc-214-mat.stp

Imports the assembly, checks every part (colours by the check in the viewport), shows
the trimkit panel, then opens File > Import > IGES [trimkit] and captures its option
groups. Writes checked_assembly.png, panel.png, import_options.png and a line
"screenshots: NAME WIDTHxHEIGHT" per file; exits 1 on any error.
"""
import argparse
import pathlib
import sys
import traceback

import bpy

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
parser = argparse.ArgumentParser()
parser.add_argument("--out", required=True)
parser.add_argument("--input", required=True)
parser.add_argument("--browse", required=True, help="the file the import dialog opens at")
ARGS = parser.parse_args(argv)
OUT = pathlib.Path(ARGS.out)
OUT.mkdir(parents=True, exist_ok=True)


def fail():
    traceback.print_exc()
    sys.stdout.flush()
    import os
    os._exit(1)


def area_of(window, kind):
    return next(a for a in window.screen.areas if a.type == kind)


def region_of(area, kind='WINDOW'):
    return next(r for r in area.regions if r.type == kind)


def shoot(name, window, area=None):
    path = OUT / name
    if path.exists():
        path.unlink()
    with bpy.context.temp_override(window=window, area=area or window.screen.areas[0], screen=window.screen):
        if area is None:
            bpy.ops.screen.screenshot(filepath=str(path))
        else:
            bpy.ops.screen.screenshot_area(filepath=str(path))
    image = bpy.data.images.load(str(path))
    print(f"screenshots: {name} {image.size[0]}x{image.size[1]}")
    bpy.data.images.remove(image)


def step_import():
    try:
        bpy.ops.preferences.addon_enable(module="trimkit")
        window = bpy.context.window_manager.windows[0]
        for obj in list(bpy.data.objects):
            bpy.data.objects.remove(obj)
        path = pathlib.Path(ARGS.input)
        operator = bpy.ops.import_scene.trimkit_step if path.suffix.lower() in (".stp", ".step") \
            else bpy.ops.import_scene.trimkit_iges
        with bpy.context.temp_override(window=window):
            assert operator(filepath=str(path)) == {'FINISHED'}
            for obj in bpy.context.view_layer.objects:
                obj.select_set(obj.type == 'MESH')
            bpy.context.view_layer.objects.active = max(
                (o for o in bpy.context.view_layer.objects if o.type == 'MESH'), key=lambda o: o.trimkit.faces)
            assert bpy.ops.object.trimkit_check() == {'FINISHED'}
        view = area_of(window, 'VIEW_3D')
        shading = view.spaces[0].shading
        shading.type = 'SOLID'
        shading.color_type = 'VERTEX'  # the active colour attribute: the check's colours
        view.spaces[0].overlay.show_floor = False
        with bpy.context.temp_override(window=window, area=view, region=region_of(view)):
            bpy.ops.view3d.view_all()
        return 1.0
    except Exception:
        fail()


def step_layout():
    try:
        window = bpy.context.window_manager.windows[0]
        # A wide Properties editor: the 3D viewport split, its right third made one.
        view = area_of(window, 'VIEW_3D')
        before = set(window.screen.areas)
        with bpy.context.temp_override(window=window, screen=window.screen, area=view, region=region_of(view)):
            bpy.ops.screen.area_split(direction='VERTICAL', factor=0.62)
        new = [a for a in window.screen.areas if a not in before]
        right = max([view] + new, key=lambda a: a.x)
        right.type = 'PROPERTIES'  # its Object tab is chosen once it has been drawn
    except Exception:
        fail()


def step_scroll_to_panel():
    try:
        window = bpy.context.window_manager.windows[0]
        properties = max((a for a in window.screen.areas if a.type == 'PROPERTIES'), key=lambda a: a.width)
        properties.spaces[0].context = 'OBJECT'
        region = region_of(properties)
        with bpy.context.temp_override(window=window, area=properties, region=region):
            for _ in range(40):
                bpy.ops.view2d.scroll_down(deltax=0, deltay=60)
        view = area_of(window, 'VIEW_3D')
        with bpy.context.temp_override(window=window, area=view, region=region_of(view)):
            bpy.ops.view3d.view_all()
        return 1.0
    except Exception:
        fail()


def step_shoot_scene():
    try:
        window = bpy.context.window_manager.windows[0]
        shoot("checked_assembly.png", window)
        shoot("panel.png", window, max((a for a in window.screen.areas if a.type == 'PROPERTIES'),
                                       key=lambda a: a.width))
        with bpy.context.temp_override(window=window, area=area_of(window, 'VIEW_3D')):
            bpy.ops.import_scene.trimkit_iges('INVOKE_DEFAULT', filepath=ARGS.browse)
        return 2.0
    except Exception:
        fail()


def step_shoot_import_options():
    try:
        windows = [w for w in bpy.context.window_manager.windows
                   if any(a.type == 'FILE_BROWSER' for a in w.screen.areas)]
        assert windows, "the file browser did not open"
        window = windows[0]
        browser = area_of(window, 'FILE_BROWSER')
        browser.spaces[0].show_region_tool_props = True  # the operator's options sidebar
        return None
    except Exception:
        fail()


def step_quit():
    print("screenshots: done")
    sys.stdout.flush()
    import os
    os._exit(0)


def step_shoot_browser():
    try:
        window = next(w for w in bpy.context.window_manager.windows
                      if any(a.type == 'FILE_BROWSER' for a in w.screen.areas))
        shoot("import_options.png", window)
    except Exception:
        fail()


STEPS = [step_import, step_layout, step_scroll_to_panel, step_shoot_scene, step_shoot_import_options, step_shoot_browser]


def run_steps():
    step = STEPS.pop(0)
    step()
    if STEPS:
        return 1.5
    bpy.app.timers.register(step_quit, first_interval=1.0)
    return None


bpy.app.timers.register(run_steps, first_interval=2.0)
