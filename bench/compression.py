#!/usr/bin/env python3
"""Issue 11 figures: `trimkit compress` on CAD files, then `trimkit extend` and
`trimkit check A B` on the round trip ([Muraki]).

    bench/compression.py [--trimkit build/bin/trimkit] [--tolerance T] FILE...

Per file: faces, faces compressed, source bytes, .tkz with every surface kept, .tkz,
gzip of each, the largest fitting error of a compressed face (as compress measures it,
Sec. 4.4) and the largest two-sided surface deviation of the extended IGES against the
source over the compressed faces (check), printed as a Markdown table row.
"""
import argparse
import gzip
import pathlib
import re
import subprocess
import sys
import tempfile


def run(cmd):
    return subprocess.run(cmd, capture_output=True, text=True, check=True).stdout


def row(trimkit, path, tolerance, tmp):
    tkz = tmp / (path.stem + ".tkz")
    igs = tmp / (path.stem + "_ext.igs")
    cmd = [trimkit, "compress", str(path), "-o", str(tkz)] + (["--tolerance", str(tolerance)] if tolerance else [])
    out = run(cmd)
    compressed = [int(m.group(1)) for m in re.finditer(r"^face (\d+): compressed", out, re.M)]
    faces = len(re.findall(r"^face \d+:", out, re.M))
    errors = [float(x) for x in re.findall(r"^face \d+: compressed .* max (\S+) ratio", out, re.M)]
    tolerance = {int(f): float(t) for f, t in re.findall(r"^face (\d+): compressed .* tolerance (\S+)$", out, re.M)}
    sizes = re.search(r"bytes: source (\d+), tkz with every surface kept (\d+), tkz (\d+)", out)
    source, kept, packed = (int(x) for x in sizes.groups())
    kept_tkz = tmp / (path.stem + "_kept.tkz")
    run([trimkit, "compress", str(path), "-o", str(kept_tkz), "--tolerance", "1e-300"])
    gz = lambda p: len(gzip.compress(pathlib.Path(p).read_bytes(), 9))
    run([trimkit, "extend", str(tkz), "-o", str(igs)])
    check = run([trimkit, "check", str(path), str(igs)])
    deviation, share = 0.0, 0.0  # largest two-sided deviation, and its largest share of the face's tolerance
    for m in re.finditer(r"^face (\d+): A->B avg \S+ max (\S+), B->A avg \S+ max (\S+)", check, re.M):
        f = int(m.group(1))
        if f in compressed:
            d = max(float(m.group(2)), float(m.group(3)))
            deviation, share = max(deviation, d), max(share, d / tolerance[f])
    return (f"| {path.name} | {faces} | {len(compressed)} ({100 * len(compressed) / max(faces, 1):.0f} %) | {source} | "
            f"{kept} | {packed} ({100 * (1 - packed / source):.1f} % / {100 * (1 - packed / kept):.1f} %) | "
            f"{gz(path)} | {gz(kept_tkz)} | {gz(tkz)} | {max(errors, default=0):.3g} | {deviation:.3g} ({share:.2f}) |")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--trimkit", default="build/bin/trimkit")
    parser.add_argument("--tolerance", type=float, default=0.0)
    parser.add_argument("files", nargs="+")
    args = parser.parse_args()
    print("| file | faces | compressed | source B | tkz kept B | tkz B (smaller than source / kept) | "
          "gzip source | gzip kept | gzip tkz | max fit error | max round-trip deviation (/ tolerance) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        for f in args.files:
            try:
                print(row(args.trimkit, pathlib.Path(f), args.tolerance, pathlib.Path(tmp)), flush=True)
            except subprocess.CalledProcessError as e:
                print(f"| {pathlib.Path(f).name} | failed: {e.stderr.strip()[:120]} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
