"""Start-up: ``import moik`` stays cheap, and the public API does not pull in the heavy
optional modules (scipy.stats, matplotlib). Checked in fresh interpreters (subprocess),
since this test session has imported everything already. Speed itself is measured by
benchmarks, not asserted here."""

import json
import subprocess
import sys

import pytest

import moik

HEAVY = ["scipy.stats", "matplotlib", "numba", "pymoo", "scipy"]


def loaded_after(code: str) -> dict[str, bool]:
    """Which of :data:`HEAVY` a fresh interpreter has imported after running ``code``."""
    script = (f"import json, sys\n{code}\n"
              f"print(json.dumps({{m: m in sys.modules for m in {HEAVY!r}}}))")
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                         check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_import_moik_loads_no_heavy_module():
    assert not any(loaded_after("import moik").values())


def test_the_public_api_does_not_import_scipy_stats_or_matplotlib():
    loaded = loaded_after("import moik\nfor name in moik.__all__:\n    getattr(moik, name)")
    assert loaded["numba"] and loaded["pymoo"]  # the API itself was loaded
    assert not loaded["scipy.stats"] and not loaded["matplotlib"]


def test_public_names_load_on_first_use():
    from moik import get_robot, solve_ik
    from moik.robots import get_robot as robots_get_robot
    from moik.solver import solve_ik as solver_solve_ik

    assert get_robot is robots_get_robot and solve_ik is solver_solve_ik
    assert set(moik.__all__) <= set(dir(moik))
    with pytest.raises(AttributeError, match="no attribute 'solve_everything'"):
        moik.solve_everything  # noqa: B018
