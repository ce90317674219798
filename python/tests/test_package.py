"""The installed package: its doctests run, its stubs and docstrings are there."""

import doctest
import pathlib

import gartowen


def test_doctests_pass():
    result = doctest.testmod(gartowen)
    assert result.attempted > 0 and result.failed == 0


def test_installed_not_source_tree():
    # The tests must exercise the built wheel, with its native module.
    assert "site-packages" in gartowen.__file__
    assert pathlib.Path(gartowen._native.__file__).suffix in (".so", ".pyd")


def test_type_stubs_and_docstrings_ship():
    folder = pathlib.Path(gartowen.__file__).parent
    assert (folder / "py.typed").exists()
    assert (folder / "_native.pyi").exists()
    for name in gartowen.__all__:
        doc = getattr(gartowen, name).__doc__
        assert doc and len(doc) > 40, name
