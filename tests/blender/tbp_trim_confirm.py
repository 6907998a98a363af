"""The TBP trim's confirmation in a real Blender window (run under Xvfb by run.py's
test_tbp_trim_asks_before_a_trim_above_500k_triangles_when_invoked):

    xvfb-run -a -s "-screen 0 1280x800x24" blender --factory-startup --enable-event-simulate -p 0 0 1280 800 FILE.blend \
        --python tests/blender/tbp_trim_confirm.py -- --cube cube.tbp --square square.tbp --far far.tbp --out build/blender

Invoked as the menu does (INVOKE_DEFAULT): a trim estimated above 500000 triangles
(the square's 2 patches at levels 3, lod 7: 2 x 8^6 = 524288) must ask first and change
nothing until confirmed (screenshot confirm_trim.png of the question; Esc then leaves
the scene as it was); a trim below it (the square at its own levels 2, lod 1, cut by the
cube) must run at once (screenshot tbp_trim_panel.png of its trimkit panel). Prints "confirm: ..." lines; exits 1 on any error.
"""
import argparse
import os
import pathlib
import sys
import traceback

import bpy

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
parser = argparse.ArgumentParser()
for name in ("--cube", "--square", "--far", "--out"):
    parser.add_argument(name, required=True)
ARGS = parser.parse_args(argv)
STATE = {}


def fail(message=None):
    if message:
        print(f"confirm: FAIL {message}")
    else:
        traceback.print_exc()
    sys.stdout.flush()
    os._exit(1)


def counts():
    return (len(bpy.data.objects), len(bpy.data.meshes))


def window_and_view():
    window = bpy.context.window_manager.windows[0]
    view = next(a for a in window.screen.areas if a.type == 'VIEW_3D')
    return window, view


def import_tbp(path, levels, lod, location=None):
    before = set(bpy.data.objects)
    assert bpy.ops.import_scene.trimkit_tbp(filepath=path, levels=levels, lod=lod) == {'FINISHED'}
    (obj,) = [o for o in bpy.data.objects if o not in before]
    if location:
        obj.location = location
    return obj


def select(active, other):
    for o in bpy.context.view_layer.objects:
        o.select_set(False)
    active.hide_set(False)
    active.select_set(True)
    other.select_set(True)
    bpy.context.view_layer.objects.active = active


def invoke_trim(**options):
    window, view = window_and_view()
    region = next(r for r in view.regions if r.type == 'WINDOW')
    with bpy.context.temp_override(window=window, screen=window.screen, area=view, region=region):
        return bpy.ops.object.trimkit_trim('INVOKE_DEFAULT', keep='outside', **options)


def first():
    try:
        bpy.ops.preferences.addon_enable(module="trimkit")
        for obj in list(bpy.data.objects):
            bpy.data.objects.remove(obj)
        STATE["cube"] = import_tbp(ARGS.cube, 1, 1)
        STATE["far"] = import_tbp(ARGS.far, 1, 1, (5.0, 0.0, 0.0))
        STATE["square"] = import_tbp(ARGS.square, 2, 1, (0.5, 0.5, 0.0))
        bpy.context.view_layer.update()
        select(STATE["square"], STATE["far"])
        STATE["before"] = counts()
        result = invoke_trim(levels=3, lod=7)
        if 'FINISHED' in result or counts() != STATE["before"]:
            fail(f"a trim estimated at 524288 triangles ran without asking: {result}, "
                 f"{STATE['before']} -> {counts()}")
        print(f"confirm: levels 3, lod 7 (524288 triangles estimated) invoked: {sorted(result)}, "
              f"counts unchanged {counts()}")
        bpy.app.timers.register(shoot_question, first_interval=1.0)
    except Exception:
        fail()


def shoot_question():
    try:
        window, _ = window_and_view()
        path = pathlib.Path(ARGS.out) / "confirm_trim.png"
        path.parent.mkdir(parents=True, exist_ok=True)
        with bpy.context.temp_override(window=window, screen=window.screen, area=window.screen.areas[0]):
            bpy.ops.screen.screenshot(filepath=str(path))
        print(f"confirm: screenshot {path.name}")
        window.event_simulate(type='ESC', value='PRESS')
        window.event_simulate(type='ESC', value='RELEASE')
        bpy.app.timers.register(after_escape, first_interval=1.0)
    except Exception:
        fail()


def after_escape():
    try:
        if counts() != STATE["before"]:
            fail(f"Esc on the question changed the scene: {STATE['before']} -> {counts()}")
        print(f"confirm: Esc: counts unchanged {counts()}")
        square, cube = STATE["square"], STATE["cube"]
        select(square, cube)
        result = invoke_trim()
        trimmed = bpy.context.view_layer.objects.active
        if result != {'FINISHED'} or trimmed is square or counts()[0] != STATE["before"][0] + 1:
            fail(f"the small trim did not run at once: {result}, {STATE['before']} -> {counts()}")
        props = trimmed.trimkit
        if (props.tbp_levels, props.tbp_lod) != (2, 1) or \
                props.import_report != "estimate 32 triangles (2 patches at levels 2, lod 1)":
            fail(f"the small trim: levels {props.tbp_levels}, lod {props.tbp_lod}, report {props.import_report!r}")
        print(f"confirm: no levels/lod (the square's 2, 1): FINISHED at once, {len(trimmed.data.polygons)} "
              f"triangles, {props.import_report}")
        # A wide Properties editor for the panel: the 3D viewport split, its right part made one.
        window, view = window_and_view()
        before = set(window.screen.areas)
        region = next(r for r in view.regions if r.type == 'WINDOW')
        with bpy.context.temp_override(window=window, screen=window.screen, area=view, region=region):
            bpy.ops.screen.area_split(direction='VERTICAL', factor=0.55)
        new = [a for a in window.screen.areas if a not in before]
        max([view] + new, key=lambda a: a.x).type = 'PROPERTIES'
        bpy.app.timers.register(scroll_panel, first_interval=1.0)
    except Exception:
        fail()


def widest_properties(window):
    return max((a for a in window.screen.areas if a.type == 'PROPERTIES'), key=lambda a: a.width)


def scroll_panel():
    try:
        window, _ = window_and_view()
        properties = widest_properties(window)
        properties.spaces[0].context = 'OBJECT'
        region = next(r for r in properties.regions if r.type == 'WINDOW')
        with bpy.context.temp_override(window=window, area=properties, region=region):
            for _ in range(40):  # down to the trimkit panel, below Object's own
                bpy.ops.view2d.scroll_down(deltax=0, deltay=60)
        bpy.app.timers.register(shoot_panel, first_interval=1.0)
    except Exception:
        fail()


def shoot_panel():
    """The trimkit panel of the trim: levels, lod, keep and the estimate line."""
    try:
        window, _ = window_and_view()
        properties = widest_properties(window)
        path = pathlib.Path(ARGS.out) / "tbp_trim_panel.png"
        with bpy.context.temp_override(window=window, screen=window.screen, area=properties):
            bpy.ops.screen.screenshot_area(filepath=str(path))
        print(f"confirm: screenshot {path.name}")
        print("confirm: done")
        sys.stdout.flush()
        os._exit(0)
    except Exception:
        fail()


bpy.app.timers.register(first, first_interval=1.0)
