#!/usr/bin/python3.11
"""Writes a deliberately broken copy of an OBJ mesh, to show that occt_check fails it.

usage: break_mesh.py IN.obj OUT.obj (--drop N | --offset-vertex D | --translate D)
  --drop N           delete every N-th triangle (a hole of one triangle every N)
  --offset-vertex D  move the vertex nearest the mesh's centre of mass by D along its
                     normal (the area-weighted mean of its triangles' normals); it stays
                     connected, so the triangles around it tilt
  --translate D      move every vertex by D along +x
Only `v` and `f` lines are read; normals, UVs and groups are dropped.
"""
import argparse
import math
import sys


def read_obj(path):
    points, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                points.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("f "):
                idx = [int(tok.split("/")[0]) for tok in line.split()[1:]]
                idx = [i - 1 if i > 0 else len(points) + i for i in idx]
                faces.extend([idx[0], idx[k - 1], idx[k]] for k in range(2, len(idx)))
    return points, faces


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input")
    parser.add_argument("output")
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--drop", type=int)
    group.add_argument("--offset-vertex", type=float)
    group.add_argument("--translate", type=float)
    args = parser.parse_args()
    points, faces = read_obj(args.input)
    note = ""
    if args.drop:
        faces = [t for k, t in enumerate(faces) if (k + 1) % args.drop != 0]
    elif args.offset_vertex is not None:
        centre = [sum(p[i] for p in points) / len(points) for i in range(3)]
        used = sorted({v for t in faces for v in t})
        v = min(used, key=lambda i: sum((points[i][k] - centre[k]) ** 2 for k in range(3)))
        # Welded by position: every copy of the vertex (per-face OBJ vertices) moves.
        same = [i for i in used if points[i] == points[v]]
        normal = [0.0, 0.0, 0.0]
        for t in faces:
            if any(points[i] == points[v] for i in t):
                n = cross(sub(points[t[1]], points[t[0]]), sub(points[t[2]], points[t[0]]))
                normal = [normal[k] + n[k] for k in range(3)]
        length = math.sqrt(sum(c * c for c in normal)) or 1.0
        moved = [points[v][k] + args.offset_vertex * normal[k] / length for k in range(3)]
        for i in same:
            points[i] = moved
        note = f"moved vertex at {moved} ({len(same)} copies)"
    else:
        points = [[p[0] + args.translate, p[1], p[2]] for p in points]
    with open(args.output, "w") as out:
        out.write(f"# broken copy of {args.input}\n")
        for p in points:
            out.write(f"v {p[0]!r} {p[1]!r} {p[2]!r}\n")
        for t in faces:
            out.write(f"f {t[0] + 1} {t[1] + 1} {t[2] + 1}\n")
    print(f"{args.output}: {len(points)} vertices, {len(faces)} triangles {note}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
