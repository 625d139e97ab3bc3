"""Multi-objective algorithms on constrained problems: BNH, OSY, SRN, TNK.

Not a paper's table: the constraint handling of every multi-objective
algorithm of the registry (constraint-domination in archives, leaders and
memories; pymoo's algorithms: their own constraint-domination), measured on
pymoo's constrained two-objective problems with analytic fronts (nothing is
downloaded; OSY's front from Deb's five segments, TNK's from its constraint
boundary: :mod:`moik.experiments.kinds.moo_fronts`). Every algorithm with its
defaults, population 100, 25,000 evaluations per run, 10 runs; the returned
members are re-evaluated: the tables count the infeasible members reported
(0 expected) and score the feasible ones, IGD against the analytic front and
HV with the reference point nadir + 0.1 x |nadir| per objective (OSY's f1 and
SRN's f2 are negative). ``random-search`` samples the same 25,000 points
uniformly and keeps the feasible non-dominated ones. Wilcoxon rank-sum test of
each algorithm against NSGA-II (``proposed``) per problem, mean ranks.
"""

_MO = ["moeosma", "mo-m-pso", "mssa", "moalo", "moda", "momvo", "mogwo", "mosma", "mopso",
       "mompa", "mo-pso", "mo-jaya", "mo-csa", "nsga2", "moead", "sms-emoa", "mopso-cd"]

EXPERIMENT = {
    "name": "moo-constrained",
    "title": "Multi-objective algorithms on the constrained BNH, OSY, SRN, TNK (IGD, HV vs NSGA-II)",
    "source": "moik: BNH (Binh & Korn 1997), OSY (Osyczka & Kundu 1995), SRN (Srinivas & Deb "
              "1994), TNK (Tanaka et al. 1995) problems of pymoo, analytic fronts",
    "problem": {"kind": "moo-benchmark", "evaluations": 25_000,
                "names": ["bnh", "osy", "srn", "tnk"]},
    "algorithms": [{"name": n} for n in _MO] + [{"name": "random-search"}],
    "pop_size": 100,
    "iterations": 249,  # unused: problem.evaluations bound the runs
    "runs": 10,
    "seed": 3000,
    "analyses": ["front-quality", "hv-shares", "versus-random", "mean-ranks"],
    "proposed": "nsga2",
    "quick": {"problem": {"evaluations": 200, "names": ["osy", "tnk"]},
              "pop_size": 20, "runs": 2},
}
