"""The last model read, kept by the process that converts: with --split parts the plan
and every part task of an assembly that land on one worker read the file once. Keyed by
path and sha256, so a changed file is read again; one model only (an assembly's model
can be large)."""
import _trimkit

_last = (None, None)


def read(path, sha256):
    """The model of `path` (read_model: RuntimeError 'FILE:LINE: reason' for a bad file)."""
    global _last
    key = (path, sha256)
    if _last[0] != key:
        _last = (None, None)  # release the old model before reading the new one
        _last = (key, _trimkit.read_model(path))
    return _last[1]
