"""Under a memory cap (RLIMIT_AS), requests that do not fit raise MemoryError and the
interpreter lives on: before, generate raised PanicException and scramble aborted the process
(issue 59). Each case runs in a child interpreter whose address space is capped at what it has
mapped plus 1.5 GiB, so the 4 GiB of 2^28 two-dimensional points and the second GiB a scramble
of a 1 GiB array needs cannot be had, while the array itself can."""

import subprocess
import sys
import textwrap

import pytest

CHILD = textwrap.dedent(
    """
    import resource, sys
    import numpy as np
    import gartowen

    def mapped_bytes():
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmSize:"):
                    return int(line.split()[1]) * 1024
        raise SystemExit("no VmSize")

    cap = mapped_bytes() + (3 << 29)
    resource.setrlimit(resource.RLIMIT_AS, (cap, cap))
    case = sys.argv[1]
    try:
        if case == "generate":
            gartowen.generate("sobol", 2, 2**28)
        else:
            x = np.zeros((1 << 26, 2))
            gartowen.scramble(x, "owen-oracle", seed=1)
    except MemoryError as e:
        print("MemoryError:", e)
        # The interpreter is intact: a small request still works.
        assert gartowen.generate("sobol", 2, 8).shape == (8, 2)
        print("alive")
    """
)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS and /proc are Linux's")
@pytest.mark.parametrize("case", ["generate", "scramble"])
def test_requests_past_a_memory_cap_raise_memory_error(case):
    r = subprocess.run(
        [sys.executable, "-c", CHILD, case], capture_output=True, text=True, timeout=300
    )
    assert r.returncode == 0, r.stderr
    assert "MemoryError:" in r.stdout and "alive" in r.stdout, r.stdout + r.stderr
