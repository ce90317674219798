"""gartowen inside Mitsuba 3 (issue 58): the per-key scrambles the sampler draws, the sampler in
a real render, the quick rendering benchmark and its fixed-table check, and the messages where
Mitsuba or libLLVM is missing. The render tests need Mitsuba 3 and libLLVM ≥ 16, which the test
command installs (scripts/python-tests.sh, scripts/prerequisites.sh); where they are missing
they are skipped, saying why."""

import json
import os
import subprocess
import sys

import numpy as np
import pytest

import gartowen
import gartowen.mitsuba as gm


def _mitsuba_or_reason():
    try:
        return gm.load_mitsuba(), None
    except gm.MitsubaUnavailable as e:
        return None, str(e)


MI, WHY = _mitsuba_or_reason()
needs_mitsuba = pytest.mark.skipif(MI is None, reason=f"Mitsuba unavailable: {WHY}")


def test_per_key_scrambles_are_the_scrambles_of_each_key():
    w = gartowen.generate("sobol", 3, 64, bits=32, words=True)
    keys = [5, 9, (1 << 64) - 1]
    fresh = gartowen.scramble_per_key(w, "owen-oracle:base=2", keys)
    assert fresh.shape == (3, 64, 3) and fresh.dtype == np.uint32
    for k, key in enumerate(keys):
        assert (fresh[k] == gartowen.scramble(w, "owen-oracle:base=2", key)).all()
    # One fixed ART table: keyed by its own seed it is the scrambler itself; other keys give
    # other scrambles of it, each keeping the nested structure (column 0's first two points,
    # 0 and 1/2, differ in their first base-16 digit under every key).
    fixed = gartowen.scramble_per_key(w, "art-owen-16p", [77, 3, 4], table_seed=77)
    assert (fixed[0] == gartowen.scramble(w, "art-owen-16p", 77)).all()
    assert not (fixed[1] == fixed[0]).all() and not (fixed[1] == fixed[2]).all()
    assert ((fixed[:, 0, 0] ^ fixed[:, 1, 0]) >> np.uint32(28) != 0).all()
    # Column j is dimension first_dim + j.
    shifted = gartowen.scramble_per_key(w[:, 1:], "art-owen-16p", [3], table_seed=77, first_dim=1)
    assert (shifted[0] == fixed[1][:, 1:]).all()


@pytest.mark.parametrize(
    "call,exc,fragment",
    [
        (lambda w: gartowen.scramble_per_key(w.astype(np.uint64), "lk-hash", [1]), TypeError, "uint32"),
        (lambda w: gartowen.scramble_per_key(w, "lk-hash", []), ValueError, "empty"),
        (lambda w: gartowen.scramble_per_key(w, "owen-oracle", [1], table_seed=3), ValueError, "no table"),
        (lambda w: gartowen.scramble_per_key(w, "nope", [1]), ValueError, "nope"),
        (lambda w: gartowen.scramble_per_key(w, "lk-hash", [-1]), ValueError, "negative"),
    ],
)
def test_per_key_scrambles_refuse_bad_input(call, exc, fragment):
    w = gartowen.generate("sobol", 2, 8, bits=32, words=True)
    with pytest.raises(exc) as info:
        call(w)
    assert fragment in str(info.value)


def _child(code):
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)


def test_missing_mitsuba_or_libllvm_names_the_install_line():
    r = _child("import sys; sys.modules['mitsuba'] = None\n"
               "import os; os.environ['DRJIT_LIBLLVM_PATH'] = '/nonexistent'\n"
               "import gartowen.mitsuba as gm\n"
               "try:\n    gm.load_mitsuba()\nexcept gm.MitsubaUnavailable as e:\n    print(e)\n")
    assert "pip install" in r.stdout and "mitsuba" in r.stdout, r.stdout + r.stderr
    r = _child("import os; os.environ.pop('DRJIT_LIBLLVM_PATH', None)\n"
               "import gartowen.mitsuba as gm\n"
               "gm.find_libllvm = lambda: None\n"
               "try:\n    gm.load_mitsuba()\nexcept gm.MitsubaUnavailable as e:\n    print(e)\n")
    assert "libllvm19" in r.stdout, r.stdout + r.stderr
    # The command line says so with exit 2, never a traceback.
    r = _child("import sys; sys.modules['mitsuba'] = None\n"
               "import os; os.environ['DRJIT_LIBLLVM_PATH'] = '/nonexistent'\n"
               "import gartowen.render as gr; sys.exit(gr.main(['--quick', '--out', '/tmp/x']))")
    assert r.returncode == 2 and "pip install" in r.stderr and "Traceback" not in r.stderr, r.stderr


def test_bad_render_arguments_exit_2_naming_them(tmp_path):
    import gartowen.render as gr
    for args, fragment in [(["--scenes", "kitchen"], "unknown scene 'kitchen'"),
                           (["--sizes", "0,16"], "--sizes"), (["--seeds", "1"], "--seeds"),
                           (["--methods", "sobol-owen,ldsampler2"], "unknown method 'ldsampler2'")]:
        r = _child(f"import sys, gartowen.render as gr; sys.exit(gr.main({args + ['--out', str(tmp_path)]!r}))")
        assert r.returncode == 2 and fragment in r.stderr and "Traceback" not in r.stderr, r.stderr


@needs_mitsuba
def test_a_gartowen_render_agrees_with_mitsubas_independent_sampler_within_its_se():
    import gartowen.render as gr
    scene = gr.scenes(MI, quick=True)["cornell"]
    reference, _ = gr.reference(MI, "cornell", scene, 4096, None)
    independent = [gr.render(MI, scene, gr.Method("i", {"type": "independent"}), 64, s)[0]
                   for s in range(6)]
    se = np.std([im.mean() for im in independent], ddof=1)
    owen = gr.Method("o", {"type": "gartowen", "sequence": "sobol", "scramble": "owen-oracle:base=2"})
    ours = [gr.render(MI, scene, owen, 64, s)[0] for s in range(6)]
    # Unbiased: the image mean within 4 SE of the reference's (a value outside [0, 1) or a
    # wrong lane order would move it); and better than independent sampling.
    assert abs(np.mean([im.mean() for im in ours]) - reference.mean()) < 4 * se
    rmse = lambda ims: np.mean([np.sqrt(((im - reference) ** 2).mean()) for im in ims])
    assert rmse(ours) < 0.6 * rmse(independent)


@needs_mitsuba
def test_the_quick_benchmark_and_its_fixed_table_check(tmp_path):
    import gartowen.render as gr
    doc = gr.run(True, str(tmp_path), seeds=8, sizes=[16, 64], log=open(os.devnull, "w"))
    rows = doc["scenes"]["cornell"]["methods"]
    for label, by_n in rows.items():
        for n, r in by_n.items():
            shared = label.startswith("control")
            # Per-pixel keys leave pixels uncorrelated; one key for every pixel does not.
            assert r["fixed_table_check"]["passes"] != shared, (label, n, r["fixed_table_check"])
    pairs = {(p["method"], p["against"], p["n"]): p["verdict"] for p in doc["scenes"]["cornell"]["pairs"]}
    assert pairs[("sobol + owen (binary)", "mitsuba independent", 64)] == "better"
    for name in ("render.json", "render.md", "cornell-reference.png", "cornell-error-0.png"):
        assert (tmp_path / name).stat().st_size > 0
    assert json.loads((tmp_path / "render.json").read_text())["seeds"] == 8
    # Each pair states the ratio it detects at power 0.9 and the seeds equivalence would need.
    for p in doc["scenes"]["cornell"]["pairs"]:
        assert p["detects"] > 1 and (p["seeds_for_equivalence"] is None or p["seeds_for_equivalence"] >= 1)


def test_pair_verdicts_state_their_power_and_the_seeds_equivalence_needs():
    import gartowen.render as gr
    rng = np.random.default_rng(5)
    a, b = rng.gamma(4.0, 0.25, 64), rng.gamma(4.0, 0.25, 64)
    v = gr.verdict(a, b, 0.2, 0.05)
    # The detectable ratio is exp((z_{α/2} + z_{0.9})·se); at 64 seeds of CV 0.5 per side,
    # se ≈ 0.088, so about exp(3.24 · 0.088) ≈ 1.33.
    assert 1.2 < v["detects"] < 1.5, v
    # Equal means: the seeds equivalence needs do not depend on how many were run (se² ∝
    # 1/seeds), so the same data twice over predicts about the same number.
    once = gr.verdict(a, a[::-1].copy(), 0.2, 0.05)["seeds_for_equivalence"]
    twice = gr.verdict(np.tile(a, 2), np.tile(a[::-1], 2), 0.2, 0.05)["seeds_for_equivalence"]
    assert once is not None and 0.9 < twice / once < 1.1, (once, twice)
    far = gr.verdict(a * 2, b, 0.2, 0.05)
    assert far["seeds_for_equivalence"] is None and far["verdict"] == "worse"


@needs_mitsuba
def test_methods_select_what_runs(tmp_path):
    import gartowen.render as gr
    doc = gr.run(True, str(tmp_path), seeds=2, sizes=[4], log=open(os.devnull, "w"),
                 method_keys=["sobol-owen", "independent"])
    # In the benchmark's order, and the pair between them judged.
    assert list(doc["scenes"]["cornell"]["methods"]) == ["mitsuba independent", "sobol + owen (binary)"]
    assert [(p["method"], p["against"]) for p in doc["scenes"]["cornell"]["pairs"]] == [
        ("sobol + owen (binary)", "mitsuba independent")]
