"""Shared fixtures: the built-in samples and the optional shared CAD folder."""
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
CAD = ROOT.parent / "shared" / "data" / "cad"


def trimkit_program():
    """The `trimkit` of the build whose _trimkit module is on the path (PYTHONPATH=BUILD/python:
    build/ normally, build-asan/ under `scripts/test --sanitize`), else build/bin/trimkit."""
    try:
        import _trimkit
        beside = pathlib.Path(_trimkit.__file__).resolve().parents[1] / "bin" / "trimkit"
        if beside.exists():
            return str(beside)
    except ImportError:
        pass
    return str(ROOT / "build" / "bin" / "trimkit")


TRIMKIT = trimkit_program()


@pytest.fixture
def bracket():
    return str(ROOT / "samples" / "bracket.igs")


@pytest.fixture
def cad_sample():
    def find(relative):
        path = CAD / relative
        if not path.exists():
            pytest.skip(f"CAD sample {relative} not found under {CAD}")
        return str(path)
    return find
