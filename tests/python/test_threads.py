# meshedit.set_threads() / meshedit.threads() and MESHEDIT_THREADS: the setting is used, bad
# values are refused naming what gave them, and the results do not depend on it.
import os
import subprocess
import sys

import numpy as np
import pytest

import meshedit


@pytest.fixture
def restore_threads():
    yield
    meshedit.set_threads(0)  # ctest runs without MESHEDIT_THREADS: all cores


def torus(m, n):
    """An m × n torus of 2mn triangles, made with numpy."""
    i, j = np.meshgrid(np.arange(m), np.arange(n), indexing="ij")
    u, v = 2 * np.pi * i / m, 2 * np.pi * j / n
    V = np.stack([(1 + 0.4 * np.cos(v)) * np.cos(u), (1 + 0.4 * np.cos(v)) * np.sin(u),
                  0.4 * np.sin(v)], axis=-1).reshape(-1, 3)
    a = (i * n + j).ravel()
    b = (((i + 1) % m) * n + j).ravel()
    c = (((i + 1) % m) * n + (j + 1) % n).ravel()
    d = (i * n + (j + 1) % n).ravel()
    return V, np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])


def test_set_threads_is_used(restore_threads):
    meshedit.set_threads(1)
    assert meshedit.threads() == 1
    meshedit.set_threads(3)
    assert meshedit.threads() == 3
    meshedit.set_threads(0)
    assert meshedit.threads() == os.cpu_count()


@pytest.mark.parametrize("bad", [-1, 100000])
def test_bad_counts_raise_value_error(bad, restore_threads):
    meshedit.set_threads(2)
    with pytest.raises(ValueError, match="set_threads: '-?[0-9]+' is not a thread count"):
        meshedit.set_threads(bad)
    assert meshedit.threads() == 2  # unchanged


@pytest.mark.parametrize("bad", ["2", 2.0, True, None])
def test_non_integers_raise_type_error(bad):
    with pytest.raises(TypeError):
        meshedit.set_threads(bad)


def test_loop_and_normals_are_the_same_on_one_thread_and_all(restore_threads):
    # 102,400 triangles: above the 100,000 faces from which Loop and normals use threads.
    V, F = torus(320, 160)
    results = []
    for n in (1, 0):
        meshedit.set_threads(n)
        mesh = meshedit.Mesh.from_arrays(V, F)
        mesh.loop()
        results.append((np.array(mesh.V), mesh.faces(), mesh.vertex_normals()))
    for one, every in zip(results[0], results[1]):
        assert np.array_equal(one, every)


def test_bad_variable_stops_the_import():
    env = dict(os.environ, MESHEDIT_THREADS="lots")
    done = subprocess.run([sys.executable, "-c", "import meshedit"], env=env,
                          capture_output=True, text=True)
    assert done.returncode != 0
    assert "MESHEDIT_THREADS: 'lots' is not a thread count" in done.stderr


def test_variable_sets_the_default():
    env = dict(os.environ, MESHEDIT_THREADS="1")
    done = subprocess.run([sys.executable, "-c", "import meshedit; print(meshedit.threads())"],
                          env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "1"
