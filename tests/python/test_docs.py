# docs/python.md's sessions run as doctests: the outputs shown there are what the module prints.
import doctest
import os

from conftest import SOURCE
from meshedit._render import _renderer


def test_python_md_sessions(tmp_path, monkeypatch):
    try:
        _renderer()  # the render example needs the program
    except FileNotFoundError:
        return
    # The sessions read dae/… and write beside it: run them in a scratch folder.
    os.symlink(SOURCE / "dae", tmp_path / "dae")
    monkeypatch.chdir(tmp_path)
    path = SOURCE / "docs" / "python.md"
    # A code fence ends an example's expected output, as a blank line does.
    text = "\n".join("" if line.startswith("```") else line
                     for line in path.read_text().splitlines())
    test = doctest.DocTestParser().get_doctest(text, {}, "python.md", str(path), 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    runner.run(test)
    assert len(test.examples) > 20
    assert runner.failures == 0
