"""The package type-checks: ``python -m mypy moik`` with the ``[tool.mypy]`` of pyproject.toml.

mypy (and the stubs of the typed dependencies) come with the ``test`` extra, so the README's
test command, which CI runs, checks the types too. The run takes no cache
(``--cache-dir`` is the null device): measured on the 2-core machine, a cold run with the
null device took 94 s against 105 s with a fresh cache folder under ``tmp_path``, and 36 s
both on a quieter machine.
"""

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("mypy", reason="mypy comes with the test extra (Python >= 3.11)")

ROOT = Path(__file__).resolve().parents[1]
ERROR = re.compile(r"^(?P<path>[^:\s]+\.py):\d+: error: ", re.MULTILINE)


def _mypy() -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "mypy", f"--cache-dir={os.devnull}", "moik"],
                          cwd=ROOT, capture_output=True, text=True, timeout=600)


def test_mypy_finds_no_error_in_the_package():
    run = _mypy()
    output = run.stdout + run.stderr
    assert run.returncode in (0, 1), f"mypy did not run (exit {run.returncode}):\n{output}"
    errors = [m.group(0) for m in ERROR.finditer(run.stdout)]
    assert run.returncode == 0 and not errors, f"mypy errors:\n{output}"
