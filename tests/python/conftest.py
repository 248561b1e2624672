"""Shared fixtures of the Python module's tests (run by CTest with PYTHONPATH=<build>/python
and SWARMAGG_BINARY=<build>/swarmagg, from the repository root)."""

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DEMO = ROOT / "worlds" / "examples" / "demo.yaml"


@pytest.fixture(scope="session")
def cli():
    """Runs the swarmagg binary built beside the module; returns the completed process."""
    binary = os.environ.get("SWARMAGG_BINARY") or str(ROOT / "build" / "swarmagg")

    def run(*args: str) -> subprocess.CompletedProcess:
        return subprocess.run([binary, *map(str, args)], check=True, capture_output=True, text=True)

    return run


@pytest.fixture(scope="session")
def demo() -> Path:
    return DEMO
