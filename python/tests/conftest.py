"""Shared fixtures: the gartowen command-line tool, to compare the package with it."""

import json
import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


def _find_cli():
    env = os.environ.get("GARTOWEN_BIN")
    if env:
        return pathlib.Path(env)
    for profile in ("debug", "release"):
        p = REPO / "target" / profile / "gartowen"
        if p.exists():
            return p
    return None


class Cli:
    """Runs the gartowen binary and returns (exit code, stdout, stderr)."""

    def __init__(self, path):
        self.path = path

    def run(self, *args, check=True):
        r = subprocess.run([str(self.path), *map(str, args)], capture_output=True, text=True)
        if check and r.returncode not in (0, 1):
            raise AssertionError(f"gartowen {' '.join(map(str, args))}: exit {r.returncode}\n{r.stderr}")
        return r.returncode, r.stdout, r.stderr

    def json(self, *args):
        code, out, err = self.run(*args)
        return code, json.loads(out)


@pytest.fixture(scope="session")
def cli():
    path = _find_cli()
    if path is None:
        pytest.fail(
            "the gartowen binary is missing: build it (cargo build -p gartowen-cli) or set GARTOWEN_BIN"
        )
    return Cli(path)
