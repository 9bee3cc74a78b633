"""Shared helpers of the Python module's tests: the CLI of the same build and the bundled cases.

RHEOMAG_BINARY and RHEOMAG_SOURCE_DIR are set by CTest (tests/python/CMakeLists.txt).
"""

import json
import os
import subprocess

import pytest

SOURCE = os.environ["RHEOMAG_SOURCE_DIR"]
BINARY = os.environ["RHEOMAG_BINARY"]
VALVE = os.path.join(SOURCE, "cases", "annular_valve.toml")

# Keys that measure time (wall clock), not results: they differ from run to run.
TIMING_KEYS = {"seconds", "mesh_seconds"}


def run_cli(*args):
    """Runs the CLI; returns (exit code, stdout, stderr)."""
    p = subprocess.run([BINARY, *args], capture_output=True, text=True, check=False)
    return p.returncode, p.stdout, p.stderr


def cli_json(*args):
    """The CLI's JSON document (exit 0 required)."""
    code, out, err = run_cli(*args, "--json")
    assert code == 0, err
    return json.loads(out)


def without_timing(document):
    """The document without its wall-clock keys (at any depth)."""
    if isinstance(document, dict):
        return {k: without_timing(v) for k, v in document.items() if k not in TIMING_KEYS}
    if isinstance(document, list):
        return [without_timing(v) for v in document]
    return document


def cli_error(*args):
    """The message of a CLI run that must fail with bad input (exit 2): stderr without the
    "rheomag: error: " prefix."""
    code, _, err = run_cli(*args)
    assert code == 2, err
    prefix = "rheomag: error: "
    assert err.startswith(prefix), err
    return err[len(prefix):].rstrip("\n")


@pytest.fixture(scope="session")
def valve_case():
    import rheomag

    return rheomag.Case.load(VALVE)
