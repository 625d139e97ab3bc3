"""``moik compile`` (moik.cli.kernels): the kernel families, and the option's check."""

import os
import subprocess
import sys

from moik.cli import main
from moik.cli.kernels import FAMILIES, compile_family, worker_setup
from moik.warmup.background import ENV_SWITCH


def test_processes_must_be_positive(capsys):
    assert main(["compile", "--processes", "0"]) == 2
    assert "--processes must be an integer >= 1, got 0" in capsys.readouterr().err


def test_workers_start_no_background_compile_of_their_own(monkeypatch):
    monkeypatch.setenv(ENV_SWITCH, "1")  # restored afterwards
    worker_setup()
    assert os.environ[ENV_SWITCH] == "0"


def test_a_family_runs_and_reports_what_it_compiled():
    assert set(FAMILIES) >= {"solve", "pareto", "unreachable", "algorithms-multi"}
    name, seconds, count = compile_family("solve-position")
    assert name == "solve-position" and seconds > 0 and count >= 0


def test_a_command_that_compiles_says_how_many_kernels_once(tmp_path):
    """A fresh kernel cache: the one notice at the first compilation, one summary at the
    end; nothing printed twice."""
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)}
    out = subprocess.run([sys.executable, "-m", "moik", "fk", "planar2", "0.1", "0.2"],
                         capture_output=True, text=True, env=env, check=True)
    assert out.stderr.count("compiling moik kernels, first run only") == 1
    assert out.stderr.count("moik: compiled ") == 1 and "`moik compile`" in out.stderr
