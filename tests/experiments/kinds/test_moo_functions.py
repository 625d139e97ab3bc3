"""Multi-objective benchmark experiments (moik.experiments.kinds.moo_functions)."""

import copy

import numpy as np
import pytest
from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting

from moik.exceptions import ConfigError
from moik.experiments.config import ExperimentConfig
from moik.experiments.kinds import moo_functions as mf
from moik.experiments.trials import build_trials, run_trial

MOO = {
    "name": "moo-test",
    "title": "tiny multi-objective benchmark experiment",
    "source": "test",
    "problem": {"kind": "moo-benchmark", "evaluations": 120, "names": [
        {"name": "zdt1", "params": {"n_var": 4}},
        {"name": "dtlz2", "label": "dtlz2-3", "params": {"n_var": 5, "n_obj": 3}}]},
    "algorithms": [{"name": "nsga2"}, {"name": "mogwo"}, {"name": "random-search"}],
    "pop_size": 12,
    "iterations": 4,
    "runs": 2,
    "seed": 4,
    "analyses": ["front-quality", "mean-ranks"],
    "proposed": "nsga2",
}


def _moo(**changes):
    d = copy.deepcopy(MOO)
    d.update(changes)
    return d


def test_config_builds_targets_and_accepts_the_random_baseline():
    cfg = ExperimentConfig.from_dict(MOO)
    assert [t.name for t in cfg.targets] == ["zdt1", "dtlz2-3"]
    assert cfg.targets[1].as_dict() == {"name": "dtlz2-3", "benchmark": "dtlz2",
                                        "params": {"n_var": 5, "n_obj": 3}}
    assert cfg.labels == ["nsga2", "mogwo", "random-search"]
    assert all(a.multi_objective for a in cfg.algorithms)
    assert cfg["problem"]["evaluations"] == 120


@pytest.mark.parametrize("change, match", [
    ({"robot": "planar2"}, "takes no 'robot'"),
    ({"problem": {"kind": "moo-benchmark", "names": ["dtlz7"]}}, "analytic front"),
    ({"problem": {"kind": "moo-benchmark", "names": ["zdt1"], "evaluations": 0}},
     "evaluations must be an integer >= 1"),
    ({"problem": {"kind": "moo-benchmark", "names": ["zdt1"], "evaluations": 100.0}},
     "evaluations must be an integer"),
    ({"problem": {"kind": "moo-benchmark", "names": [{"name": "zdt1",
                                                       "params": {"n_obj": 3}}]}},
     "unknown key.*n_obj"),
    ({"problem": {"kind": "moo-benchmark", "names": [{"name": "dtlz2",
                                                       "params": {"n_obj": 4}}]}},
     "n_obj must be an integer in \\[2, 3\\]"),
    ({"problem": {"kind": "moo-benchmark", "names": [{"name": "zdt1",
                                                       "params": {"n_var": True}}]}},
     "n_var must be an integer"),
    ({"problem": {"kind": "moo-benchmark", "names": ["zdt1", "zdt1"]}}, "labels must be unique"),
    ({"problem": {"kind": "moo-benchmark", "names": []}}, "non-empty list"),
    ({"algorithms": [{"name": "random-search", "params": {"archive_size": 3}}]},
     "unknown key.*archive_size"),
    ({"algorithms": [{"name": "ga"}]}, "'ga' is single-objective"),
    ({"analyses": ["front-quality"], "proposed": None}, "need 'proposed'"),
])
def test_config_errors(change, match):
    data = _moo(**change)
    if data.get("proposed") is None:
        data.pop("proposed")
    with pytest.raises(ConfigError, match=match):
        ExperimentConfig.from_dict(data)


def test_random_search_is_not_a_baseline_of_the_other_kinds(tiny):
    tiny["algorithms"] = [{"name": "random-search"}]
    with pytest.raises(ConfigError, match="unknown algorithm 'random-search'"):
        ExperimentConfig.from_dict(tiny)


def test_random_search_samples_the_budget_and_keeps_the_non_dominated():
    problem = mf.build_problem("zdt1", {"n_var": 3})
    X, F = mf.random_search(problem, 500, np.random.default_rng(7))
    assert np.all((X - problem.xl >= 0) & (problem.xu - X >= 0))
    assert len(NonDominatedSorting().do(F, only_non_dominated_front=True)) == len(F)
    np.testing.assert_array_equal(F, problem.evaluate(X, return_values_of=["F"]))
    X2, _ = mf.random_search(problem, 500, np.random.default_rng(7))
    np.testing.assert_array_equal(X, X2)
    rng = np.random.default_rng(7)
    sample = problem.xl + rng.random((500, 3)) * (problem.xu - problem.xl)
    assert all(any(np.array_equal(x, s) for s in sample) for x in X)


def test_trials_record_igd_hv_and_the_budget():
    cfg = ExperimentConfig.from_dict(MOO)
    specs = build_trials(cfg)
    assert len(specs) == 3 * 2 * 2
    by_id = {s.trial_id: s for s in specs}
    rec, arrays = run_trial(by_id["random-search/1/0"])
    assert rec["status"] == "ok", rec.get("error")
    assert rec["n_eval"] == 120 and rec["n_front"] == len(arrays["front_F"])
    assert rec["hv_ref_point"] == pytest.approx([1.1 * 1.0] * 3)  # DTLZ2 nadir (1, 1, 1)
    assert rec["igd"] > 0 and rec["hv"] >= 0
    again, _ = run_trial(by_id["random-search/1/0"])
    assert again["igd"] == rec["igd"]
    rec, arrays = run_trial(by_id["nsga2/0/1"])
    assert rec["status"] == "ok", rec.get("error")
    assert 120 <= rec["n_eval"] < 120 + 12 and arrays["front_F"].shape[1] == 2
    igd, hv = mf.front_scores(arrays["front_F"], mf.analytic_front(
        mf.build_problem("zdt1", {"n_var": 4}), "zdt1"))
    assert (igd, hv) == (rec["igd"], rec["hv"])


def test_without_evaluations_the_generations_bound_the_run():
    data = _moo()
    del data["problem"]["evaluations"]
    cfg = ExperimentConfig.from_dict(data)
    by_id = {s.trial_id: s for s in build_trials(cfg)}
    rec, _ = run_trial(by_id["nsga2/0/0"])
    assert rec["n_eval"] == 12 + 4 * 12  # the initial population and 4 iterations
    rec, _ = run_trial(by_id["random-search/0/0"])
    assert rec["n_eval"] == 12 + 4 * 12  # the initial population and 4 iterations


def test_constrained_problems_take_no_params():
    with pytest.raises(ConfigError, match=r"params"):
        ExperimentConfig.from_dict(_moo(problem={"kind": "moo-benchmark", "names": [
            {"name": "osy", "params": {"n_var": 4}}]}))


def test_constrained_trials_count_the_infeasible_members_and_score_the_feasible():
    cfg = ExperimentConfig.from_dict(_moo(problem={"kind": "moo-benchmark", "evaluations": 300,
                                                   "names": ["osy", "tnk"]}))
    by_id = {s.trial_id: s for s in build_trials(cfg)}
    problem = mf.build_problem("osy", {})
    front = mf.analytic_front(problem, "osy")
    for trial in ("nsga2/0/0", "random-search/0/1", "mogwo/0/0"):
        rec, arrays = run_trial(by_id[trial])
        assert rec["status"] == "ok", rec.get("error")
        X, F = arrays["front_X"], arrays["front_F"]
        ok = mf.violation(problem, X) <= 0.0
        assert rec["n_front"] == ok.sum() and rec["n_infeasible"] == (~ok).sum() == 0
        igd, hv = mf.front_scores(F[ok], front)
        assert (igd, hv) == (rec["igd"], rec["hv"])
        np.testing.assert_allclose(rec["hv_ref_point"], [-42.0 * 0.9, 76.0 * 1.1])


def test_violation_and_scores_without_feasible_members():
    problem = mf.build_problem("tnk", {})
    X = np.array([[0.05, 0.05], [1.1, 1.1], [0.9, 0.9]])  # g1 violated; g2 violated; feasible
    cv = mf.violation(problem, X)
    assert cv[0] > 0 and cv[1] > 0 and cv[2] == 0.0
    front = mf.analytic_front(problem, "tnk")
    assert mf.front_scores(np.zeros((0, 2)), front) == (float("inf"), 0.0)
    assert np.all(mf.violation(mf.build_problem("zdt1", {}), np.full((2, 30), 0.5)) == 0.0)


def test_random_search_keeps_only_feasible_points_when_some_are():
    problem = mf.build_problem("tnk", {})
    X, F = mf.random_search(problem, 400, np.random.default_rng(3))
    assert len(X) and np.all(mf.violation(problem, X) == 0.0)
    np.testing.assert_array_equal(F, X)  # TNK: f = x


def test_ik_problems_run_against_their_reference_fronts():
    cfg = ExperimentConfig.from_dict(_moo(problem={"kind": "moo-benchmark", "evaluations": 120,
                                                   "names": ["eosma-p1"]}))
    rec, arrays = run_trial({s.trial_id: s for s in build_trials(cfg)}["nsga2/0/0"])
    assert rec["status"] == "ok", rec.get("error")
    front = mf.analytic_front(mf.build_problem("eosma-p1", {}), "eosma-p1")
    assert front.shape == (75, 2)  # the shipped reference front (moik.fronts)
    igd, hv = mf.front_scores(arrays["front_F"], front)
    assert (igd, hv) == (rec["igd"], rec["hv"]) and igd > 0
    with pytest.raises(ConfigError, match=r"params"):
        ExperimentConfig.from_dict(_moo(problem={"kind": "moo-benchmark", "names": [
            {"name": "eosma-p1", "params": {"n_var": 4}}]}))
