# meshedit.render(): meshedit-render's picture as an (H, W, 4) uint8 array.
import os
import subprocess

import numpy as np
import pytest

import meshedit
from meshedit._render import _renderer, decode_png


@pytest.fixture
def renderer():
    try:
        return _renderer()
    except FileNotFoundError:
        pytest.skip("meshedit-render is not built")


def test_render_equals_the_programs_picture(renderer, sample, tmp_path):
    image = meshedit.render(meshedit.read(sample("cube.dae")), 64, 48, shading="studio",
                            wireframe=True)
    assert image.shape == (48, 64, 4) and image.dtype == np.uint8
    png = tmp_path / "cube.png"
    subprocess.run([renderer, "--size", "64x48", "--shading", "studio", "--wireframe", "-o",
                    str(png), sample("cube.dae")], check=True)
    assert np.array_equal(image, decode_png(png.read_bytes()))
    assert len(np.unique(image.reshape(-1, 4), axis=0)) > 10


def test_render_errors(renderer, sample):
    mesh = meshedit.read(sample("cube.dae"))
    with pytest.raises(ValueError, match="width and height"):
        meshedit.render(mesh, 0, 10)
    with pytest.raises(RuntimeError, match="render: .*shading"):
        meshedit.render(mesh, 8, 8, shading="nope")


def test_render_of_an_edited_mesh_with_creases(renderer, sample):
    mesh = meshedit.read(sample("creased.dae"))
    mesh.loop()
    image = meshedit.render(mesh, 32, 24, flat=True, samples=1)
    assert image.shape == (24, 32, 4)
