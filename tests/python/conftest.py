"""Fixtures of the Python module's tests: the command-line program they compare with, and scene files.

CTest sets DROPSCOPE_CLI (the dropscope program of the same build) and PYTHONPATH (build/python).
"""

import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]
CLI = os.environ.get("DROPSCOPE_CLI", str(SOURCE_DIR / "build" / "app" / "dropscope"))

# The detectors scene of the C++ tests with a line spectrum (three wavelength bands) and hit records.
DETECTOR_SCENE = json.loads((SOURCE_DIR / "tests/data/scenes/detectors.json").read_text())
DETECTOR_SCENE["sources"][0]["spectrum"] = {"lines_nm": [[450, 1], [550, 2], [650, 1]]}
DETECTOR_SCENE["detectors"][0]["record"] = 50


def run_cli(*args, expect=0):
    """Runs `dropscope ARGS`; asserts its exit status; returns the CompletedProcess (text)."""
    done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=600)
    assert done.returncode == expect, f"dropscope {' '.join(map(str, args))}: exit {done.returncode}\n{done.stderr}"
    return done


@pytest.fixture
def detector_scene_file(tmp_path):
    path = tmp_path / "detectors.json"
    path.write_text(json.dumps(DETECTOR_SCENE, indent=1))
    return path
