"""gartowen.generate: agreement with the CLI, with SciPy's Sobol, and its refusals."""

import numpy as np
import pytest

import gartowen


@pytest.mark.parametrize(
    "seq,dims,n,scramble,bits",
    [
        ("sobol", 5, 100, None, 32),
        ("sz16", 16, 256, "owen-oracle", 32),
        ("sz4", 4, 64, "q-art-4", 64),
        ("sobol", 3, 33, "owen-per-bit-hash", 64),
    ],
)
def test_words_equal_the_cli(cli, tmp_path, seq, dims, n, scramble, bits):
    out = tmp_path / "x.npy"
    args = ["generate", "--seq", seq, "--dims", dims, "--n", n, "--bits", bits, "--seed", 7,
            "--format", "npy", "--words", "-o", out]
    if scramble:
        args += ["--scramble", scramble]
    cli.run(*args)
    expected = np.load(out)
    got = gartowen.generate(seq, dims, n, scramble=scramble, seed=7, bits=bits, words=True)
    assert got.dtype == expected.dtype == (np.uint32 if bits == 32 else np.uint64)
    assert got.shape == (n, dims)
    np.testing.assert_array_equal(got, expected)


def test_floats_equal_the_cli(cli, tmp_path):
    out = tmp_path / "x.npy"
    cli.run("generate", "--seq", "sz16", "--dims", 4, "--n", 512, "--scramble", "art-owen-16p",
            "--seed", 3, "--format", "npy", "-o", out)
    got = gartowen.generate("sz16", 4, 512, scramble="art-owen-16p", seed=3)
    assert got.dtype == np.float64
    np.testing.assert_array_equal(got, np.load(out))
    assert got.min() >= 0.0 and got.max() < 1.0


def test_sobol_equals_scipy_bit_for_bit():
    qmc = pytest.importorskip("scipy.stats.qmc")
    for dims, m in [(1, 6), (8, 10), (40, 7)]:
        ref = qmc.Sobol(dims, scramble=False, bits=32).random_base2(m)
        ours = gartowen.generate("sobol", dims, 1 << m, words=True, order="gray")
        # SciPy's values are words * 2^-32, exactly.
        np.testing.assert_array_equal((ref * 2.0**32).astype(np.uint64), ours.astype(np.uint64))
        np.testing.assert_array_equal(ref, gartowen.generate("sobol", dims, 1 << m, order="gray"))


def test_start_and_scramble_base():
    whole = gartowen.generate("sobol", 2, 64, scramble="owen-oracle", seed=5, words=True)
    tail = gartowen.generate("sobol", 2, 32, scramble="owen-oracle", seed=5, words=True, start=32)
    np.testing.assert_array_equal(whole[32:], tail)
    b2 = gartowen.generate("sobol", 2, 64, scramble="owen-oracle", seed=5, words=True)
    b4 = gartowen.generate("sobol", 2, 64, scramble="owen-oracle", seed=5, words=True, base=4)
    assert not np.array_equal(b2, b4)
    # A base-4 scramble keeps the base-4 t-value of a Sobol net (nested in base 4), though not
    # necessarily its base-2 t-value (a base-4 scramble is not nested in base 2).
    plain = gartowen.generate("sobol", 2, 64, words=True)
    assert gartowen.check(b4, 4).t == gartowen.check(plain, 4).t


@pytest.mark.parametrize(
    "kwargs,exc,fragment",
    [
        (dict(seq="halton", dims=2, n=4), ValueError, "halton"),
        (dict(seq="sz16", dims=17, n=4), ValueError, "17"),
        (dict(seq="sobol", dims=2, n=0), ValueError, "at least 1"),
        (dict(seq="sobol", dims=2, n=4, scramble="lk-hash", base=4), ValueError, "conflicts with lk-hash"),
        (dict(seq="sobol", dims=2, n=4, bits=16), ValueError, "32 or 64"),
        (dict(seq="sobol", dims=2, n=4, scramble="nope"), ValueError, "nope"),
        (dict(seq="sobol", dims=2, n=4, seed=-1), ValueError, "negative"),
        (dict(seq="sobol", dims=2, n=4, seed=1 << 64), ValueError, "out of range"),
        (dict(seq="sobol", dims=2, n=4, seed=1.5), TypeError, "integer"),
        (dict(seq="sobol", dims=2, n=4, seed=True), TypeError, "bool"),
        (dict(seq="sobol", dims=-2, n=4), ValueError, "dims"),
        (dict(seq="sobol", dims=2, n=4, order="reverse"), ValueError, "order"),
        (dict(seq=3, dims=2, n=4), TypeError, "seq"),
        (dict(seq="sobol", dims=2, n=1 << 40), ValueError, ""),
    ],
)
def test_bad_arguments_raise_clear_errors(kwargs, exc, fragment):
    with pytest.raises(exc) as info:
        gartowen.generate(**kwargs)
    assert fragment in str(info.value)


@pytest.mark.parametrize(
    "args,kwargs",
    [
        (["--seq", "halton", "--dims", 2, "--n", 4], dict(seq="halton", dims=2, n=4)),
        (["--seq", "sz16", "--dims", 17, "--n", 4], dict(seq="sz16", dims=17, n=4)),
        (["--seq", "sobol", "--dims", 2, "--n", 0], dict(seq="sobol", dims=2, n=0)),
        (["--seq", "sobol", "--dims", 2, "--n", 4, "--scramble", "nope"],
         dict(seq="sobol", dims=2, n=4, scramble="nope")),
        (["--seq", "sobol", "--dims", 2, "--n", 4, "--scramble", "owen-oracle:base=3"],
         dict(seq="sobol", dims=2, n=4, scramble="owen-oracle:base=3")),
        (["--seq", "sz4", "--dims", 2, "--n", 1 << 40], dict(seq="sz4", dims=2, n=1 << 40)),
    ],
)
def test_errors_carry_the_cli_message(cli, args, kwargs):
    code, _, err = cli.run("generate", *args, check=False)
    assert code == 2
    with pytest.raises(ValueError) as info:
        gartowen.generate(**kwargs)
    assert str(info.value) in err, (str(info.value), err)
