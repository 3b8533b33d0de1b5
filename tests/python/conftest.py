# Shared fixtures of the Python module's tests (ctest python_module, label python): the
# repository's samples and the CLI built beside the module, to compare messages and files.
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("MESHEDIT_SOURCE_DIR",
                                     pathlib.Path(__file__).resolve().parents[2]))
CLI = os.environ.get("MESHEDIT_CLI")


@pytest.fixture
def sample():
    return lambda name: str(SOURCE / "dae" / name)


@pytest.fixture
def cli():
    """Runs `meshedit ARGS`; returns (exit status, stdout, stderr)."""
    if not CLI or not os.path.exists(CLI):
        pytest.skip("the meshedit CLI is not built (MESHEDIT_CLI)")

    def run(*args):
        done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
        return done.returncode, done.stdout, done.stderr
    return run
