"""gartowen.discrepancy against exact Fraction arithmetic written here, SciPy and the CLI."""

from fractions import Fraction

import numpy as np
import pytest

import gartowen


def l2star_squared(points):
    """Warnock's formula in exact rationals."""
    n, d = len(points), len(points[0])
    single = sum(np.prod([(1 - x * x) / 2 for x in p]) for p in points)
    pair = sum(np.prod([1 - max(a, b) for a, b in zip(p, q)]) for p in points for q in points)
    return Fraction(1, 3**d) - Fraction(2, n) * single + Fraction(1, n * n) * pair


def centered_squared(points):
    """Hickernell's centered L2 discrepancy in exact rationals."""
    n, d = len(points), len(points[0])
    h = Fraction(1, 2)
    single = sum(np.prod([1 + h * abs(x - h) - h * (x - h) ** 2 for x in p]) for p in points)
    pair = sum(
        np.prod([1 + h * abs(a - h) + h * abs(b - h) - h * abs(a - b) for a, b in zip(p, q)])
        for p in points
        for q in points
    )
    return Fraction(13, 12) ** d - Fraction(2, n) * single + Fraction(1, n * n) * pair


def as_fractions(words, bits=32):
    return [[Fraction(int(w), 1 << bits) for w in row] for row in words]


@pytest.mark.parametrize("dims,n", [(2, 32), (3, 24), (5, 16)])
def test_exact_equals_fractions(dims, n):
    w = gartowen.generate("sobol", dims, n, scramble="owen-oracle", seed=dims, words=True)
    pts = as_fractions(w)
    for kind, formula in [("l2star", l2star_squared), ("cd", centered_squared)]:
        want = formula(pts)
        r = gartowen.discrepancy(w, kind, "exact")
        assert r.exact == want
        assert r.value == float(want)  # correctly rounded
        assert r.squared and r.method == "exact"
        # Its bound covers the one rounding to float: 0 only when the float is exact.
        assert r.rel_error_bound == (0 if Fraction(r.value) == want else 2.0**-53)
        # auto keeps its promised bound against the exact value.
        a = gartowen.discrepancy(w, kind)
        assert a.rel_error_bound is not None and a.rel_error_bound <= 1e-12
        assert abs(Fraction(a.value) - want) <= Fraction(a.rel_error_bound) * want
        # The root is the square root of the same value.
        assert gartowen.discrepancy(w, kind, "exact", root=True).value == pytest.approx(
            float(want) ** 0.5, rel=1e-15)


def test_fast_2d_is_exact():
    w = gartowen.generate("sobol", 2, 64, scramble="owen-per-bit-hash", seed=3, words=True)
    r = gartowen.discrepancy(w)
    assert r.method == "fast" and r.exact == l2star_squared(as_fractions(w))


def test_agrees_with_scipy():
    qmc = pytest.importorskip("scipy.stats.qmc")
    x = gartowen.generate("sobol", 4, 512, scramble="owen-oracle", seed=1)
    # SciPy returns D for L2-star and D^2 for CD and WD.
    assert gartowen.discrepancy(x, "l2star", root=True).value == pytest.approx(
        qmc.discrepancy(x, method="L2-star"), rel=1e-9)
    assert gartowen.discrepancy(x, "cd").value == pytest.approx(
        qmc.discrepancy(x, method="CD"), rel=1e-9)
    assert gartowen.discrepancy(x, "wd").value == pytest.approx(
        qmc.discrepancy(x, method="WD"), rel=1e-9)


def test_equals_the_cli(cli, tmp_path):
    x = gartowen.generate("sz16", 3, 256, scramble="owen-oracle", seed=2, words=True)
    f = tmp_path / "x.npy"
    np.save(f, x)
    for kind in ("l2star", "cd", "wd", "gl2"):
        _, doc = cli.json("discrepancy", f, "--kind", kind, "--pairs", "first", "--json")
        r = gartowen.discrepancy(x, kind, pairs="first")
        assert r.value == doc["result"]["value"]
        assert r.method == doc["result"]["method"]
        assert [p.value for p in r.pairs] == [p["value"] for p in doc["result"]["pairs"]]
        assert [p.pair for p in r.pairs] == [tuple(p["pair"]) for p in doc["result"]["pairs"]]


@pytest.mark.parametrize(
    "args,exc,fragment",
    [
        (dict(kind="star"), ValueError, "unknown kind 'star'; use l2star, cd, wd or gl2"),
        (dict(method="quick"), ValueError, "unknown method 'quick'; use auto, naive, compensated"),
        (dict(kind="cd", method="fast"), ValueError, "2-D L2-star"),
        (dict(pairs="some"), ValueError, "pairs"),
    ],
)
def test_bad_arguments(args, exc, fragment):
    x = gartowen.generate("sobol", 3, 16)
    with pytest.raises(exc) as info:
        gartowen.discrepancy(x, **args)
    assert fragment in str(info.value)


def test_nan_is_refused():
    x = gartowen.generate("sobol", 2, 8)
    x[3, 0] = np.nan
    with pytest.raises(ValueError, match="point 3, dimension 0"):
        gartowen.discrepancy(x)


def test_values_outside_the_float_range():
    # One point in 2600 dimensions: WD's D^2 overflows a float, L2-star's underflows.
    x = ((np.arange(2600) * 7919) % 1024 / 1024.0).reshape(1, -1)
    wd = gartowen.discrepancy(x, "wd")
    assert wd.value == float("inf") and wd.rel_error_bound is None and wd.exact > 10**308
    l2 = gartowen.discrepancy(x, "l2star")
    assert l2.value == 0.0 and l2.rel_error_bound is None and 0 < l2.exact < Fraction(1, 10**308)


def test_64_bit_words_void_the_float_bound_and_compensated_falls_back_to_exact():
    w = gartowen.generate("sobol", 3, 256, scramble="owen-oracle", seed=5, bits=64, words=True)
    comp = gartowen.discrepancy(w, "cd", "compensated")
    assert comp.method == "exact"
    assert abs(Fraction(comp.value) - comp.exact) <= Fraction(comp.rel_error_bound) * comp.exact
    auto = gartowen.discrepancy(w, "cd")
    assert auto.method == "exact"
    assert abs(Fraction(auto.value) - auto.exact) <= Fraction(auto.rel_error_bound) * auto.exact
