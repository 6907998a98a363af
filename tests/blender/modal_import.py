"""The CAD import's modal path in a real Blender window (run under Xvfb by run.py's
test_modal_import_finishes_and_a_cancelled_one_leaves_the_scene_unchanged):

    xvfb-run -a -s "-screen 0 1280x800x24" blender --factory-startup --enable-event-simulate -p 0 0 1280 800 FILE.blend \
        --python tests/blender/modal_import.py -- --input as1-oc-214-mat.stp

Starts the import as the file browser does (run_modal): it must return RUNNING_MODAL,
read and mesh in its working thread, then make the objects from its modal handler.
Then a second import is cancelled while reading with the flag Esc sets
(modal_work.ACTIVE, from the working thread), and a third by a simulated Esc key press
(Blender started with --enable-event-simulate): both must end with the scene's counts
unchanged. Prints "modal: ..." lines; exits 1 on any error.
"""
import argparse
import os
import pathlib
import sys
import time
import traceback

import bpy

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
parser = argparse.ArgumentParser()
parser.add_argument("--input", required=True)
ARGS = parser.parse_args(argv)
PATH = pathlib.Path(ARGS.input)
# Seconds the whole script may take before it gives up.
DEADLINE = 240.0
STATE = {"start": time.perf_counter(), "ticks": 0}


def fail(message=None):
    if message:
        print(f"modal: FAIL {message}")
    else:
        traceback.print_exc()
    sys.stdout.flush()
    os._exit(1)


def counts():
    return (len(bpy.data.objects), len(bpy.data.meshes), len(bpy.data.texts), len(bpy.data.collections))


def start_import():
    window = bpy.context.window_manager.windows[0]
    operator = bpy.ops.import_scene.trimkit_step if PATH.suffix.lower() in (".stp", ".step") \
        else bpy.ops.import_scene.trimkit_iges
    with bpy.context.temp_override(window=window, screen=window.screen, area=window.screen.areas[0]):
        result = operator('EXEC_DEFAULT', filepath=str(PATH), run_modal=True)
    if result != {'RUNNING_MODAL'}:
        fail(f"import returned {result}, expected RUNNING_MODAL")


def first():
    try:
        bpy.ops.preferences.addon_enable(module="trimkit")
        STATE["before"] = counts()
        STATE["t0"] = time.perf_counter()
        start_import()
        print(f"modal: started {PATH.name}: RUNNING_MODAL")
        bpy.app.timers.register(wait_finished, first_interval=0.05)
    except Exception:
        fail()


def ticking():
    STATE["ticks"] += 1
    return 0.05 if time.perf_counter() - STATE["start"] < DEADLINE else fail("deadline passed")


def wait_finished():
    from trimkit import modal_work
    try:
        if modal_work.ACTIVE:
            return 0.05
        after = counts()
        if not after[0] > STATE["before"][0]:
            fail(f"no objects after the modal import: {STATE['before']} -> {after}")
        timing = next(o.trimkit.import_timing for o in bpy.data.objects if o.type == 'MESH')
        total = float(timing.split(": ")[1].split(" s ")[0])
        parts = [float(p.split()[1]) for p in timing.split("(")[1].rstrip(")").split(", ")]
        if abs(total - sum(parts)) > 0.015:
            fail(f"the timing's parts do not sum to its total: {timing}")
        print(f"modal: {timing}")
        print(f"modal: finished in {time.perf_counter() - STATE['t0']:.2f} s ({STATE['ticks']} timer ticks since "
              f"Blender started), objects {STATE['before'][0]} -> {after[0]}")
        STATE["before"] = after
        STATE["t0"] = time.perf_counter()
        start_import()
        cancel_when_reading()
    except Exception:
        fail()
    return None


def cancel_when_reading():
    """Sets the cancel flag from the working thread once the read is under way (what Esc
    does from the modal handler; Blender's main loop under Xvfb is too slow to be sure
    of catching the read from a timer)."""
    from trimkit import modal_work
    if not modal_work.ACTIVE:
        fail("the second import ended before it could be cancelled")
    limits = modal_work.ACTIVE[-1]

    def on_progress(stage, fraction):
        if not limits.cancel.is_set() and (stage != "read" or fraction > 0.3):
            STATE["cancelled_at"] = (stage, fraction, time.perf_counter() - STATE["t0"])
            limits.cancel.set()
    limits.on_progress = on_progress
    bpy.app.timers.register(wait_cancelled, first_interval=0.05)
    return None


def counts_unchanged(what):
    """The scene's counts, which must equal those before `what` started."""
    after = counts()
    if after != STATE["before"]:
        fail(f"{what} changed the scene: {STATE['before']} -> {after}")
    return after


def wait_cancelled():
    from trimkit import modal_work
    if modal_work.ACTIVE:
        return 0.05
    after = counts_unchanged("the cancelled import")
    stage, fraction, at = STATE["cancelled_at"]
    print(f"modal: cancelled at {stage} {fraction:.2f} after {at:.2f} s, ended "
          f"{time.perf_counter() - STATE['t0'] - at:.2f} s later; counts unchanged {after}")
    press_escape()
    return None


def press_escape():
    """A third import, cancelled by an Esc key press (Window.event_simulate; Blender runs
    with --enable-event-simulate) sent right after it started: the modal handler sets the
    flag, the reader stops, the scene's counts stay."""
    STATE["before"] = counts()
    STATE["t0"] = time.perf_counter()
    start_import()
    window = bpy.context.window_manager.windows[0]
    window.event_simulate(type='ESC', value='PRESS')
    window.event_simulate(type='ESC', value='RELEASE')
    bpy.app.timers.register(wait_escaped, first_interval=0.05)


def wait_escaped():
    from trimkit import modal_work
    if modal_work.ACTIVE:
        return 0.05
    after = counts_unchanged("the import cancelled by Esc")
    print(f"modal: Esc pressed at once: ended after {time.perf_counter() - STATE['t0']:.2f} s; "
          f"counts unchanged {after}")
    print("modal: done")
    sys.stdout.flush()
    os._exit(0)


bpy.app.timers.register(ticking, first_interval=0.05)
bpy.app.timers.register(first, first_interval=0.5)
