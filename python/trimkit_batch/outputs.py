"""Outputs are written under a temporary name beside the final one and renamed into
place (os.replace, atomic on one filesystem): a reader, or a rerun after a worker was
killed mid-write, sees the whole old file or the whole new one, never a torn file. The
temporary name keeps the extension, since the writers choose the format by it:
  OUT/part.glb  <-  OUT/.part.glb.partial-<random>.glb
"""
import os
import pathlib
import uuid


def temporary_path(output):
    output = pathlib.Path(output)
    return output.with_name(f".{output.name}.partial-{uuid.uuid4().hex[:12]}{output.suffix}")


def write_atomically(output, write):
    """Calls write(temporary path) and renames the file it wrote to `output`; returns
    the output's size in bytes. The temporary file is removed if `write` raises."""
    output = pathlib.Path(output)
    output.parent.mkdir(parents=True, exist_ok=True)
    temporary = temporary_path(output)
    try:
        write(str(temporary))
        os.replace(temporary, output)
    except BaseException:
        temporary.unlink(missing_ok=True)
        raise
    return output.stat().st_size


def remove_partials(output):
    """Deletes temporary files left beside `output` by writers that were killed."""
    output = pathlib.Path(output)
    for stale in output.parent.glob(f".{output.name}.partial-*"):
        stale.unlink(missing_ok=True)
