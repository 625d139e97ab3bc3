"""A solve's printed time leaves out the first run's compiling and says it."""

import moik._jit as jit_module
from moik.cli.timing import Compiling, compiling


def test_the_time_without_compiling_says_what_was_compiled():
    assert Compiling().time_text(0.0123) == "12.3 ms"
    assert Compiling(kernels=10, seconds=22.1).time_text(22.1123) == \
        "12.3 ms (compiled 10 kernels in 22.1 s first)"
    assert Compiling(kernels=0, seconds=3.0).time_text(3.5) == \
        "500.0 ms (waited 3.0 s for kernels compiled in the background)"


def test_compiling_measures_what_the_block_compiled(monkeypatch):
    import numba  # noqa: F401 - loaded, as in a solve: the counters are read

    state = {"kernels": 4, "seconds": 1.0}
    monkeypatch.setattr(jit_module, "compile_count", lambda: state["kernels"])
    monkeypatch.setattr(jit_module, "compile_seconds", lambda: state["seconds"])
    with compiling() as compiled:
        state.update(kernels=7, seconds=3.5)
    assert (compiled.kernels, compiled.seconds) == (3, 2.5)
