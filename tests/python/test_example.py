# The example script of examples/ runs and says what it did.
import os
import pathlib
import subprocess
import sys

from conftest import SOURCE


def test_example_session(tmp_path):
    script = SOURCE / "examples" / "python_session.py"
    done = subprocess.run([sys.executable, str(script), str(SOURCE / "dae" / "cube.dae"),
                           str(tmp_path)], capture_output=True, text=True, env=os.environ)
    assert done.returncode == 0, done.stderr
    assert "wrote" in done.stdout
    assert (pathlib.Path(tmp_path) / "cube_edited.ply").exists()
