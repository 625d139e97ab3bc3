"""A trial's algorithm records its best-so-far curve (moik.experiments.convergence)."""

from types import SimpleNamespace

from pymoo.optimize import minimize

from moik.experiments.convergence import BestF, algorithm_factory, convergence_curve
from moik.problems.benchmarks import get_benchmark


def _run(name: str, n_gen: int = 5):
    created: list = []
    factory = algorithm_factory(SimpleNamespace(algorithm=name, params={"pop_size": 8}), created)
    algorithm = factory()
    assert created == [algorithm]
    minimize(get_benchmark("F1", n_var=3), algorithm, ("n_gen", n_gen), seed=1,
             copy_algorithm=False)
    return algorithm


def test_pymoo_single_objective_algorithms_get_the_best_f_callback():
    algorithm = _run("ga")
    assert isinstance(algorithm.callback, BestF)
    curve = convergence_curve(algorithm)
    assert curve.shape == (5,) and (curve[1:] <= curve[:-1]).all()


def test_moik_algorithms_record_their_own_curve():
    algorithm = _run("eosma")
    assert not isinstance(algorithm.callback, BestF)
    assert convergence_curve(algorithm).shape == (5,)
