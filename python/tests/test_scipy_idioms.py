"""SciPy's spellings: accepted where they mean the same thing, refused with the gartowen
equivalent where they do not; errors speak Python."""

import numpy as np
import pytest

import gartowen


def test_d_is_dims_and_scramble_false_is_no_scramble():
    a = gartowen.generate("sobol", d=3, n=16, words=True)
    b = gartowen.generate("sobol", 3, 16, words=True)
    c = gartowen.generate("sobol", 3, 16, scramble=False, words=True)
    assert np.array_equal(a, b) and np.array_equal(b, c)
    with pytest.raises(TypeError, match="not both"):
        gartowen.generate("sobol", 3, 16, d=3)
    with pytest.raises(TypeError, match="needs dims"):
        gartowen.generate("sobol", n=16)


def test_scramble_true_names_the_equivalents():
    with pytest.raises(ValueError) as info:
        gartowen.generate("sobol", d=2, n=16, scramble=True)
    message = str(info.value)
    assert "owen-oracle" in message and "lms-shift" in message
    # The named equivalent works.
    x = gartowen.generate("sobol", d=2, n=16, scramble="lms-shift", seed=1)
    assert x.shape == (16, 2)


def test_scipy_kind_names_and_convention():
    qmc = pytest.importorskip("scipy.stats.qmc")
    x = gartowen.generate("sobol", 3, 256, scramble="owen-oracle", seed=4)
    for name in ("L2-star", "CD", "WD"):
        ours = gartowen.discrepancy(x, name, scipy_convention=True).value
        assert ours == pytest.approx(qmc.discrepancy(x, method=name), rel=1e-9), name
        # method= as in qmc.discrepancy(sample, method=...) reads as the kind.
        assert gartowen.discrepancy(x, method=name, scipy_convention=True).value == ours
    # Without the convention, L2-star is D^2: the square of SciPy's number.
    d = qmc.discrepancy(x, method="L2-star")
    assert gartowen.discrepancy(x, "L2-star").value == pytest.approx(d * d, rel=1e-9)
    assert gartowen.discrepancy(x, "cd").value == gartowen.discrepancy(x, "CD").value


def test_what_gartowen_lacks_is_refused_with_its_names():
    x = gartowen.generate("sobol", 2, 16)
    with pytest.raises(ValueError, match="mixture discrepancy .* 'cd'"):
        gartowen.discrepancy(x, "MD")
    with pytest.raises(ValueError, match="give the kind once"):
        gartowen.discrepancy(x, "cd", method="WD")


def test_errors_speak_python():
    x = gartowen.generate("sobol", 2, 24, words=True)  # 24 is not a power of 2
    with pytest.raises(ValueError, match="Python's m="):
        gartowen.check(x, 2)
    with pytest.raises(ValueError, match="claims are lower case: 'owen'"):
        gartowen.verify(lambda words, dim, seed: words, 2, 32, claims="Owen")
