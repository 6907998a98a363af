#!/usr/bin/env python3
"""compress -> extend -> check through the `trimkit` CLI (issue 11, a ctest).

    compress_round_trip.py TRIMKIT MODEL...

For each model: `trimkit compress` (default 1 % tolerance), `trimkit extend` to IGES,
`trimkit check MODEL OUT.igs`. Every compressed face's two-sided deviation must be
within the tolerance compress printed for it, every kept face's within 1e-9 of the
model's size (its surface is written bit for bit); the .tkz must not be larger than
the same file with every surface kept. Missing models are skipped with a message.
"""
import pathlib
import re
import subprocess
import sys
import tempfile


def run(cmd):
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {done.returncode}: {done.stderr.strip()}")
    return done.stdout


def check_model(trimkit, model, tmp):
    tkz, igs = tmp / "out.tkz", tmp / "out.igs"
    out = run([trimkit, "compress", model, "-o", str(tkz)])
    tolerance = {int(f): float(t) for f, t in re.findall(r"^face (\d+): compressed .* tolerance (\S+)$", out, re.M)}
    faces = len(re.findall(r"^face \d+:", out, re.M))
    kept, packed = map(int, re.search(r"tkz with every surface kept (\d+), tkz (\d+)", out).groups())
    run([trimkit, "extend", str(tkz), "-o", str(igs)])
    check = run([trimkit, "check", model, str(igs)])
    size = max([float(x) for x in re.findall(r"tolerance ([0-9.eE+-]+)\)?$", out, re.M)] + [1.0]) * 100
    failures = []
    rows = re.findall(r"^face (\d+): A->B avg \S+ max (\S+), B->A avg \S+ max (\S+)$", check, re.M)
    if len(rows) != faces:
        failures.append(f"check reports {len(rows)} faces, compress {faces}")
    for f, ab, ba in rows:
        f, worst = int(f), max(float(ab), float(ba))
        limit = tolerance.get(f, 1e-9 * size)
        if not worst <= limit:
            failures.append(f"face {f} ({'compressed' if f in tolerance else 'kept'}): deviation {worst:g} > {limit:g}")
    if packed > kept:
        failures.append(f".tkz {packed} bytes > {kept} with every surface kept")
    print(f"{model}: {len(tolerance)} of {faces} faces compressed, {packed} of {kept} bytes, "
          f"{len(failures)} failures")
    return failures


def main():
    trimkit, models = sys.argv[1], sys.argv[2:]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        for model in models:
            if not pathlib.Path(model).exists():
                print(f"{model}: not found, skipped")
                continue
            failures += [f"{model}: {f}" for f in check_model(trimkit, model, pathlib.Path(tmp))]
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
