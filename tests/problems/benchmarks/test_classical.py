"""Classical functions F1-F23 (MChOA Table 2) against their known optima.

Optimum sources: Yao, Liu & Lin (1999), IEEE TEC 3(2), Table I-III (F1-F23
values and locations); Jamil & Yang (2013), Int. J. Math. Model. Numer. Optim.
4(2) (Kowalik, camel, Branin, Goldstein-Price, Hartman, Shekel to more digits);
Surjanovic & Bingham, SFU Virtual Library of Simulation Experiments (Hartman 3/6
minimizers, Shekel optima -10.1532/-10.4029/-10.5364, Branin 0.397887).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import minimize

from moik.exceptions import ParameterError, UnknownNameError
from moik.problems.benchmarks import available_benchmarks, get_benchmark

# name: (literature optimum value, literature location, tolerance at that location)
LITERATURE = {
    "F14": (0.998004, [-31.97833, -31.97833], 1e-6),  # Yao 1999; foxholes
    "F15": (0.0003075, [0.1928, 0.1908, 0.1231, 0.1358], 2e-7),  # Yao 1999; Kowalik
    "F16": (-1.0316285, [0.08983, -0.7126], 1e-7),  # Yao 1999; six-hump camel
    "F17": (0.397887, [-np.pi, 12.275], 1e-6),  # Yao 1999; Branin
    "F18": (3.0, [0.0, -1.0], 1e-12),  # Yao 1999; Goldstein-Price
    "F19": (-3.86278, [0.114614, 0.555649, 0.852547], 1e-5),  # SFU; Hartman 3
    "F20": (-3.32237, [0.20169, 0.150011, 0.476874, 0.275332, 0.311652, 0.6573], 1e-5),
    "F21": (-10.1532, [4.0, 4.0, 4.0, 4.0], 1e-4),  # SFU; Shekel m=5
    "F22": (-10.4029, [4.0, 4.0, 4.0, 4.0], 2e-4),  # SFU; Shekel m=7
    "F23": (-10.5364, [4.0, 4.0, 4.0, 4.0], 2e-4),  # SFU; Shekel m=10
}

# scalable: name -> (bound, optimum location value, optimum per dimension)
SCALABLE = {
    "F1": (100.0, 0.0, 0.0),
    "F2": (10.0, 0.0, 0.0),
    "F3": (100.0, 0.0, 0.0),
    "F4": (100.0, 0.0, 0.0),
    "F5": (30.0, 1.0, 0.0),
    "F6": (100.0, -0.5, 0.0),
    "F7": (1.28, 0.0, 0.0),
    "F8": (500.0, 420.9687, -418.9829),  # Yao 1999: -12569.5 at n=30
    "F9": (5.12, 0.0, 0.0),
    "F10": (32.0, 0.0, 0.0),
    "F11": (600.0, 0.0, 0.0),
    "F12": (50.0, -1.0, 0.0),
    "F13": (50.0, 1.0, 0.0),
}


def value(problem, x) -> float:
    return float(problem.evaluate(np.atleast_2d(np.asarray(x, dtype=float)))[0, 0])


def test_registry_lists_all_23():
    names = available_benchmarks()
    assert all(f"F{i}" in names for i in range(1, 24))


def test_unknown_name_lists_valid_names():
    with pytest.raises(UnknownNameError, match="unknown benchmark 'F25'.*F1, F10"):
        get_benchmark("F25")


def test_bad_keyword_and_dimension():
    with pytest.raises(ParameterError, match="unknown keyword"):
        get_benchmark("F16", n_var=3)
    with pytest.raises(ParameterError, match="n_var must be an integer >= 2"):
        get_benchmark("F1", n_var=0)


@pytest.mark.parametrize("name", list(SCALABLE))
@pytest.mark.parametrize("n_var", [2, 30])
def test_scalable_optimum_and_bounds(name, n_var):
    bound, x_star, f_per_dim = SCALABLE[name]
    kwargs = {"noise": False} if name == "F7" else {}
    problem = get_benchmark(name, n_var=n_var, **kwargs)
    assert problem.n_var == n_var
    np.testing.assert_allclose(problem.xl, -bound)
    np.testing.assert_allclose(problem.xu, bound)
    assert problem.f_opt == pytest.approx(f_per_dim * n_var, abs=1e-3 * n_var)
    assert value(problem, np.full(n_var, x_star)) == pytest.approx(
        f_per_dim * n_var, abs=1e-3 * n_var
    )
    assert value(problem, problem.x_opt) == pytest.approx(problem.f_opt, abs=1e-9)
    rng = np.random.default_rng(0)
    F = problem.evaluate(rng.uniform(-bound, bound, (64, n_var)))
    assert F.shape == (64, 1) and np.all(F[:, 0] >= problem.f_opt - 1e-9)


def test_hand_computed_values():
    x = np.array([[1.0, -2.0, 3.0]])
    assert get_benchmark("F2", n_var=3).evaluate(x)[0, 0] == 6.0 + 6.0
    assert get_benchmark("F3", n_var=3).evaluate(x)[0, 0] == 1.0 + 1.0 + 4.0
    assert get_benchmark("F4", n_var=3).evaluate(x)[0, 0] == 3.0
    assert get_benchmark("F6", n_var=3, step=True).evaluate(x)[0, 0] == 1.0 + 4.0 + 9.0
    noiseless = get_benchmark("F7", n_var=3, noise=False).evaluate(x)[0, 0]
    assert noiseless == 1.0 + 2.0 * 16.0 + 3.0 * 81.0


def test_f7_noise_is_seeded_and_in_unit_interval():
    x = np.zeros((50, 30))
    a = get_benchmark("F7", seed=3).evaluate(x)[:, 0]
    b = get_benchmark("F7", seed=3).evaluate(x)[:, 0]
    np.testing.assert_array_equal(a, b)
    assert np.all((a >= 0.0) & (a < 1.0)) and np.ptp(a) > 0.0


@pytest.mark.parametrize("name", list(LITERATURE))
def test_fixed_dimension_optimum_at_literature_location(name):
    f_lit, x_lit, tol = LITERATURE[name]
    problem = get_benchmark(name)
    assert problem.n_var == len(x_lit)
    assert value(problem, x_lit) == pytest.approx(f_lit, abs=tol)
    assert problem.pareto_front()[0, 0] == pytest.approx(f_lit, abs=tol)
    # a local polish from the literature point finds no lower value than f_opt
    bounds = list(zip(problem.xl, problem.xu, strict=True))
    res = minimize(
        lambda z: value(problem, z),
        np.asarray(x_lit, float),
        method="L-BFGS-B",
        bounds=bounds,
        options={"ftol": 1e-15, "gtol": 1e-12},
    )
    assert res.fun == pytest.approx(problem.f_opt, abs=1e-7)
    assert value(problem, problem.x_opt) == pytest.approx(problem.f_opt, abs=tol)


def test_branin_has_three_global_minima():
    problem = get_benchmark("F17")
    X = np.array([[-np.pi, 12.275], [np.pi, 2.275], [9.42478, 2.475]])
    np.testing.assert_allclose(problem.evaluate(X)[:, 0], 0.397887, atol=1e-6)


def test_random_points_never_beat_the_optimum():
    rng = np.random.default_rng(1)
    for name in LITERATURE:
        problem = get_benchmark(name)
        X = rng.uniform(problem.xl, problem.xu, (2000, problem.n_var))
        assert problem.evaluate(X)[:, 0].min() >= problem.f_opt - 1e-9, name
