#!/usr/bin/env python3
"""Replays the minimised fuzz findings through the `trimkit` CLI (a ctest).

    replay_regressions.py TRIMKIT REGRESSIONS_DIR

REGRESSIONS_DIR/FORMAT/* are inputs that once crashed, hung or leaked in a reader.
Each goes through the command that reads its format: `info` and a coarse `mesh`
for IGES, STEP and .brep, `tbp mesh` for .tbp, `extend` for .tkz, `tbp from-mesh` for OBJ, PLY, STL and GLB.
Every run must end within TIME_LIMIT seconds with exit status 0 or 2 (bad input),
never a signal or an internal error (1); on 2, stderr must be one line
`trimkit: FILE[:LINE]: reason` naming the input. Exits non-zero listing failures.
"""
import pathlib
import subprocess
import sys
import tempfile

TIME_LIMIT = 20.0  # seconds per command; the readers take milliseconds on these inputs

# The input's extension as each reader wants it (the regression files keep
# libFuzzer's names, crash-<sha1>, with the format's extension added).
EXTENSIONS = {"iges": ".igs", "step": ".stp", "brep": ".brep", "tbp": ".tbp", "obj": ".obj", "ply": ".ply",
              "stl": ".stl", "glb": ".glb", "tkz": ".tkz"}


def commands(trimkit, fmt, path, out_dir):
    if fmt in ("iges", "step", "brep"):
        return [[trimkit, "info", path],
                [trimkit, "mesh", path, "-o", str(out_dir / "out.obj"), "--tolerance", "0.02",
                 "--relative", "--threads", "1"]]
    if fmt == "tkz":
        return [[trimkit, "extend", path, "-o", str(out_dir / "out.igs")]]
    if fmt == "tbp":
        return [[trimkit, "tbp", "mesh", path, "--output", str(out_dir / "out.obj"), "--levels", "1",
                 "--lod", "1"]]
    return [[trimkit, "tbp", "from-mesh", path, "--output", str(out_dir / "out.tbp")]]


def check(command, path):
    """A failure message, or None when `command` ended as bad input must."""
    shown = " ".join(command[1:])
    try:
        run = subprocess.run(command, capture_output=True, text=True, errors="replace", timeout=TIME_LIMIT)
    except subprocess.TimeoutExpired:
        return f"{shown}: still running after {TIME_LIMIT:g} s"
    stderr = run.stderr.strip().splitlines()
    if run.returncode < 0:
        return f"{shown}: killed by signal {-run.returncode}: {' | '.join(stderr[-3:])}"
    if run.returncode not in (0, 2):
        return f"{shown}: exit {run.returncode}: {' | '.join(stderr[-3:])}"
    if run.returncode == 2:
        if len(stderr) != 1 or not stderr[0].startswith(f"trimkit: {path}"):
            return f"{shown}: exit 2 but stderr does not name the file in one line: {stderr}"
    return None


def main():
    trimkit, regressions = sys.argv[1], pathlib.Path(sys.argv[2])
    failures, count = [], 0
    with tempfile.TemporaryDirectory() as tmp:
        out_dir = pathlib.Path(tmp)
        for fmt_dir in sorted(p for p in regressions.iterdir() if p.is_dir()):
            fmt = fmt_dir.name
            if fmt not in EXTENSIONS:
                failures.append(f"{fmt_dir}: unknown format folder")
                continue
            for source in sorted(p for p in fmt_dir.iterdir() if p.is_file()):
                if source.suffix != EXTENSIONS[fmt]:
                    failures.append(f"{source}: expected the extension {EXTENSIONS[fmt]}")
                    continue
                count += 1
                for command in commands(trimkit, fmt, str(source), out_dir):
                    failure = check(command, str(source))
                    if failure:
                        failures.append(failure)
                        break
    for failure in failures:
        print("FAIL", failure)
    print(f"replay_regressions: {count} inputs, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
