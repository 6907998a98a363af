#!/usr/bin/python3.11
"""[Muraki] Fig. 15 for our compression: the normals along the G1 edges of rebuilt faces
against their neighbours' normals, drawn from the check compress_model makes
(_trimkit.g1_normals: 50 points per G1 edge, each projected on both surfaces).

    PYTHONPATH=build/python bench/g1_normals.py [MODEL] [--out bench/plots/g1_normals.png]

Left: the compressed face with the most G1 edges, its edge points, its normals (red) and
the neighbours' (blue, drawn shorter so both show). Right: the angle between the two normals
at every sample of every compressed face, against compress_model's limit (0.5 degrees).
Prints the figures.
"""
import argparse
import pathlib
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import _trimkit  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
LIMIT = 0.5  # degrees: fit/g1_angle.h kMaxG1Angle


def samples(model):
    """(compressed model, extended model, {face: (points, normals, neighbour normals, angles)})
    of the faces compressed with at least one G1 edge."""
    compressed, report = _trimkit.compress_model(model)
    extended = _trimkit.extend_model(compressed)
    out = {}
    for f, r in enumerate(report):
        if r.compressed and r.g1_edges:
            points, normals, neighbours, angles = _trimkit.g1_normals(compressed, extended, f)
            if len(angles):
                out[f] = (np.asarray(points), np.asarray(normals), np.asarray(neighbours), np.asarray(angles))
    return out


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("model", nargs="?", default=str(ROOT.parent / "shared" / "data" / "cad" / "brep" / "bottle.brep"))
    parser.add_argument("--out", default=str(ROOT / "bench" / "plots" / "g1_normals.png"))
    args = parser.parse_args()
    faces = samples(_trimkit.read_model(args.model))
    if not faces:
        print(f"{args.model}: no compressed face with a G1 edge")
        return 1
    # The face whose G1 edges spread most in their second direction (not a thin strip).
    face = max(faces, key=lambda f: np.sort(np.ptp(faces[f][0], axis=0))[1])
    points, normals, neighbours, angles = faces[face]
    # Neighbour normals point whichever way its face is oriented: drawn on the rebuilt side.
    neighbours = neighbours * np.sign(np.sum(neighbours * normals, axis=1))[:, None]
    every = np.concatenate([a for (_, _, _, a) in faces.values()])
    size = np.ptp(points, axis=0).max() or 1.0

    fig = plt.figure(figsize=(12, 5.5))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    ax.plot(*points.T, ".", color="black", markersize=2)
    shown = slice(None, None, 4)
    ax.quiver(*points[shown].T, *(0.25 * size * normals[shown]).T, color="tab:red", linewidth=1.0,
              label="rebuilt face")
    ax.quiver(*points[shown].T, *(0.18 * size * neighbours[shown]).T, color="tab:blue", linewidth=1.6,
              label="neighbour")
    centre = 0.5 * (points.min(axis=0) + points.max(axis=0))
    for set_lim, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        set_lim(c - 0.65 * size, c + 0.65 * size)
    ax.set_title(f"{pathlib.Path(args.model).name}, face {face}: {len(angles)} samples, max {angles.max():.3f} deg")
    ax.legend(loc="upper left")
    ax2 = fig.add_subplot(1, 2, 2)
    ax2.hist(every, bins=40, color="tab:gray")
    ax2.axvline(LIMIT, color="tab:red", linestyle="--", label=f"limit {LIMIT} deg")
    ax2.set_xlabel("angle between the normals (degrees)")
    ax2.set_ylabel("samples")
    ax2.set_title(f"{len(faces)} compressed faces with G1 edges, {len(every)} samples")
    ax2.legend()
    fig.tight_layout()
    pathlib.Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.out, dpi=110)
    print(f"{pathlib.Path(args.model).name}: {len(faces)} compressed faces with G1 edges, {len(every)} samples, "
          f"angle mean {every.mean():.3f} max {every.max():.3f} deg (limit {LIMIT}); face {face} max "
          f"{angles.max():.3f}; plot {args.out}")
    return 0 if every.max() <= LIMIT else 1


if __name__ == "__main__":
    sys.exit(main())
