"""Multi-objective benchmark suite: every registered MO algorithm on ZDT and DTLZ problems.

Not a paper's table: the comparison behind the multi-objective part of
docs/algorithms.md, on the runner (``studies/moo_quality.py`` measures the
same suite outside it). Problems with analytic Pareto fronts only (nothing is
downloaded): ZDT1/2/3 with 30 variables, ZDT4 and ZDT6 with 10 (their standard
sizes, pymoo's defaults), DTLZ1 (7 variables) and DTLZ2 (12) with three
objectives. Every multi-objective algorithm of the registry with its defaults,
and two documented options (MOEOSMA's ``diversity="nsga2-gaussian"``, MOALO's
``antlion="first"``, MALO.m's rule), population 100, 25,000 evaluations per run (``problem.evaluations``; the
iteration count is then unused), 10 runs; ``random-search`` samples the same
25,000 points uniformly and keeps the non-dominated ones. IGD against the
analytic front (ZDT 1,000 points, DTLZ 496 Das-Dennis points) and HV with the
reference point 1.1 x the front's nadir per objective; Wilcoxon rank-sum test of
each algorithm against NSGA-II (``proposed``) per problem, mean ranks over the
problems. Beside them three bi-objective IK problems of ``moik.problems.available()``
(EOSMA P1, MO-m-PSO's Eq. 16 pose, an unreachable Sawyer pose), measured against their
reference fronts (:mod:`moik.fronts`, local solutions to 1e-9 shipped with moik).
"""

_MO = ["moeosma", "mo-m-pso", "mssa", "moalo", "moda", "momvo", "mogwo", "mosma", "mopso",
       "mompa", "mo-pso", "mo-jaya", "mo-csa", "nsga2", "moead", "sms-emoa", "mopso-cd"]

EXPERIMENT = {
    "name": "moo-suite",
    "title": "Multi-objective algorithms on ZDT1-4/6 and DTLZ1-2 (IGD, HV vs NSGA-II)",
    "source": "moik: ZDT (Zitzler, Deb & Thiele 2000) and DTLZ (Deb et al. 2005) problems "
              "of pymoo, analytic fronts",
    "problem": {"kind": "moo-benchmark", "evaluations": 25_000, "names": [
        {"name": "zdt1", "params": {"n_var": 30}},
        {"name": "zdt2", "params": {"n_var": 30}},
        {"name": "zdt3", "params": {"n_var": 30}},
        {"name": "zdt4", "params": {"n_var": 10}},
        {"name": "zdt6", "params": {"n_var": 10}},
        {"name": "dtlz1", "params": {"n_var": 7, "n_obj": 3}},
        {"name": "dtlz2", "params": {"n_var": 12, "n_obj": 3}},
        "eosma-p1", "mpso-eq16", "sawyer7-unreachable",  # IK, reference fronts (moik.fronts)
    ]},
    "algorithms": [{"name": n} for n in _MO] + [
        {"name": "moeosma", "label": "moeosma-nsga2-gaussian",
         "params": {"diversity": "nsga2-gaussian"}},
        {"name": "moalo", "label": "moalo-first", "params": {"antlion": "first"}},
        {"name": "random-search"}],
    "pop_size": 100,
    "iterations": 249,  # unused: problem.evaluations bound the runs
    "runs": 10,
    "seed": 2000,
    "analyses": ["front-quality", "hv-shares", "versus-random", "mean-ranks"],
    "proposed": "nsga2",
    "quick": {"problem": {"evaluations": 200, "names": [
        {"name": "zdt1", "params": {"n_var": 5}},
        {"name": "dtlz2", "params": {"n_var": 5, "n_obj": 3}}]},
        "pop_size": 20, "runs": 2},
}
