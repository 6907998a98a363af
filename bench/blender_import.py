"""Blender import timings: a 1M-triangle mesh through blender_mesh.create_mesh, and
bearing.iges / hammer.iges through the import operator at its default tolerance
(0.1 % of the model's diagonal).

    blender -b --factory-startup -P bench/blender_import.py [-- --cad ../shared/data/cad]
"""
import argparse
import pathlib
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "addon"), str(ROOT / "build" / "python")]

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


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser()
    parser.add_argument("--cad", default=str(ROOT.parent / "shared" / "data" / "cad"))
    args = parser.parse_args(argv)
    trimkit.register()

    part = grid_part(708)
    for exact_normals in (False, True):
        start = time.perf_counter()
        me = blender_mesh.create_mesh(part, exact_normals=exact_normals)
        seconds = time.perf_counter() - start
        print(f"blender_mesh.create_mesh: {len(me.polygons)} triangles in {seconds:.2f} s "
              f"(UV map, seams, sharp edges, cad_face, material"
              f"{', exact custom normals' if exact_normals else ''})")

    for name in ("bearing.iges", "hammer.iges"):
        path = pathlib.Path(args.cad) / "iges" / name
        if not path.exists():
            print(f"{name}: skipped, not found under {args.cad}")
            continue
        bpy.ops.wm.read_homefile(use_empty=True)
        start = time.perf_counter()
        result = bpy.ops.import_scene.trimkit_iges(filepath=str(path))
        seconds = time.perf_counter() - start
        objects = [o for o in bpy.data.objects if o.type == 'MESH']
        tris = sum(len(o.data.polygons) for o in objects)
        print(f"{name}: import {seconds:.2f} s ({result}), {len(objects)} objects, {tris} triangles, "
              f"tessellation {objects[0].trimkit.seconds:.2f} s")


main()
