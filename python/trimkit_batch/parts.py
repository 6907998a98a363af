"""--split parts: an assembly (a model with instances: STEP parts, IGES 308/408
subfigures) meshed one unique part definition per task, so that one assembly of
thousands of parts spreads over the cluster, then written with every instance placed.

Three steps, each a task:
  plan_parts(job)        reads the model; a Part per instanced body (its faces and every
                         placement), plus one for the faces no instance places.
  mesh_part(job, part)   meshes the part's faces alone (select_faces), once, in the
                         body's own coordinates; returns the mesh as arrays.
  write_assembly(...)    places each part's mesh at each of its placements and writes
                         one mesh, faces numbered as flatten_instances numbers them
                         (what `trimkit mesh` meshes), so failed-face ids agree; a .glb
                         keeps the instancing (each part's mesh once, one node per
                         placement with its matrix).

A part placed with scale s is meshed at tolerance T / s (the largest s among its
placements), so every placed copy stays within T. Departures from `trimkit mesh` on the
same file, which meshes the placed copies: vertices are not welded across parts, and a
copy's mesh is the definition's moved (equal to meshing the moved surface up to
rounding), so outputs agree in geometry and tolerance, not byte for byte.
"""
import dataclasses
import time

import numpy as np

import _trimkit

from . import model_cache, outputs
from .convert import absolute_tolerance, tessellation_options
from .outcome import OK, Outcome, deviation_figures, failed, failed_face, finite

@dataclasses.dataclass
class Part:
    name: str
    faces: list           # Model.faces indices, in the order flatten_instances copies them
    placements: list      # (4, 4) matrices, body -> model coordinates (file units)
    first_faces: list     # per placement: the flattened face id of the copy's first face
    tolerance: float      # absolute, in the body's coordinates


@dataclasses.dataclass
class Plan:
    parts: list           # empty: the model has no instances (convert it whole)
    tolerance: float = 0.0  # absolute, model units
    faces: int = 0        # faces with instances placed
    unread_faces: list = dataclasses.field(default_factory=list)  # Model.unread_faces


def largest_scale(matrix):
    """How much the 4x4 affine `matrix` stretches a length at most (its linear part's
    largest singular value)."""
    return float(np.linalg.norm(np.asarray(matrix)[:3, :3], 2))


def plan_parts(job, sha256, settings):
    """The Plan of job.input, or a failed Outcome for a bad file."""
    start = time.perf_counter()
    try:
        model = model_cache.read(job.input, sha256)
        if not model.instances:
            return Plan(parts=[])
        return make_plan(model, absolute_tolerance(model, settings))
    except (RuntimeError, ValueError, OSError) as err:
        return failed(err, time.perf_counter() - start)


def make_plan(model, tolerance):
    """Parts of a model with instances, numbered like flatten_instances: the faces of no
    instanced body first (in model order), then each instance's copy of its body."""
    bodies = model.bodies
    valid = [i for i in model.instances if 0 <= i.body < len(bodies)]
    instanced = {i.body for i in valid}
    placed_faces = {f for b in instanced for f in bodies[b].faces}
    rest = [f for f in range(len(model.faces)) if f not in placed_faces]
    parts = []
    if rest:
        parts.append(Part(name="unplaced faces", faces=rest, placements=[np.eye(4)], first_faces=[0],
                          tolerance=tolerance))
    by_body = {}
    next_face = len(rest)
    for instance in valid:
        body = bodies[instance.body]
        if instance.body not in by_body:
            by_body[instance.body] = Part(name=body.name or f"Body.{instance.body}", faces=list(body.faces),
                                          placements=[], first_faces=[], tolerance=tolerance)
            parts.append(by_body[instance.body])
        part = by_body[instance.body]
        part.placements.append(np.array(instance.matrix, np.float64))
        part.first_faces.append(next_face)
        next_face += len(body.faces)
    parts = [p for p in parts if p.faces]
    for part in parts:
        part.tolerance = tolerance / max(1.0, max(largest_scale(m) for m in part.placements))
    return Plan(parts=parts, tolerance=tolerance, faces=next_face, unread_faces=list(model.unread_faces))


@dataclasses.dataclass
class PartMesh:
    """A part's mesh in its body's coordinates; face ids are positions in Part.faces."""
    arrays: dict          # Mesh constructor arguments: positions, triangles, normals, ...
    failed_faces: list    # [(position in Part.faces, reason)]
    deviation: object     # DeviationReport figures (dict) or None
    area_mesh: float
    area_exact: float
    seconds: float


def mesh_part(job, sha256, settings, part):
    """Meshes one part; a failed Outcome when the file cannot be read."""
    start = time.perf_counter()
    try:
        model = _trimkit.select_faces(model_cache.read(job.input, sha256), part.faces)
        result = _trimkit.tessellate_model(model, tessellation_options(settings, part.tolerance))
    except (RuntimeError, ValueError, OSError) as err:
        return failed(err, time.perf_counter() - start)
    mesh = result.mesh
    deviation, area_mesh, area_exact = None, 0.0, 0.0
    if settings.check:
        report = _trimkit.measure_deviation(model, mesh)
        deviation = deviation_figures(report, part.tolerance)
        area_mesh, area_exact = report.area_mesh, report.area_exact
    arrays = dict(positions=mesh.positions, triangles=mesh.triangles, normals=mesh.normals, uvs=mesh.uvs,
                  face_ids=mesh.face_ids, edges=mesh.edges, edge_flags=mesh.edge_flags)
    return PartMesh(arrays=arrays, failed_faces=[(f.face, f.reason) for f in result.failed_faces],
                    deviation=deviation, area_mesh=area_mesh, area_exact=area_exact,
                    seconds=time.perf_counter() - start)


def placed_arrays(arrays, matrix, first_face):
    """A part's mesh arrays moved by the affine `matrix`, face ids from `first_face`:
    normals by the inverse transpose, and a mirroring matrix reverses each triangle's
    corners so that it stays counter-clockwise seen from its normal side."""
    linear, offset = matrix[:3, :3], matrix[:3, 3]
    triangles = arrays["triangles"]
    normals = arrays["normals"]
    if len(normals):
        normals = normals @ np.linalg.inv(linear)  # rows: (L^-T n)^T = n^T L^-1
        normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    if np.linalg.det(linear) < 0.0:
        triangles = triangles[:, ::-1]
    return dict(positions=arrays["positions"] @ linear.T + offset, triangles=triangles, normals=normals,
                uvs=arrays["uvs"], face_ids=arrays["face_ids"] + first_face, edges=arrays["edges"],
                edge_flags=arrays["edge_flags"])


def assemble_mesh(plan, meshes):
    """One native Mesh of every placement of every part (meshes: a PartMesh per
    plan.parts entry), copies in flattened face order."""
    copies = sorted(((first, mesh, matrix) for part, mesh in zip(plan.parts, meshes)
                     for matrix, first in zip(part.placements, part.first_faces)), key=lambda copy: copy[0])
    pieces = [placed_arrays(mesh.arrays, matrix, first) for first, mesh, matrix in copies]
    offsets = np.cumsum([0] + [len(p["positions"]) for p in pieces[:-1]])

    def joined(name, width, dtype):
        arrays = [p[name] for p in pieces]
        return np.concatenate(arrays).astype(dtype) if arrays else np.zeros((0, width), dtype)

    has_normals = all(len(p["normals"]) == len(p["positions"]) for p in pieces)
    has_uvs = all(len(p["uvs"]) == len(p["positions"]) for p in pieces)
    return _trimkit.Mesh(
        joined("positions", 3, np.float64),
        np.concatenate([p["triangles"] + o for p, o in zip(pieces, offsets)]).astype(np.int32),
        normals=joined("normals", 3, np.float64) if has_normals else None,
        uvs=joined("uvs", 2, np.float64) if has_uvs else None,
        face_ids=np.concatenate([p["face_ids"] for p in pieces]).astype(np.int32),
        edges=np.concatenate([p["edges"] + o for p, o in zip(pieces, offsets)]).astype(np.int32),
        edge_flags=np.concatenate([p["edge_flags"] for p in pieces]).astype(np.uint8))


def instanced_meshes(plan, meshes):
    """A .glb's instancing: each part's mesh once, in its body's coordinates, and one
    (part index, matrix, name) per placement, in flattened face order."""
    part_meshes = [placed_mesh(m.arrays, np.eye(4), 0) for m in meshes]
    copies = sorted((first, k, matrix) for k, part in enumerate(plan.parts)
                    for matrix, first in zip(part.placements, part.first_faces))
    count = {}
    placements = []
    for _, k, matrix in copies:
        count[k] = count.get(k, 0) + 1
        placements.append((k, np.asarray(matrix, np.float64), f"{plan.parts[k].name}.{count[k]}"))
    return part_meshes, placements


def placed_mesh(arrays, matrix, first_face):
    """A native Mesh of one placed copy (placed_arrays)."""
    p = placed_arrays(arrays, matrix, first_face)
    n = len(p["positions"])
    return _trimkit.Mesh(
        np.asarray(p["positions"], np.float64), np.asarray(p["triangles"], np.int32),
        normals=np.asarray(p["normals"], np.float64) if len(p["normals"]) == n else None,
        uvs=np.asarray(p["uvs"], np.float64) if len(p["uvs"]) == n else None,
        face_ids=np.asarray(p["face_ids"], np.int32), edges=np.asarray(p["edges"], np.int32),
        edge_flags=np.asarray(p["edge_flags"], np.uint8))


def write_assembly(job, settings, plan, meshes):
    """Writes the placed parts to job.output; the Outcome of the whole file (a failed one
    when a part failed, naming it)."""
    start = time.perf_counter()
    for part, mesh in zip(plan.parts, meshes):
        if isinstance(mesh, Outcome):
            return failed(f"part {part.name!r}: {mesh.error}", time.perf_counter() - start)
    try:
        mesh = assemble_mesh(plan, meshes)
        if str(job.output).endswith(".glb"):
            part_meshes, placements = instanced_meshes(plan, meshes)
            write = lambda path: _trimkit.write_glb_instances(path, part_meshes, placements)  # noqa: E731
        else:
            write = lambda path: _trimkit.write_mesh(path, mesh)  # noqa: E731
        size = outputs.write_atomically(job.output, write)
    except (RuntimeError, ValueError, OSError) as err:
        return failed(err, time.perf_counter() - start)
    failed_faces = [failed_face(first + k, reason)
                    for part, m in zip(plan.parts, meshes) for k, reason in m.failed_faces
                    for first in part.first_faces]
    return Outcome(status=OK, triangles=mesh.triangle_count, failed_faces=sorted(failed_faces, key=lambda f: f["face"]),
                   unread_faces=plan.unread_faces,
                   deviation=assembly_deviation(plan, meshes) if settings.check else None,
                   seconds=time.perf_counter() - start + sum(m.seconds for m in meshes),
                   output_bytes=size, parts=len(plan.parts))


def assembly_deviation(plan, meshes):
    """The deviation of the placed assembly from its parts' figures: each part's distances
    times its largest placement scale (exact for similarities), areas summed over copies."""
    def worst(name):
        values = [m.deviation[name] * largest_scale(matrix) for p, m in zip(plan.parts, meshes)
                  for matrix in p.placements if m.deviation[name] is not None]
        return max(values) if values else None

    def total(name):
        return sum(getattr(m, name) * abs(np.linalg.det(matrix[:3, :3])) ** (2.0 / 3.0)
                   for p, m in zip(plan.parts, meshes) for matrix in p.placements)

    area_exact = total("area_exact")
    return {"mesh_to_surface": worst("mesh_to_surface"), "surface_to_mesh": worst("surface_to_mesh"),
            "area_ratio": finite(total("area_mesh") / area_exact) if area_exact > 0.0 else None,
            "open_edges": sum(m.deviation["open_edges"] * len(p.placements) for p, m in zip(plan.parts, meshes)),
            "tolerance": plan.tolerance}
