"""gartowen.scramble: agreement with the CLI, any memory order, dtype and shape kept."""

import numpy as np
import pytest

import gartowen


def sobol_words(n=256, dims=3, bits=32):
    return gartowen.generate("sobol", dims, n, words=True, bits=bits)


@pytest.mark.parametrize("name,bits", [("owen-oracle", 32), ("art-owen-8p", 32),
                                       ("owen-oracle:xor", 64), ("lk-hash", 32)])
def test_words_equal_the_cli(cli, tmp_path, name, bits):
    x = sobol_words(bits=bits)
    src, out = tmp_path / "in.npy", tmp_path / "out.npy"
    np.save(src, x)
    cli.run("scramble", src, "--scramble", name, "--seed", 11, "--words", "-o", out)
    got = gartowen.scramble(x, name, 11)
    assert got.dtype == x.dtype and got.shape == x.shape
    np.testing.assert_array_equal(got, np.load(out))


def test_floats_equal_the_cli(cli, tmp_path):
    x = gartowen.generate("sobol", 2, 128)
    src, out = tmp_path / "in.npy", tmp_path / "out.npy"
    np.save(src, x)
    cli.run("scramble", src, "--scramble", "owen-oracle", "--seed", 2, "-o", out)
    got = gartowen.scramble(x, "owen-oracle", 2)
    assert got.dtype == np.float64
    np.testing.assert_array_equal(got, np.load(out))


def test_scramble_is_a_nested_bijection_keeping_the_net():
    x = sobol_words(n=1024, dims=2)
    y = gartowen.scramble(x, "owen-oracle", 9)
    assert not np.array_equal(x, y)
    # Column j is scrambled as dimension j: distinct dimensions get distinct permutations.
    assert not np.array_equal(y[:, 0], y[:, 1])
    for j in range(2):
        assert len(np.unique(y[:, j])) == 1024
    assert gartowen.check(y, 2).t == gartowen.check(x, 2).t == 0


def test_memory_order_does_not_matter():
    x = sobol_words(n=64, dims=4)
    ref = gartowen.scramble(x, "owen-oracle", 4)
    np.testing.assert_array_equal(gartowen.scramble(np.asfortranarray(x), "owen-oracle", 4), ref)
    # A strided view: every other dimension.
    strided = x[:, ::2]
    assert not strided.flags.c_contiguous
    np.testing.assert_array_equal(
        gartowen.scramble(strided, "owen-oracle", 4),
        gartowen.scramble(np.ascontiguousarray(strided), "owen-oracle", 4),
    )


def test_one_dimension_keeps_its_shape():
    x = sobol_words(n=32, dims=1)[:, 0]
    y = gartowen.scramble(x, "owen-oracle", 1)
    assert y.shape == (32,)
    np.testing.assert_array_equal(y, gartowen.scramble(x[:, None], "owen-oracle", 1)[:, 0])


@pytest.mark.parametrize(
    "data,exc,fragment",
    [
        (np.array([[0.5, np.nan]]), ValueError, "point 0, dimension 1"),
        (np.array([[0.5, 1.0]]), ValueError, "point 0, dimension 1"),
        (np.array([[0.5, -0.25]]), ValueError, "dimension 1"),
        (np.zeros((4, 2), dtype=np.float32), TypeError, "dtype"),
        (np.zeros((4, 2), dtype=np.int64), TypeError, "dtype"),
        (np.zeros((2, 2, 2), dtype=np.uint32), ValueError, "shape"),
        (np.zeros((0, 2), dtype=np.uint32), ValueError, "empty"),
        ("0.5", TypeError, "NumPy array"),
    ],
)
def test_bad_points(data, exc, fragment):
    with pytest.raises(exc) as info:
        gartowen.scramble(data, "owen-oracle", 1)
    assert fragment in str(info.value)


def test_bad_scrambler_arguments():
    x = sobol_words(n=4, dims=1)
    with pytest.raises(ValueError, match="negative"):
        gartowen.scramble(x, "owen-oracle", -3)
    with pytest.raises(ValueError, match="nope"):
        gartowen.scramble(x, "nope", 1)
    with pytest.raises(ValueError, match="64-bit"):
        gartowen.scramble(np.zeros((4, 1), dtype=np.uint64), "lk-hash", 1)
    # Floats are 64-bit words; the message says how to reach a 32-bit scrambler.
    with pytest.raises(ValueError, match="pass uint32 words"):
        gartowen.scramble(np.zeros((4, 1)), "lk-hash", 1)
    y = gartowen.scramble((np.arange(4) * 2**30).astype(np.uint32), "lk-hash", 1)
    assert y.dtype == np.uint32 and len(set(y.tolist())) == 4


def test_base_3_floats_and_digit_words_equal_the_cli(cli, tmp_path):
    """A base that is not a power of two: floats snapped to the base-3 grid, words as base-3
    digit integers, bit-identical to `gartowen scramble --scramble-base 3`."""
    for extra, name in [(["--bits", "64"], "plain.npy"), (["--words"], "words.npy")]:
        plain = tmp_path / name
        code, _, err = cli.run("generate", "--seq", "faure:base=3", "--dims", "3", "--n", "81",
                               *extra, "-o", plain)
        assert code == 0, err
        out = tmp_path / ("cli-" + name)
        code, _, err = cli.run("scramble", plain, "--scramble", "owen-oracle:per-depth",
                               "--scramble-base", "3", "--seed", "4",
                               *(["--words"] if "--words" in extra else []), "-o", out)
        assert code == 0, err
        mine = gartowen.scramble(np.load(plain), "owen-oracle:per-depth", 4, base=3)
        theirs = np.load(out)
        assert mine.dtype == theirs.dtype and np.array_equal(mine, theirs), name
        assert not np.array_equal(mine, np.load(plain))
        if "--words" not in extra:
            # 64-bit digit words, as `--bits 64` (the default is generate's 32).
            code, _, err = cli.run("scramble", plain, "--scramble", "owen-oracle:per-depth",
                                   "--scramble-base", "3", "--seed", "4", "--bits", "64",
                                   "-o", out)
            assert code == 0, err
            wide = gartowen.scramble(np.load(plain), "owen-oracle:per-depth", 4, base=3, bits=64)
            assert np.array_equal(wide, np.load(out)) and not np.array_equal(wide, mine)
    # Words must be base-3 digit integers below 3^20; other bases' scramblers are refused.
    with pytest.raises(ValueError, match="below 3\\^20"):
        gartowen.scramble(np.array([[3**20]], dtype=np.uint32), "owen-oracle", 0, base=3)
    with pytest.raises(ValueError, match="only owen-oracle"):
        gartowen.scramble(np.array([[0.5]]), "art-owen-2", 0, base=3)
