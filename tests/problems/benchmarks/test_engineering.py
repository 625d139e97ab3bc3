"""Spring and pressure vessel design (I-BES Section 5.3) as constrained problems.

Best known designs: spring 0.012665 at (0.051689, 0.356718, 11.288966)
(Coello 2000, Table; He & Wang 2007); pressure vessel with the I-BES bounds
(L <= 200, continuous thicknesses) 5885.3328 at (0.7782, 0.3846, 40.3196, 200)
(Coelho 2010, Expert Syst. Appl. 37); original discrete version 6059.7143 at
(0.8125, 0.4375, 42.0984, 176.6366) (Kannan & Kramer 1994 as improved by
Coello 2000 / He & Wang 2007). I-BES Table 16: 5.8862e3 at
(0.7782, 0.3847, 40.3223, 200).
"""

from __future__ import annotations

import numpy as np
import pytest

from moik.problems.benchmarks import get_benchmark


def evaluate(problem, x):
    F, G = problem.evaluate(np.atleast_2d(np.asarray(x, float)), return_values_of=["F", "G"])
    return F[0, 0], G[0]


def test_spring_best_known_design_is_feasible():
    problem = get_benchmark("spring")
    assert (problem.n_var, problem.n_ieq_constr) == (3, 4)
    f, g = evaluate(problem, [0.051689, 0.356718, 11.288966])  # literature, rounded
    assert f == pytest.approx(0.012665, abs=1e-6)
    assert np.max(g) < 1e-5  # rounding to 6 digits leaves g1 ~ 1e-6
    f, g = evaluate(problem, problem.x_opt)
    assert f == pytest.approx(0.0126652, abs=1e-7)
    assert np.max(g) <= 1e-9  # 12-digit design: active constraints at +-2e-11


def test_spring_infeasible_designs_have_positive_violation():
    problem = get_benchmark("spring")
    F, G = problem.evaluate(
        np.array([[0.05, 0.25, 2.0], [0.25, 0.25, 15.0]]), return_values_of=["F", "G"]
    )
    assert np.all(np.max(G, axis=1) > 0.0)
    # I-BES Table 14's reported design d = D: singular g2, infeasible, weight 0.2656
    assert F[1, 0] == pytest.approx(17 * 0.25**3)
    assert G[1, 1] == np.inf


def test_pressure_vessel_relaxed_optimum_applies_to_paper_bounds():
    problem = get_benchmark("pressure_vessel")
    assert (problem.n_var, problem.n_ieq_constr) == (4, 4)
    np.testing.assert_allclose(problem.xu, [99.0, 99.0, 200.0, 200.0])
    assert problem.f_opt == pytest.approx(5885.3328, abs=1e-3)
    f, g = evaluate(problem, problem.x_opt)
    assert f == pytest.approx(5885.3328, abs=1e-3)
    assert np.max(g) <= 1e-6  # three constraints active at the optimum
    f, g = evaluate(problem, [0.7782, 0.3847, 40.3223, 200.0])  # I-BES Table 16
    assert f == pytest.approx(5886.2, abs=0.1)
    assert g[0] > 0.0  # its 4-digit rounding leaves g1 = +2e-5: slightly infeasible


def test_pressure_vessel_discrete_version():
    problem = get_benchmark("pressure_vessel", discrete=True)
    f, g = evaluate(problem, [0.8125, 0.4375, 42.098446, 176.636596])
    assert f == pytest.approx(6059.7143, abs=1e-3)
    assert np.max(g) < 1e-6
    # thicknesses are rounded up to the 0.0625 grid before evaluation
    f_off, _ = evaluate(problem, [0.80, 0.43, 42.098446, 176.636596])
    assert f_off == pytest.approx(f)


def test_pressure_vessel_infeasible_design():
    problem = get_benchmark("pressure_vessel")
    f, g = evaluate(problem, [0.5, 0.25, 40.0, 100.0])
    assert g[0] > 0 and g[1] > 0 and g[2] > 0
    assert f < problem.f_opt  # cheaper than the optimum, but infeasible


def test_pymoo_reports_constraint_violation():
    from pymoo.core.evaluator import Evaluator
    from pymoo.core.population import Population

    problem = get_benchmark("pressure_vessel")
    pop = Population.new(X=np.vstack([problem.x_opt, [0.5, 0.25, 40.0, 100.0]]))
    Evaluator().eval(problem, pop)
    cv = pop.get("CV")[:, 0]
    assert cv[0] <= 1e-6 and cv[1] > 1.0
