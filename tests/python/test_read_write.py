# meshedit.read(), Mesh.write(), info(), validate(), fields: the CLI's formats, notes and errors.
import numpy as np
import pytest

import meshedit


def test_read_cube_info(sample):
    mesh = meshedit.read(sample("cube.dae"))
    info = mesh.info()
    assert (info["vertices"], info["edges"], info["faces"]) == (8, 18, 12)
    assert info["genus"] == 0 and info["boundary_loops"] == 0 and info["components"] == 1
    assert info["euler_characteristic"] == 2
    assert info["face_degrees"] == {3: 12}
    assert info["bbox"]["min"] == pytest.approx((-1, -1, -1)) or info["bbox"] is not None
    assert mesh.validate() is None
    assert isinstance(mesh.notices, list)


def test_info_matches_the_cli(sample, cli):
    import json
    status, out, _ = cli("info", sample("torus.dae"), "--json")
    assert status == 0
    expected = json.loads(out)
    got = meshedit.read(sample("torus.dae")).info()
    for key in ("vertices", "edges", "faces", "boundary_loops", "components",
                "euler_characteristic", "genus", "creases", "triangle_mesh"):
        assert got[key] == expected[key], key
    assert list(got["bbox"]["min"]) == pytest.approx(expected["bbox"]["min"])


def test_stats_has_every_field(sample):
    stats = meshedit.read(sample("cube.dae")).info(stats=True)["stats"]
    assert stats["area"] > 0 and "volume" in stats
    assert set(stats["fields"]) == set(meshedit.field_names())


def test_field_values(sample):
    mesh = meshedit.read(sample("cube.dae"))
    valence = mesh.field("valence")
    assert valence.shape == (8,) and valence.sum() == 2 * 18
    with pytest.raises(ValueError, match="unknown field 'nope'"):
        mesh.field("nope")
    with pytest.raises(IndexError, match="source: vertex 99"):
        mesh.field("distance", source=99)


def test_missing_file_raises_ioerror_with_the_cli_message(tmp_path, cli):
    missing = tmp_path / "missing.dae"
    with pytest.raises(meshedit.IoError) as error:
        meshedit.read(missing)
    assert isinstance(error.value, OSError)
    status, _, err = cli("info", missing)
    assert status == 2
    assert str(error.value) in err


def test_bad_files_raise_ioerror_naming_the_file():
    from conftest import SOURCE
    for name in ("garbage.dae", "index_out_of_range.dae", "nan.dae", "empty.dae"):
        path = SOURCE / "tests" / "cli" / "data" / name
        try:
            meshedit.read(path)
        except meshedit.IoError as error:
            assert name in str(error)


def test_write_round_trip_and_what_a_format_cannot_keep(sample, tmp_path):
    mesh = meshedit.read(sample("cube.dae"))
    assert mesh.write(tmp_path / "cube.ply") == []
    back = meshedit.read(tmp_path / "cube.ply")
    assert np.array_equal(back.V, mesh.V)
    assert np.array_equal(back.faces(), mesh.faces())
    mesh.crease(0, 6)
    unkept = mesh.write(tmp_path / "cube.obj")
    assert len(unkept) == 1 and "crease" in unkept[0]


def test_write_to_a_bad_place_raises(sample, tmp_path):
    mesh = meshedit.read(sample("cube.dae"))
    with pytest.raises(meshedit.IoError, match="no_such_folder"):
        mesh.write(tmp_path / "no_such_folder" / "cube.obj")
    with pytest.raises(meshedit.IoError):
        mesh.write(tmp_path / "cube.xyz")


def test_bezier_patches_read_as_their_tessellation(cli):
    from conftest import SOURCE
    import json
    mesh = meshedit.read(SOURCE / "bez" / "teapot.bez", density=4)
    status, out, _ = cli("info", SOURCE / "bez" / "teapot.bez", "--json", "--density", "4")
    assert status == 0
    assert mesh.info()["vertices"] == json.loads(out)["vertices"]
    assert any("Bezier patches at density 4" in line for line in mesh.notices)
    with pytest.raises(ValueError, match="density: expected 1 to 256"):
        meshedit.read(SOURCE / "bez" / "teapot.bez", density=0)
    curves = sorted((SOURCE / "bez").glob("*.bzc"))
    if curves:
        with pytest.raises(meshedit.IoError, match="a Bezier curve, not a mesh"):
            meshedit.read(curves[0])
    assert meshedit.__version__.count(".") == 2
