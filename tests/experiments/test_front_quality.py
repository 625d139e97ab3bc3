"""Front-quality tables (moik.experiments.front_quality) on tiny synthetic cases."""

import pytest

from moik.experiments.front_quality import (
    front_quality_table,
    mean_ranks,
    mean_ranks_table,
    ranksum_verdicts,
)


def test_mean_ranks_by_hand():
    means = {"p1": {"a": 0.1, "b": 0.3, "c": 0.2},
             "p2": {"a": 0.5, "b": 0.4, "c": 0.5}}  # a and c tie for ranks 2 and 3
    ranks, mean = mean_ranks(means, higher_is_better=False)
    assert ranks == {"p1": {"a": 1.0, "b": 3.0, "c": 2.0}, "p2": {"a": 2.5, "b": 1.0, "c": 2.5}}
    assert mean == {"a": 1.75, "b": 2.0, "c": 2.25}
    ranks, mean = mean_ranks(means, higher_is_better=True)
    assert ranks["p1"] == {"a": 3.0, "b": 1.0, "c": 2.0}
    assert mean == {"a": 2.25, "b": 2.0, "c": 1.75}


def test_ranksum_verdicts_by_hand():
    # Exact two-sided Mann-Whitney p of fully separated samples: 2 / C(n+m, n).
    samples = {"ref": [5, 6, 7, 8, 9], "low": [0, 1, 2, 3, 4], "high": [10, 11, 12, 13, 14],
               "mixed": [4.5, 5.5, 6.5, 7.5, 8.5], "three": [1, 2, 3]}
    igd = ranksum_verdicts(samples, "ref", higher_is_better=False)
    assert igd["low"] == (pytest.approx(2 / 252), "+")
    assert igd["high"] == (pytest.approx(2 / 252), "-")
    assert igd["mixed"][1] == "="
    assert igd["three"] == (pytest.approx(2 / 56), "+")
    hv = ranksum_verdicts(samples, "ref", higher_is_better=True)
    assert hv["low"][1] == "-" and hv["high"][1] == "+"
    assert set(igd) == {"low", "high", "mixed", "three"}


def test_ranksum_verdict_is_equal_when_not_significant():
    p, verdict = ranksum_verdicts({"ref": [1, 2, 3], "x": [4, 5, 6]}, "ref",
                                  higher_is_better=False)["x"]
    assert p == pytest.approx(0.1) and verdict == "="  # 2 / C(6, 3) = 0.1 >= 0.05


class _FakeResults:
    """What the table functions read: config, meta targets, labels and records per label."""

    def __init__(self, data, targets):
        self.config = {"proposed": "ref"}
        self.meta = {"targets": [{"name": t} for t in targets]}
        self.labels = list(data)
        self.by_label = {
            lab: [{"target": ti, "run": r, "igd": igd, "hv": hv, "n_front": 10, "time": 1.0,
                   "hv_ref_point": [1.1, 1.1]}
                  for ti, runs in enumerate(per_target) for r, (igd, hv) in enumerate(runs)]
            for lab, per_target in data.items()}


def _case():
    # two problems, five runs each; "good" has lower IGD and higher HV than "ref" on p1,
    # is equal-ish on p2; "bad" is worse everywhere.
    ref = [[(0.5 + 0.01 * r, 0.5) for r in range(5)], [(0.3 + 0.01 * r, 0.6) for r in range(5)]]
    good = [[(0.1 + 0.01 * r, 0.8) for r in range(5)],
            [(0.305 + 0.01 * r, 0.6) for r in range(5)]]
    bad = [[(0.9 + 0.01 * r, 0.1) for r in range(5)], [(0.9 + 0.01 * r, 0.3) for r in range(5)]]
    return _FakeResults({"ref": ref, "good": good, "bad": bad}, ["p1", "p2"])


def test_front_quality_table_rows():
    tables = front_quality_table(_case())
    assert [t.title for t in tables] == ["p1: IGD and HV over the runs",
                                         "p2: IGD and HV over the runs"]
    rows = {r[0]: r for r in tables[0].rows}
    assert rows["good"][1] == "0.12" and rows["good"][3].startswith("+ (0.0079")
    assert rows["bad"][3].startswith("- (") and rows["ref"][3] == "-"
    assert rows["good"][7] == "160.0%" and rows["bad"][7] == "20.0%"
    assert {r[0]: r[3][0] for r in tables[1].rows} == {"ref": "-", "good": "=", "bad": "-"}


def test_mean_ranks_table_counts_and_order():
    (table,) = mean_ranks_table(_case())
    assert [r[0] for r in table.rows] == ["good", "ref", "bad"]
    rows = {r[0]: r for r in table.rows}
    assert rows["good"][1:] == ["1.50", "1.25", "1/1/0", "1", "2"]  # HV ties with ref on p2
    assert rows["ref"][1:] == ["1.50", "1.75", "-", "2", "1"]
    assert rows["bad"][1:4] == ["3.00", "3.00", "0/0/2"]


def test_mean_ranks_table_leaves_out_problems_without_every_algorithm():
    res = _case()
    res.by_label["bad"] = [r for r in res.by_label["bad"] if r["target"] == 0]
    (table,) = mean_ranks_table(res)
    assert table.header[-1] == "p1 IGD rank" and any("left out" in n and "p2" in n
                                                      for n in table.notes)


def test_headlines():
    from moik.experiments.front_quality import front_quality_lines, mean_ranks_lines

    assert front_quality_lines(_case()) == ["- lowest mean IGD per problem: p1 good 0.12, ref "
                                            "0.52; p2 ref 0.32"]
    lines = mean_ranks_lines(_case())
    assert lines[0] == "| algorithm | mean IGD rank | mean HV rank | IGD vs ref +/=/- |"
    assert lines[2] == "| good | 1.50 | 1.25 | 1/1/0 |" and lines[-1].startswith("- ranks of")


def test_a_run_without_a_feasible_member_ranks_last_and_prints_inf():
    # "none" found no feasible member in two of five runs: IGD stored as null
    res = _FakeResults({"ref": [[(0.5 + 0.01 * r, 0.5) for r in range(5)]],
                        "none": [[(None, 0.0)] * 2 + [(0.6, 0.4)] * 3]}, ["osy"])
    res.meta["targets"][0]["benchmark"] = "osy"
    for r in res.by_label["none"][:2]:
        r["n_infeasible"] = 3
    (table,) = front_quality_table(res)
    rows = {r[0]: r for r in table.rows}
    assert rows["none"][1] == "inf" and rows["none"][2] == "-"  # mean inf, std undefined
    assert rows["none"][3].startswith("- (")  # worse than ref: inf ranks above every IGD
    assert "infeasible reported" in table.header
    assert rows["none"][table.header.index("infeasible reported")] == "6"
    assert rows["ref"][table.header.index("infeasible reported")] == "0"


def test_ranksum_with_infinite_values_only_uses_their_order():
    with_inf = ranksum_verdicts({"ref": [1, 2, 3, 4, 5], "x": [6, 7, 8, float("inf"),
                                                              float("inf")]}, "ref",
                                higher_is_better=False)["x"]
    finite = ranksum_verdicts({"ref": [1, 2, 3, 4, 5], "x": [6, 7, 8, 100, 100]}, "ref",
                              higher_is_better=False)["x"]
    assert with_inf == finite
