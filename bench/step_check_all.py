#!/usr/bin/python3.11
"""Meshes every STEP and .brep file (and, with --iges, every IGES file) with `trimkit mesh`
and measures each mesh against Open CASCADE's own reading of the file with
`occt_reference/occt_check` (issue 9's acceptance: both deviation directions <= T, area
ratio within 0.2% of 1, no failed faces); meshes the same file with OCCT's BRepMesh at the
same absolute tolerance T on one thread (`occt_reference/occt_mesh --threads 1`) for the
timings and triangle counts; prints a markdown table.

usage: bench/step_check_all.py [--tolerance 0.001] [--iges] [--files A.stp B.brep ...]
                               [--trimkit build/bin/trimkit] [--occt build-occt-ref]
                               [--json-out FILE] [--timeout 900]
T = the absolute tolerance trimkit used (--relative --tolerance R: R times its model's
diagonal); where trimkit fails, OCCT meshes at R times its own diagonal and the row says
so. trimkit runs with --threads 1. A trimkit error is recorded in the row and the next
file goes on. Exit status 1 if any file breaks the guarantee or errs.
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[1]
DATA = ROOT.parent / "shared" / "data" / "cad"
AREA_LIMIT = 0.002


def run(cmd, timeout):
    """(exit status, stdout, stderr) of cmd; status None on a timeout."""
    try:
        r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True, timeout=timeout)
        return r.returncode, r.stdout, r.stderr
    except subprocess.TimeoutExpired:
        return None, "", f"timed out after {timeout} s"


def last_json(text):
    for line in reversed(text.strip().splitlines()):
        if line.startswith("{"):
            return json.loads(line)
    return None


def one_line(text, limit=120):
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 3] + "..."


def measure(path, args, tmp):
    """One file's figures: dicts from trimkit mesh, occt_check and occt_mesh, and notes."""
    row = {"file": path.name, "notes": []}
    out = pathlib.Path(tmp) / (path.stem + ".obj")
    status, stdout, stderr = run([args.trimkit, "mesh", path, "-o", out, "--relative", "--tolerance",
                                  args.tolerance, "--threads", "1", "--json"], args.timeout)
    mesh = last_json(stdout) if status == 0 else None
    if mesh is None:
        message = (stderr or stdout or f"exit status {status}").strip()
        row["trimkit_error"] = one_line(message.removeprefix("trimkit: "))
    row["trimkit"] = mesh

    occt = pathlib.Path(args.occt)
    if mesh is not None:
        T = mesh["tolerance"]
        status, stdout, stderr = run([occt / "occt_check", path, out, "--tolerance", repr(T)], args.timeout)
        check = last_json(stdout)
        if check is None or "error" in check:
            row["check_error"] = one_line((check or {}).get("error") or stderr or f"exit status {status}")
            check = None
        row["check"] = check
        # occt_mesh works in OCCT's units: IGES files not in mm are scaled (occt_check's unit).
        unit = check["unit"] if check else 1.0
        occt_args = ["--tolerance", repr(T * unit)]
        if unit != 1.0:
            row["notes"].append(f"OCCT's model is in mm, the file's unit is {unit:g} mm")
    else:
        row["check"] = None
        occt_args = ["-r", str(args.tolerance)]
        row["notes"].append(f"OCCT at r = {args.tolerance} of its own diagonal")
    status, stdout, stderr = run([occt / "occt_mesh", *occt_args, "--threads", "1", path], args.timeout)
    reference = last_json(stdout)
    if reference is None or "error" in reference:
        row["occt_error"] = one_line((reference or {}).get("error") or stderr or f"exit status {status}")
        reference = None
    row["occt"] = reference
    out.unlink(missing_ok=True)
    return row


def verdict(row):
    m, c = row["trimkit"], row["check"]
    if m is None or c is None:
        return "ERROR"
    ok = (c["mesh_to_surface"]["max_T"] <= 1 and c["surface_to_mesh"]["max_T"] <= 1
          and abs(c["area_ratio"] - 1) <= AREA_LIMIT and not m["failed_faces"])
    return "ok" if ok else "FAIL"


def table_row(row):
    m, c, o = row["trimkit"], row["check"], row["occt"]
    cells = [row["file"]]
    cells.append(str(c["faces"]) if c else (str(o["faces"]) if o else "–"))
    if m:
        s = m["seconds"]
        mesh_s = s["total"] - s["read"] - s.get("write", 0.0)
        cells += [f"{m['faces_meshed']}/{m['faces']}", str(len(m["failed_faces"]))]
    else:
        cells += ["–", "–"]
    if c:
        cells += [f"{c['area_ratio']:.5f}", f"{c['mesh_to_surface']['max_T']:.3f}",
                  f"{c['surface_to_mesh']['max_T']:.3f}"]
    else:
        cells += ["–", "–", "–"]
    if m:
        cells += [str(m["open_edges"]), f"{s['read']:.3f}", f"{mesh_s:.3f}", str(m["triangles"])]
    else:
        cells += ["–", "–", "–", "–"]
    if o:
        cells += [f"{o['read_seconds']:.3f}", f"{o['mesh_seconds']:.3f}", str(o["triangles"])]
    else:
        cells += ["–", "–", "–"]
    cells.append(verdict(row))
    notes = list(row["notes"])
    for key, who in (("trimkit_error", "trimkit"), ("check_error", "occt_check"), ("occt_error", "OCCT")):
        if key in row:
            notes.append(f"{who}: {row[key]}")
    if o and o.get("faces_failed"):
        notes.append(f"OCCT failed faces {o['faces_failed']}")
    if c and c["faces"] != (m or {}).get("faces", c["faces"]):
        notes.append(f"faces: OCCT {c['faces']}, trimkit {m['faces']}")
    cells.append("; ".join(notes).replace("|", "/"))
    return "| " + " | ".join(cells) + " |"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tolerance", type=float, default=0.001, help="relative tolerance R")
    parser.add_argument("--iges", action="store_true", help="also every file in iges/")
    parser.add_argument("--files", nargs="*", help="paths (or names under step/, brep/, iges/)")
    parser.add_argument("--trimkit", default=str(ROOT / "build" / "bin" / "trimkit"))
    parser.add_argument("--occt", default=str(ROOT / "build-occt-ref"), help="folder of occt_check, occt_mesh")
    parser.add_argument("--json-out", help="also write each file's raw figures as JSON lines")
    parser.add_argument("--timeout", type=float, default=900, help="seconds per program run")
    args = parser.parse_args()

    folders = ["step", "brep"] + (["iges"] if args.iges else [])
    if args.files:
        files = []
        for name in args.files:
            p = pathlib.Path(name)
            if not p.exists():
                p = next((DATA / f / name for f in ("step", "brep", "iges") if (DATA / f / name).exists()), p)
            files.append(p)
    else:
        files = [p for f in folders for p in sorted((DATA / f).iterdir(), key=lambda p: p.name.lower())]

    header = ["file", "OCCT faces", "trimkit faces meshed", "failed faces", "area ratio",
              "mesh→surface (T)", "surface→mesh (T)", "open edges", "trimkit read s", "trimkit mesh s",
              "trimkit triangles", "OCCT read s", "BRepMesh s", "OCCT triangles", "verdict", "notes"]
    print(f"relative tolerance {args.tolerance}; trimkit {args.trimkit} (--threads 1); "
          f"OCCT BRepMesh at the same T, one thread")
    print()
    print("| " + " | ".join(header) + " |")
    print("|" + "|".join("---" if k in (0, 14, 15) else "--:" for k in range(len(header))) + "|")
    sys.stdout.flush()
    bad = 0
    json_out = open(args.json_out, "w") if args.json_out else None
    with tempfile.TemporaryDirectory() as tmp:
        for path in files:
            row = measure(path, args, tmp)
            bad += verdict(row) != "ok"
            print(table_row(row))
            sys.stdout.flush()
            if json_out:
                json_out.write(json.dumps(row) + "\n")
                json_out.flush()
    print()
    print(f"{len(files)} files, {bad} not ok")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
