"""The Python examples of docs/python.md and examples/python/verify_my_scrambler.py run as documented."""

import json
import pathlib
import re
import subprocess
import sys

REPO = pathlib.Path(__file__).resolve().parents[2]


def readme_python_blocks():
    text = (REPO / "docs" / "python.md").read_text()
    return re.findall(r"```python\n(.*?)```", text, re.S)


def test_readme_examples_run_and_say_what_they_print(capsys):
    blocks = readme_python_blocks()
    assert len(blocks) >= 5  # one per function at least
    namespace = {}
    for block in blocks:
        exec(compile(block, "docs/python.md", "exec"), namespace)
    # The claims the comments make.
    assert namespace["r"].passed is False
    assert {"pair-law", "flip-rank"} <= {c["check"] for c in namespace["r"].failures}
    assert namespace["e"].exact is not None
    assert namespace["d"].rel_error_bound <= 1e-12


def test_verify_my_scrambler_example():
    script = REPO / "examples" / "python" / "verify_my_scrambler.py"
    r = subprocess.run([sys.executable, str(script)], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "as expected" in r.stdout
    assert "python:my_owen (claim owen): pass" in r.stdout
    assert "python:my_shift (claim owen): FAIL" in r.stdout


def test_the_front_readme_python_example_prints_what_its_comment_says(capsys):
    text = (REPO / "README.md").read_text()
    (block,) = re.findall(r"```python\n(.*?)```", text, re.S)
    exec(compile(block, "README.md", "exec"), {})
    printed = capsys.readouterr().out.split()
    # The comment: "0: still a (0,3,16)-net in base 16".
    assert re.search(r"# (\d+): still a \(\1,", block), "the comment states a t-value"
    t = re.search(r"# (\d+): still", block).group(1)
    assert printed == [t]


def _verify_external_radix(cli, tmp_path, *flags):
    """`gartowen verify --external "python owen_radix.py FLAGS" --base 3`: exit code and checks."""
    program = REPO / "examples" / "external" / "owen_radix.py"
    command = " ".join([sys.executable, str(program), *flags])
    out = tmp_path / "verify.json"
    code, _, err = cli.run("verify", "--external", command, "--base", "3", "--json", out)
    implementation = json.loads(out.read_text())["result"]["implementations"][0]
    return code, err, {c["check"]: c["verdict"] for c in implementation["checks"]}


def test_the_python_base_3_owen_program_passes_and_its_per_depth_variant_fails_the_joint_laws(
    cli, tmp_path
):
    code, err, verdicts = _verify_external_radix(cli, tmp_path)
    assert code == 0, err
    assert verdicts.pop("flip-rank") == "not-run"
    assert set(verdicts.values()) == {"pass"}, verdicts
    assert "nets" in verdicts and "pair-law" in verdicts
    code, err, verdicts = _verify_external_radix(cli, tmp_path, "--per-depth")
    assert code == 1, err
    failed = {check for check, verdict in verdicts.items() if verdict == "fail"}
    assert failed == {"pair-law", "collisions", "pair-lemma"}, verdicts
