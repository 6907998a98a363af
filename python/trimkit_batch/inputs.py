"""The files a batch converts: INPUT arguments (files, or folders searched recursively
for CAD files) become Jobs, each an input file and the output file it is converted to.

Outputs: a file named on the command line goes to OUT/<stem>.<format>; a file found in
a folder goes to OUT/<its path below that folder>/<stem>.<format>, so a part library's
tree is kept. A file reached twice (named and inside a named folder) is converted once.
Two inputs that would write the same output are refused before anything runs.
Paths are absolute: on a cluster of several machines, inputs and OUT must be on a
filesystem every worker sees at the same path.
"""
import dataclasses
import os
import pathlib

CAD_SUFFIXES = (".igs", ".iges", ".stp", ".step", ".brep", ".tbp")


class InputError(ValueError):
    """An INPUT argument that names nothing to convert, or outputs that collide."""


@dataclasses.dataclass(frozen=True)
class Job:
    input: str    # absolute path of the CAD file
    output: str   # absolute path of the file to write
    size: int     # input bytes (larger files are submitted first)

    @property
    def name(self):
        return pathlib.Path(self.input).name


def is_cad_file(path):
    return path.suffix.lower() in CAD_SUFFIXES


def discover(arguments, out, suffix):
    """Jobs for INPUT `arguments` (files or folders), outputs under `out` with `suffix`
    (".glb", ...), in the order given (a folder's files sorted). Raises InputError for a
    missing path, a named file that is not a CAD file, a folder without any, or two
    inputs with one output."""
    out = pathlib.Path(out).resolve()
    jobs, seen, writers = [], set(), {}
    for argument in arguments:
        root = pathlib.Path(argument)
        if root.is_dir():
            found = sorted(p for p in root.rglob("*") if p.is_file() and is_cad_file(p))
            if not found:
                raise InputError(f"{argument}: no CAD files ({', '.join(CAD_SUFFIXES)}) in this folder")
            pairs = [(p, out / p.relative_to(root).parent / (p.stem + suffix)) for p in found]
        elif root.is_file():
            if not is_cad_file(root):
                raise InputError(f"{argument}: not a CAD file (expected {', '.join(CAD_SUFFIXES)})")
            pairs = [(root, out / (root.stem + suffix))]
        else:
            raise InputError(f"{argument}: no such file or folder")
        for path, output in pairs:
            path = path.resolve()
            if path in seen:
                continue
            seen.add(path)
            if output in writers:
                raise InputError(f"{writers[output]} and {path} would both be written to {output}; "
                                 "convert them in separate runs or into separate --out folders")
            writers[output] = path
            jobs.append(Job(input=str(path), output=str(output), size=os.path.getsize(path)))
    if not jobs:
        raise InputError("no inputs")
    return jobs
