"""gartowen.check: agreement with the CLI, t-values, the first failing box."""

import numpy as np
import pytest

import gartowen


def test_result_equals_the_cli(cli, tmp_path):
    x = gartowen.generate("sz16", 4, 4096, scramble="owen-oracle", seed=1, words=True)
    f = tmp_path / "x.npy"
    np.save(f, x)
    for extra, kwargs in [([], {}), (["--t", 0], dict(t=0)),
                          (["--projections", "pairs"], dict(projections="pairs")),
                          (["--sequence", "--t", 0], dict(sequence=True, t=0))]:
        code, doc = cli.json("check", f, "--base", 16, "--json", *extra)
        r = gartowen.check(x, 16, **kwargs)
        assert r.result == doc["result"]
        assert r.holds == (code == 0)
        assert r.certificate["inputs"][0]["checksum_fnv1a64"] == doc["inputs"][0]["checksum_fnv1a64"]


def test_t_values_of_known_nets():
    assert gartowen.check(gartowen.generate("sobol", 2, 1024), 2).t == 0
    assert gartowen.check(gartowen.generate("sz16", 16, 256), 16).t == 0
    r = gartowen.check(gartowen.generate("sobol", 4, 256), 2, projections="pairs")
    assert set(r.t_values) == {(i, j) for i in range(4) for j in range(i + 1, 4)}
    assert r.t_values[(0, 1)] == 0


def test_first_failing_box_is_real():
    x = gartowen.generate("sobol", 2, 256, words=True)
    x[5] = x[6]  # two equal points: some box now holds 2 and another 0
    r = gartowen.check(x, 2, t=0)
    assert not r.holds
    f = r.first_failure
    assert f is not None and f["count"] != f["expected"]
    # Count the points in the named box independently.
    inside = np.ones(len(x), dtype=bool)
    for j, (d, a) in enumerate(zip(f["shape"], f["box_index"])):
        digit = x[:, j].astype(np.uint64) >> np.uint64(32 - d) if d else np.zeros(len(x), np.uint64)
        inside &= digit == a
    assert inside.sum() == f["count"]
    assert "holds" in f["description"]
    # Without t, the t-value is positive and the witness box shows it is not t - 1.
    r = gartowen.check(x, 2)
    assert r.t > 0 and r.first_failure is not None


def test_floats_words_and_memory_orders_agree():
    w = gartowen.generate("sobol", 3, 512, words=True)
    f = w / 2.0**32
    ref = gartowen.check(w, 2).t
    assert gartowen.check(f, 2).t == ref
    assert gartowen.check(np.asfortranarray(w), 2).t == ref
    assert gartowen.check(w.astype(np.uint64) << np.uint64(32), 2).t == ref
    assert gartowen.check(w[:, ::2], 2).t == gartowen.check(np.ascontiguousarray(w[:, ::2]), 2).t


def test_base_four_nets():
    x = gartowen.generate("sz4", 4, 1024, scramble="q-art-4", seed=8, words=True)
    assert gartowen.check(x, 4).t == 0
    assert gartowen.check(x, 4, sequence=True, t=0).holds


@pytest.mark.parametrize(
    "kwargs,exc,fragment",
    [
        (dict(base=1), ValueError, "base"),
        (dict(base=2, projections="0,9"), ValueError, "9"),
        (dict(base=2, t=-1), ValueError, "negative"),
        (dict(base=2, projections=3), TypeError, "projections"),
    ],
)
def test_bad_arguments(kwargs, exc, fragment):
    x = gartowen.generate("sobol", 2, 16)
    with pytest.raises(exc) as info:
        gartowen.check(x, **kwargs)
    assert fragment in str(info.value)


def test_errors_carry_the_cli_message(cli, tmp_path):
    x = gartowen.generate("sobol", 2, 16)
    f = tmp_path / "x.npy"
    np.save(f, x)
    for args, kwargs in [(["--base", 1], dict(base=1)),
                         (["--base", 2, "--projections", "0,9"], dict(base=2, projections="0,9")),
                         (["--base", 2, "--m", 9], dict(base=2, m=9))]:
        code, _, err = cli.run("check", f, *args, check=False)
        assert code == 2
        with pytest.raises(ValueError) as info:
            gartowen.check(x, **kwargs)
        assert str(info.value) in err, (str(info.value), err)


def test_scipy_halton_floats_check_with_the_right_t_in_bases_3_and_5(cli, tmp_path):
    """Unscrambled SciPy Halton points (another tool's floats): each coordinate is a (0,m,1)-net
    in its own base once snapped; read by floor, base 3 is not even a (0,1,1)-net."""
    qmc = pytest.importorskip("scipy.stats.qmc")
    x = qmc.Halton(d=3, scramble=False).random(3 ** 8)
    for m in range(1, 9):
        assert gartowen.check(x[: 3 ** m, 1], 3, m=m).t == 0, m
    for m in range(1, 6):
        assert gartowen.check(x[: 5 ** m, 2], 5, m=m).t == 0, m
    assert gartowen.check(x[:3, 1], 3, m=1, snap=False).t == 1
    r = gartowen.check(x[:, 1], 3, m=8)
    assert r.certificate["parameters"]["snap"]["depth"] == 8
    # The CLI on the same file says the same.
    f = tmp_path / "halton.npy"
    np.save(f, np.ascontiguousarray(x[:, 1]))
    code, doc = cli.json("check", f, "--base", 3, "--m", 8, "--t", 0, "--json")
    assert code == 0 and doc["result"]["holds"]


def test_floats_rounded_coarser_than_float_error_are_refused():
    x = np.array([0.0, 1 / 3, 2 / 3])
    coarse = np.floor(x * 2.0 ** 44) / 2.0 ** 44
    with pytest.raises(ValueError, match="point 1 coordinate 0"):
        gartowen.check(coarse, 3, m=1)
    assert gartowen.check(x, 3, m=1).t == 0
