"""Shared fixtures: the built-in samples and the optional shared CAD folder."""
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
CAD = ROOT.parent / "shared" / "data" / "cad"


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
