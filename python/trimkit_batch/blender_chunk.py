"""The script Blender runs on a chunk of files for --format blend (blend.py starts it):

    blender -b --factory-startup --python-exit-code 1 -P blender_chunk.py -- CHUNK.json RESULTS.jsonl

CHUNK.json: {"path": [folders for sys.path], "settings": Settings.as_dict(),
"jobs": [{"input", "output"}]}. Each file goes through the add-on's batch.convert into
its own .blend (an empty scene each), written under a temporary name and renamed.
RESULTS.jsonl gets "ready" once the add-on is loaded, then one Outcome (with "input")
per file as it finishes, flushed, so that the worker sees progress and, if Blender dies,
which file it died on. Blender keeps instances as linked duplicates: triangles count
each mesh once, and failed faces are numbered as the model's faces. With --check each object's mesh is measured as
object.trimkit_check does, after the file is saved (the .blend does not get the colours).
"""
import dataclasses
import json
import os
import pathlib
import sys
import threading
import time


def main():
    argv = sys.argv[sys.argv.index("--") + 1:]
    request = json.loads(pathlib.Path(argv[0]).read_text())
    sys.path[:0] = request["path"]
    from trimkit import batch, importer, mesh_check
    from trimkit_batch import outputs
    from trimkit_batch.isolated import exit_with_parent
    threading.Thread(target=exit_with_parent, args=(os.getppid(),), daemon=True).start()  # a killed worker
    from trimkit_batch.outcome import OK, Outcome, failed, failed_face

    settings = request["settings"]

    def convert(job):
        start = time.perf_counter()
        if pathlib.Path(job["input"]).suffix.lower() == ".tbp":
            return failed(f"{job['input']}: a .tbp solid is not converted to .blend by batch.convert "
                          "(--format glb, ply, obj or stl polygonizes it)")
        summaries = []
        try:
            size = outputs.write_atomically(job["output"], lambda path: summaries.extend(batch.convert(
                [job["input"]], path, settings["tolerance"], relative=settings["relative"],
                angle=settings["angle"], mode=settings["mode"], trim_method=settings["trim_method"], report=None)))
            deviation = scene_deviation(importer, mesh_check) if settings["check"] else None
        except (RuntimeError, ValueError, OSError) as err:
            return failed(err, time.perf_counter() - start)
        summary = summaries[0]
        return Outcome(status=OK, triangles=summary["triangles"],
                       failed_faces=[failed_face(f, reason) for f, reason in summary["failed_face_reasons"]],
                       unread_faces=summary.get("unread_faces", []),
                       deviation=deviation, seconds=time.perf_counter() - start, output_bytes=size)

    with open(argv[1], "a", encoding="utf-8") as results:
        def say(message):
            results.write(json.dumps(message) + "\n")
            results.flush()

        say("ready")
        for job in request["jobs"]:
            say(dict(input=job["input"], **dataclasses.asdict(convert(job))))


def scene_deviation(importer, mesh_check):
    """The largest two-sided deviation over the scene's trimkit meshes (each mesh once),
    model units, as outcome.deviation_figures lays them out."""
    import bpy
    from trimkit_batch.outcome import finite
    seen, worst, area_mesh, area_exact, open_edges, tolerance = set(), [0.0, 0.0], 0.0, 0.0, 0, 0.0
    for obj in bpy.data.objects:
        if not importer.is_trimkit(obj) or obj.data.name in seen:
            continue
        seen.add(obj.data.name)
        report, tolerance = mesh_check.check_object(obj)
        worst = [max(worst[0], report.mesh_to_surface), max(worst[1], report.surface_to_mesh)]
        area_mesh += report.area_mesh
        area_exact += report.area_exact
        open_edges += report.open_edges
    return {"mesh_to_surface": finite(worst[0]), "surface_to_mesh": finite(worst[1]),
            "area_ratio": finite(area_mesh / area_exact) if area_exact > 0.0 else None,
            "open_edges": open_edges, "tolerance": finite(tolerance)}


if __name__ == "__main__":
    main()
