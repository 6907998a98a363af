"""trimkit-batch --split parts: an assembly meshed one unique part per task, then written
with every instance placed. Checked against the exact model with its instances placed
(what `trimkit mesh` meshes): the written mesh covers every placed face within the
tolerance, and its triangle count is the part's count times its placements."""
import collections
import pathlib

import numpy as np
import pytest

import _trimkit
from batch_support import mesh_reference, read_manifest, run_batch
from conftest import CAD
from iges_samples import write_bracket_assembly

pytest.importorskip("distributed")

TOLERANCE = 0.05
# The PLY writer stores float32 positions: rounding of coordinates up to ~400 mm.
FLOAT32_SLACK = 1e-4


def read_ply(path):
    """(positions (n, 3), triangles (m, 3), face ids (m,)) of a trimkit PLY (x y z nx ny nz u v)."""
    data = pathlib.Path(path).read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    n = int(next(h for h in header if h.startswith("element vertex")).split()[-1])
    m = int(next(h for h in header if h.startswith("element face")).split()[-1])
    floats = sum(h.startswith("property float") for h in header)
    vertices = np.frombuffer(data, np.float32, n * floats, end).reshape(n, floats)
    faces = np.frombuffer(data, np.dtype([("k", "u1"), ("v", "<i4", 3), ("f", "<i4")]), m, end + 4 * n * floats)
    assert np.all(faces["k"] == 3)
    return vertices[:, :3].astype(np.float64), faces["v"].astype(np.int32), faces["f"].astype(np.int32)


def part_triangles(path, tolerance):
    """Triangles of the assembly's one body meshed alone, in its own coordinates."""
    model = _trimkit.read_model(str(path))
    body = _trimkit.select_faces(model, list(model.bodies[0].faces))
    return _trimkit.tessellate_model(body, _trimkit.TessellationOptions(tolerance=tolerance)).mesh.triangle_count


def placed_deviation(source, ply, faces=None):
    """trimkit check's figures of the written mesh against the model with instances placed
    (flattened face ids), over `faces` only when given."""
    positions, triangles, face_ids = read_ply(ply)
    flat = _trimkit.flatten_instances(_trimkit.read_model(str(source)))
    assert set(np.unique(face_ids)) == set(range(len(flat.faces)))
    if faces is not None:
        keep = np.isin(face_ids, faces)
        triangles, face_ids = triangles[keep], face_ids[keep]
    return _trimkit.measure_deviation(flat, _trimkit.Mesh(positions, triangles, face_ids=face_ids),
                                      faces=list(faces or []))


def first_face_of_each_copy(model, unplaced):
    """Flattened ids of the first face of every placed copy (flatten_instances' order:
    the unplaced faces, then each instance's copy of its body)."""
    first, at = [], len(unplaced)
    for instance in model.instances:
        faces = model.bodies[instance.body].faces
        if faces:
            first.append(at)
        at += len(faces)
    return ([0] if unplaced else []) + first


def test_assembly_parts_are_meshed_once_and_placed(tmp_path):
    folder = tmp_path / "in"
    folder.mkdir()
    moved = write_bracket_assembly(folder / "moved.igs", [(0, 0, 0, 1), (200, 0, 0, 1), (0, 150, 30, 1)])
    scaled = write_bracket_assembly(folder / "scaled.igs", [(0, 0, 0, 1), (0, 0, 100, 2.0)])
    out = tmp_path / "out"
    run = run_batch(folder, "--out", out, "--split", "parts", "--format", "ply", "--tolerance", TOLERANCE,
                    "--check", "--workers", "2")
    assert run.returncode == 0, run.stderr
    lines = {pathlib.Path(line["input"]).name: line for line in read_manifest(out / "manifest.jsonl")}
    assert sorted(lines) == ["moved.igs", "scaled.igs"]

    # Translations only: three copies of the part at the tolerance, as `trimkit mesh` has them.
    line = lines["moved.igs"]
    assert line["status"] == "ok" and line["parts"] == 1 and line["failed_faces"] == []
    assert line["triangles"] == 3 * part_triangles(moved, TOLERANCE)
    assert line["triangles"] == mesh_reference(moved, tmp_path / "moved.ply", "--tolerance", TOLERANCE)["triangles"]
    # Placed at scale 2, the part is meshed at T / 2 so that the large copy stays within T.
    line = lines["scaled.igs"]
    assert line["status"] == "ok" and line["parts"] == 1
    assert line["triangles"] == 2 * part_triangles(scaled, TOLERANCE / 2)

    for name, source in (("moved", moved), ("scaled", scaled)):
        report = placed_deviation(source, out / f"{name}.ply")
        assert report.mesh_to_surface <= TOLERANCE + FLOAT32_SLACK, name
        assert report.surface_to_mesh <= TOLERANCE + FLOAT32_SLACK, name
        assert abs(report.area_ratio - 1.0) < 1e-3, name
        deviation = lines[f"{name}.igs"]["deviation"]  # the parts' own figures, scaled to the placements
        assert deviation["tolerance"] == TOLERANCE
        assert 0.0 < deviation["mesh_to_surface"] <= TOLERANCE
        assert deviation["mesh_to_surface"] == pytest.approx(report.mesh_to_surface, rel=0.05, abs=FLOAT32_SLACK)


SHARED_ASSEMBLIES = [("iges", "bug33327.igs"), ("step", "as1-oc-214-mat.stp")]


def test_shared_assemblies_are_placed_within_the_tolerance(tmp_path):
    found = [CAD / kind / name for kind, name in SHARED_ASSEMBLIES if (CAD / kind / name).exists()]
    if not _trimkit.step_supported():
        found = [p for p in found if p.suffix != ".stp"]
    if not found:
        pytest.skip(f"no shared assemblies ({', '.join(n for _, n in SHARED_ASSEMBLIES)}) under {CAD}")
    out = tmp_path / "out"
    run = run_batch(*found, "--out", out, "--split", "parts", "--format", "ply", "--tolerance", "0.001",
                    "--relative", "--workers", "2")
    assert run.returncode == 0, run.stderr
    for line in read_manifest(out / "manifest.jsonl"):
        source = pathlib.Path(line["input"])
        model = _trimkit.read_model(str(source))
        tolerance = 0.001 * _trimkit.model_diagonal(model)
        placements = collections.Counter(i.body for i in model.instances if model.bodies[i.body].faces)
        placed = {f for b in placements for f in model.bodies[b].faces}
        unplaced = [f for f in range(len(model.faces)) if f not in placed]  # meshed as one more part
        assert line["status"] == "ok" and line["parts"] == len(placements) + bool(unplaced), line
        # Each part meshed once in its own coordinates, its mesh copied to every placement
        # (all rigid here). `trimkit mesh` meshes each placed copy, and the count of a
        # copy changes with its orientation: printed, not compared.
        options = _trimkit.TessellationOptions(tolerance=tolerance)
        count = lambda faces: _trimkit.tessellate_model(_trimkit.select_faces(model, faces), options).mesh.triangle_count
        expected = sum(n * count(list(model.bodies[b].faces)) for b, n in placements.items())
        assert line["triangles"] == expected + (count(unplaced) if unplaced else 0)
        # Every placement checked on its first face (all faces: ~25 s for as1).
        report = placed_deviation(source, out / (source.stem + ".ply"), first_face_of_each_copy(model, unplaced))
        slack = 1e-6 * _trimkit.model_diagonal(model)  # float32 positions in the PLY
        assert report.mesh_to_surface <= tolerance + slack and report.surface_to_mesh <= tolerance + slack
        reference = mesh_reference(source, tmp_path / (source.stem + ".ply"), "--tolerance", "0.001", "--relative")
        print(f"{source.name}: {line['parts']} parts, {line['triangles']} triangles, deviation "
              f"{report.mesh_to_surface / tolerance:.3f} T / {report.surface_to_mesh / tolerance:.3f} T "
              f"(trimkit mesh: {reference['triangles']} triangles)")


def read_glb(path):
    """(JSON, BIN) chunks of a .glb file."""
    import json
    import struct
    data = pathlib.Path(path).read_bytes()
    magic, version, total = struct.unpack_from("<III", data, 0)
    assert (magic, version, total) == (0x46546C67, 2, len(data))
    length, kind = struct.unpack_from("<II", data, 12)
    assert kind == 0x4E4F534A
    document = json.loads(data[20:20 + length])
    bin_length, _ = struct.unpack_from("<II", data, 20 + length)
    return document, data[28 + length:28 + length + bin_length]


def glb_positions(document, blob, mesh):
    """POSITION array (n, 3) of the glTF mesh `mesh`'s first primitive."""
    accessor = document["accessors"][document["meshes"][mesh]["primitives"][0]["attributes"]["POSITION"]]
    view = document["bufferViews"][accessor["bufferView"]]
    return np.frombuffer(blob, np.float32, 3 * accessor["count"], view["byteOffset"]).reshape(-1, 3)


def test_glb_assembly_stores_each_part_once_and_places_it_by_nodes(tmp_path):
    folder = tmp_path / "in"
    folder.mkdir()
    placements = [(0, 0, 0, 1), (200, 0, 0, 1), (0, 150, 30, 1)]
    source = write_bracket_assembly(folder / "moved.igs", placements)
    out = tmp_path / "out"
    run = run_batch(folder, "--out", out, "--split", "parts", "--format", "glb", "--tolerance", TOLERANCE,
                    "--workers", "1")
    assert run.returncode == 0, run.stderr
    [line] = read_manifest(out / "manifest.jsonl")
    assert line["status"] == "ok" and line["parts"] == 1
    document, blob = read_glb(out / "moved.glb")
    # One mesh (the part, in its own coordinates), one node per placement with its matrix.
    assert len(document["meshes"]) == 1 and len(document["nodes"]) == len(placements)
    model = _trimkit.read_model(str(source))
    part = _trimkit.tessellate_model(_trimkit.select_faces(model, list(model.bodies[0].faces)),
                                     _trimkit.TessellationOptions(tolerance=TOLERANCE)).mesh
    positions = glb_positions(document, blob, 0)
    np.testing.assert_allclose(positions, np.asarray(part.positions), atol=FLOAT32_SLACK)
    assert line["triangles"] == len(placements) * part.triangle_count
    for node, instance in zip(document["nodes"], model.instances):
        matrix = np.asarray(node.get("matrix", np.eye(4).ravel(order="F"))).reshape(4, 4, order="F")
        np.testing.assert_allclose(matrix, np.asarray(instance.matrix), atol=1e-12)
        assert node["mesh"] == 0 and node["name"].startswith(document["nodes"][0]["name"].rsplit(".", 1)[0])
    # Placed by their nodes, the copies are where the flattened model's faces are.
    flat = _trimkit.flatten_instances(model)
    copies = []
    for node in document["nodes"]:
        matrix = np.asarray(node.get("matrix", np.eye(4).ravel(order="F"))).reshape(4, 4, order="F")
        copies.append(positions.astype(np.float64) @ matrix[:3, :3].T + matrix[:3, 3])
    triangles = np.concatenate([np.asarray(part.triangles) + k * len(positions) for k in range(len(copies))])
    face_ids = np.concatenate([np.asarray(part.face_ids) + k * len(model.bodies[0].faces) for k in range(len(copies))])
    report = _trimkit.measure_deviation(flat, _trimkit.Mesh(np.concatenate(copies), triangles.astype(np.int32),
                                                            face_ids=face_ids.astype(np.int32)))
    assert report.mesh_to_surface <= TOLERANCE + FLOAT32_SLACK
    assert report.surface_to_mesh <= TOLERANCE + FLOAT32_SLACK
