"""Shared fixtures: the package under test is the build's (PYTHONPATH=<build>/python)."""

import os
import pathlib

import pytest

import thyrix

#: The repository's root, for the examples.
ROOT = pathlib.Path(__file__).resolve().parents[2]

#: Relative tolerance of the closed-form checks: looser with THYRIX_REAL=float.
TOLERANCE = 1e-12 if thyrix.real_dtype.itemsize == 8 else 1e-5


@pytest.fixture
def evaluate_reference():
    """The path of the C++ helper thyrix_evaluate_reference (built with the tests)."""
    path = os.environ.get("THYRIX_EVALUATE_REFERENCE")
    if path is None:
        path = pathlib.Path(thyrix.__file__).resolve().parent.parent / "thyrix_evaluate_reference"
    assert os.path.exists(path), f"build thyrix_evaluate_reference first ({path})"
    return str(path)
