"""Compact front-quality tables (moik.experiments.front_shares) on a tiny synthetic case."""

from moik.experiments.front_shares import hv_shares_table, versus_random_table


class _FakeResults:
    """What the table functions read: config, meta targets, labels and records per label."""

    def __init__(self, data, targets):
        self.config = {"proposed": "ref"}
        self.meta = {"targets": [{"name": t} for t in targets]}
        self.labels = list(data)
        self.by_label = {
            lab: [{"target": ti, "run": r, "igd": igd, "hv": hv, "n_front": 10, "time": 1.0}
                  for ti, runs in enumerate(per_target) for r, (igd, hv) in enumerate(runs)]
            for lab, per_target in data.items()}


def _case():
    ref = [[(0.5 + 0.01 * r, 0.5) for r in range(5)], [(0.3 + 0.01 * r, 0.6) for r in range(5)]]
    good = [[(0.1 + 0.01 * r, 0.8) for r in range(5)],
            [(0.305 + 0.01 * r, 0.6) for r in range(5)]]
    bad = [[(0.9 + 0.01 * r, 0.1) for r in range(5)], [(0.9 + 0.01 * r, 0.3) for r in range(5)]]
    return _FakeResults({"ref": ref, "good": good, "bad": bad}, ["p1", "p2"])


def test_versus_random_and_hv_shares_tables():
    res = _case()
    res.labels.append("random-search")
    res.by_label["random-search"] = [
        {"target": ti, "run": r, "igd": v, "hv": 0.2, "n_front": 5, "time": 0.1}
        for ti, v in ((0, 0.6), (1, 0.5)) for r in range(5)]
    (table,) = versus_random_table(res)
    rows = {r[0]: r for r in table.rows}
    assert "random-search" not in rows
    assert rows["good"][1:] == ["0.2", "0.65"]  # 0.12 / 0.6, 0.325 / 0.5
    assert rows["bad"][1:] == ["1.53 (not below)", "1.84 (not below)"]
    assert table.notes[0].startswith("2 cell(s) not below 1")
    (shares,) = hv_shares_table(res)
    rows = {r[0]: r for r in shares.rows}
    assert rows["ref"][1:] == ["100.0%", "100.0%"] and rows["good"][1:] == ["160.0%", "100.0%"]
    assert versus_random_table(_case()) == []
