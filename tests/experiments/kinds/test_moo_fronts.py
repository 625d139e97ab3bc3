"""The analytic fronts of the multi-objective benchmark experiments (moo_fronts)."""

import inspect
import socket

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pymoo.problems import get_problem

from moik.experiments.kinds import moo_fronts as fr
from moik.experiments.kinds import moo_functions as mf


def _problem(name):
    if name in fr.IK_FRONTS:  # moik's IK problems: reference fronts shipped as package data
        return mf.build_problem(name, {})
    return get_problem(name, n_obj=3) if name.startswith("dtlz") else get_problem(name)


@pytest.mark.parametrize("name", fr.PYMOO_FRONTS)
def test_the_pymoo_fronts_used_are_closed_form(name):
    """pymoo downloads some fronts (DTLZ7's, WFG's, OSY's, TNK's) through Remote."""
    source = inspect.getsource(type(_problem(name))._calc_pareto_front)
    assert "Remote" not in source and "load(" not in source


def test_the_fronts_never_touch_the_network(monkeypatch):
    def refuse(*args, **kwargs):
        raise AssertionError("network access")

    monkeypatch.setattr(socket, "socket", refuse)
    monkeypatch.setattr(socket, "create_connection", refuse)
    import pymoo.util.remote as remote
    monkeypatch.setattr(remote.Remote, "load", refuse)
    for name in fr.ANALYTIC_FRONTS:
        problem = _problem(name)
        front = fr.analytic_front(problem, name)
        assert front.ndim == 2 and front.shape[1] == problem.n_obj and np.isfinite(front).all()
        if name in fr.CONSTRAINED:  # built here: non-dominated filtered
            assert len(fr.non_dominated(front)) == len(front)
    assert len(fr.analytic_front(_problem("dtlz2"), "dtlz2")) == 496
    assert len(fr.analytic_front(_problem("zdt1"), "zdt1")) == fr.ZDT_FRONT_POINTS


def test_osy_front_ends_and_segments():
    """Deb (2001), Section 14.1: f1 from -274 (x = 5, 1, 5, 0, 5, 0) to -42, f2 from 76 to 4."""
    problem = get_problem("osy")
    front = fr.analytic_front(problem, "osy")
    np.testing.assert_allclose(front.min(axis=0), [-274.0, 4.0])
    np.testing.assert_allclose(front.max(axis=0), [-42.0, 76.0])
    F, G = problem.evaluate(np.array([[5.0, 1.0, 5.0, 0.0, 5.0, 0.0]]),
                            return_values_of=["F", "G"])
    assert np.all(G <= 1e-12)
    np.testing.assert_allclose(F[0], [-274.0, 76.0])  # the f1 end, computed by hand


def test_tnk_front_lies_on_the_first_constraint_boundary():
    problem = get_problem("tnk")
    front = fr.analytic_front(problem, "tnk")
    x1, x2 = front[:, 0], front[:, 1]  # TNK: f = x
    g1 = -(x1**2 + x2**2 - 1.0 - 0.1 * np.cos(16.0 * np.arctan(x1 / x2)))
    np.testing.assert_allclose(g1, 0.0, atol=1e-12)
    assert np.all((x1 - 0.5) ** 2 + (x2 - 0.5) ** 2 <= 0.5 + 1e-12)
    # symmetric in x1 <-> x2, and the known disconnected pieces: no point near (0.6, 0.6)
    assert np.min(np.linalg.norm(front - [0.6, 0.6], axis=1)) > 0.1


@settings(max_examples=25, deadline=None)
@given(st.sampled_from(["bnh", "osy", "srn", "tnk"]), st.integers(0, 2**32 - 1))
def test_no_feasible_point_dominates_a_constrained_front(name, seed):
    """Random feasible points (dense in the box) never beat the analytic front."""
    problem = get_problem(name)
    front = fr.analytic_front(problem, name)
    rng = np.random.default_rng(seed)
    X = problem.xl + rng.random((20_000, problem.n_var)) * (problem.xu - problem.xl)
    F, G = problem.evaluate(X, return_values_of=["F", "G"])
    F = F[np.all(G <= 0.0, axis=1)]
    scale = front.max(axis=0) - front.min(axis=0)
    tol = 1e-3 * scale  # the front is sampled: between samples a point can beat it by a hair
    dominated = np.all(F[:, None, :] <= front[None, :, :] - tol, axis=2)
    assert not dominated.any()


def test_hv_reference_is_beyond_the_nadir_for_either_sign():
    front = np.array([[-274.0, 76.0], [-42.0, 4.0]])
    np.testing.assert_allclose(fr.hv_reference(front), [-37.8, 83.6])
    np.testing.assert_allclose(fr.hv_reference(np.array([[0.0, 1.0], [1.0, 0.0]])), [1.1, 1.1])
