#!/usr/bin/env python3
"""Meshes every IGES file in a folder with `trimkit mesh` and verifies each mesh with
`trimkit check` (issue 3's acceptance): both deviation directions <= the tolerance,
area ratio within 0.2% of 1, failed faces, open edges, triangles and seconds.

usage: bench/mesh_check_all.py [--folder ../shared/data/cad/iges] [--tolerance 0.001]
                               [--files a.igs b.igs ...] [--format ply] [--trimkit build/bin/trimkit]
Tolerance is relative (a fraction of the model's diagonal). Exit status 1 if any file
breaks the guarantee.
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[1]
TRIMKIT = ROOT / "build" / "bin" / "trimkit"
DAMAGED = {"bad_header.igs", "bug22566_test_Bad.igs"}


def run_json(trimkit, *args):
    result = subprocess.run([str(trimkit), *args, "--json"], capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(result.stderr.strip())
    return json.loads(result.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--folder", default=str(ROOT.parent / "shared" / "data" / "cad" / "iges"))
    parser.add_argument("--tolerance", type=float, default=0.001)
    parser.add_argument("--files", nargs="*")
    parser.add_argument("--format", default="ply", choices=["ply", "obj", "stl", "glb"])
    parser.add_argument("--mode", default="guaranteed")
    parser.add_argument("--trim-method", default="bezier3d")
    parser.add_argument("--trimkit", default=str(TRIMKIT), help="the trimkit program to run")
    args = parser.parse_args()

    folder = pathlib.Path(args.folder)
    files = [folder / f for f in args.files] if args.files else sorted(
        p for p in folder.iterdir() if p.suffix.lower() in (".igs", ".iges"))
    print(f"relative tolerance {args.tolerance}, mode {args.mode}, trim method {args.trim_method}")
    print(f"{'file':28s} {'tol':>10s} {'triangles':>9s} {'failed':>6s} {'mesh->surf':>10s} "
          f"{'surf->mesh':>10s} {'area ratio':>10s} {'open':>5s} {'mesh s':>7s}  verdict")
    bad = 0
    with tempfile.TemporaryDirectory() as tmp:
        for path in files:
            out = pathlib.Path(tmp) / (path.stem + "." + args.format)
            try:
                m = run_json(args.trimkit, "mesh", str(path), "-o", str(out), "--relative", "--tolerance",
                             str(args.tolerance), "--mode", args.mode, "--trim-method", args.trim_method)
                c = run_json(args.trimkit, "check", str(path), str(out))
            except RuntimeError as err:
                verdict = "rejected (damaged on purpose)" if path.name in DAMAGED else "ERROR"
                bad += verdict == "ERROR"
                print(f"{path.name:28s} {verdict}: {err}")
                continue
            tol = m["tolerance"]
            d1, d2 = c["mesh_to_surface"]["max"], c["surface_to_mesh"]["max"]
            ok = d1 <= tol and d2 <= tol and abs(c["area_ratio"] - 1) <= 0.002 and not m["failed_faces"]
            if path.name in DAMAGED:
                verdict = "ok" if ok else "damaged file (not judged)"
            else:
                verdict = "ok" if ok else "FAIL"
                bad += not ok
            print(f"{path.name:28s} {tol:10.3g} {m['triangles']:9d} {len(m['failed_faces']):6d} "
                  f"{d1 / tol:9.3f}T {d2 / tol:9.3f}T {c['area_ratio']:10.5f} {c['open_edges']:5d} "
                  f"{m['seconds']['total']:7.2f}  {verdict}")
    print(f"{len(files)} files, {bad} failing")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
