"""Mirjalili's multi-objective algorithms at their papers' setting: ZDT1-3, 100 iterations.

The MOGWO (Mirjalili et al. 2016), MOALO (Mirjalili, Jangir & Saremi 2017), MSSA
(Mirjalili et al. 2017), MODA (Mirjalili 2016) and MOMVO (Mirjalili et al. 2017)
papers test on ZDT1-3 with 100 iterations and population (archive) 100; their
papers use 30 variables, the authors' public MATLAB codes 5. Both sizes are run
here (``zdtK-30`` and ``zdtK-5``), 10 runs, with NSGA-II and ``random-search``
(the NSGA-II budget, 100 x 101 evaluations, sampled uniformly) beside them;
MSSA with N = 200 and archive 100 as MSSA.m. The papers' own IGD tables are not in this
repository's papers, so the report prints moik's numbers only. Budget: 100
update iterations after initialization (``iterations``); each algorithm
evaluates what its method does per iteration. Metrics as in ``moo-suite`` (IGD against the analytic front, HV with
1.1 x the front's nadir).
"""

_ZDT = [{"name": f"zdt{k}", "label": f"zdt{k}-{n}", "params": {"n_var": n}}
        for n in (30, 5) for k in (1, 2, 3)]

EXPERIMENT = {
    "name": "moo-reference",
    "title": "MOGWO, MOALO, MSSA, MODA, MOMVO at their papers' setting (ZDT1-3, 100 iterations)",
    "source": "Mirjalili et al.: MOGWO 2016, MOALO 2017, MSSA 2017, MODA 2016, MOMVO 2017 "
              "(ZDT1-3, 100 iterations, N = 100)",
    "problem": {"kind": "moo-benchmark", "names": _ZDT},
    "algorithms": [
        {"name": "mogwo"},
        {"name": "moalo"},
        {"name": "mssa", "params": {"pop_size": 200, "archive_size": 100}},
        {"name": "moda"},
        {"name": "momvo"},
        {"name": "nsga2"},
        {"name": "random-search"},
    ],
    "pop_size": 100,
    "iterations": 100,
    "runs": 10,
    "seed": 2016,
    "analyses": ["front-quality", "mean-ranks"],
    "proposed": "nsga2",
    "quick": {"problem": {"names": [{"name": "zdt1", "label": "zdt1-5", "params": {"n_var": 5}}]},
              "pop_size": 10, "iterations": 3, "runs": 2,
              "algorithms": [{"name": "mogwo"}, {"name": "mssa"}, {"name": "nsga2"},
                             {"name": "random-search"}]},
}
