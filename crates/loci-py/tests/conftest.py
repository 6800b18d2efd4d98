"""Shared paths for the tests."""

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]


@pytest.fixture
def examples() -> Path:
    """The repository's examples directory."""
    return ROOT / "examples"
