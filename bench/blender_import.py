"""Blender import timings: a 1M-triangle mesh through blender_mesh.create_mesh (total
and each step of blender_mesh.STEPS), and bearing.iges / hammer.iges / screw.step
through the import operators at their default tolerance (0.1 % of the model's diagonal).

    blender -b --factory-startup -P bench/blender_import.py \
        [-- --cad ../shared/data/cad --python build/python --repeat 3]
"""
import argparse
import collections
import functools
import pathlib
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]


def parse():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="bench/blender_import.py")
    parser.add_argument("--cad", default=str(ROOT.parent / "shared" / "data" / "cad"))
    parser.add_argument("--python", default=str(ROOT / "build" / "python"),
                        help="folder holding the built _trimkit module")
    parser.add_argument("--repeat", type=int, default=3, help="create_mesh runs per setting")
    return parser.parse_args(argv)


ARGS = parse()
sys.path[:0] = [str(ROOT / "addon"), ARGS.python]

import bpy  # noqa: E402
import numpy as np  # noqa: E402

import trimkit  # noqa: E402
from trimkit import blender_mesh, io  # noqa: E402


def grid_part(n):
    """An n x n vertex grid on a wavy surface: 2 (n-1)^2 triangles, one CAD face."""
    u, v = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n), indexing="ij")
    positions = np.stack([u, v, 0.05 * np.sin(6 * u) * np.cos(6 * v)], axis=-1).reshape(-1, 3)
    i = np.arange(n - 1)[:, None] * n + np.arange(n - 1)[None, :]
    quads = np.stack([i, i + n, i + n + 1, i + 1], axis=-1).reshape(-1, 4)
    triangles = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]]).astype(np.int32)
    m = len(triangles)
    uv = np.stack([u, v], axis=-1).reshape(-1, 2)
    normals = np.tile(np.array([0, 0, 1], np.float32), (3 * m, 1))
    boundary = np.concatenate([np.stack([np.arange(n - 1), np.arange(1, n)], axis=1)])
    return io.MeshPart(name="grid", kind="MODEL", index=-1, positions=positions, triangles=triangles,
                       face_ids=np.zeros(m, np.int32), corner_uvs=uv[triangles.ravel()].astype(np.float32),
                       corner_normals=normals, edges=boundary.astype(np.int32),
                       edge_flags=np.full(len(boundary), 3, np.uint8),
                       materials=[io.material_name(None)], material_index=np.zeros(m, np.int32))


def load_average():
    return pathlib.Path("/proc/loadavg").read_text().split()[0]


def timed_steps(names):
    """Wraps blender_mesh's step functions so that each call adds its time to the returned dict."""
    seconds = collections.defaultdict(float)

    def wrap(name, step):
        @functools.wraps(step)
        def run(*args, **kwargs):
            start = time.perf_counter()
            try:
                return step(*args, **kwargs)
            finally:
                seconds[name] += time.perf_counter() - start
        return run
    for name in names:
        setattr(blender_mesh, name, wrap(name, getattr(blender_mesh, name)))
    return seconds


def bench_create_mesh(part, repeat):
    """create_mesh without and with exact normals, `repeat` times each, with the steps' times."""
    steps = timed_steps(blender_mesh.STEPS + ("vertex_normals_if_shared",))
    for exact_normals in (False, True):
        for _ in range(repeat):
            steps.clear()
            start, cpu = time.perf_counter(), time.process_time()
            me = blender_mesh.create_mesh(part, exact_normals=exact_normals)
            seconds, cpu = time.perf_counter() - start, time.process_time() - cpu
            print(f"blender_mesh.create_mesh: {len(me.polygons)} triangles in {seconds:.2f} s "
                  f"(CPU {cpu:.2f} s; UV map, seams, sharp edges, cad_face, material"
                  f"{', exact custom normals' if exact_normals else ''}), load average {load_average()}")
            print("    " + ", ".join(f"{name} {t:.3f}" for name, t in steps.items()))
            bpy.data.meshes.remove(me)


def main():
    trimkit.register()
    bench_create_mesh(grid_part(708), ARGS.repeat)

    for relative in ("iges/bearing.iges", "iges/hammer.iges", "step/screw.step"):
        bench_import(pathlib.Path(ARGS.cad) / relative)


def bench_import(path):
    """One CAD file through its import operator at the default tolerance."""
    step = path.suffix == ".step"
    if not path.exists() or (step and not io.has_step()):
        print(f"{path.name}: skipped, not found or no STEP support")
        return
    bpy.ops.wm.read_homefile(use_empty=True)
    operator = bpy.ops.import_scene.trimkit_step if step else bpy.ops.import_scene.trimkit_iges
    start = time.perf_counter()
    result = operator(filepath=str(path))
    seconds = time.perf_counter() - start
    objects = [o for o in bpy.data.objects if o.type == 'MESH']
    tris = sum(len(o.data.polygons) for o in objects)
    print(f"{path.name}: import {seconds:.2f} s ({result}), {len(objects)} objects, {tris} triangles, "
          f"tessellation {objects[0].trimkit.seconds:.2f} s")

main()
