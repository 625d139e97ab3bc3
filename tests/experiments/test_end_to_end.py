"""Quick-size runs of the papers' experiments, end to end, and their report."""

import json

from moik.cli import main
from moik.experiments.store import ResultStore


def test_quick_runs_and_report(tmp_path, capsys):
    out = tmp_path / "results"
    for name in ("mpso-table5", "eosma-table8"):
        assert main(["experiment", "run", name, "--quick", "--workers", "1", "--no-progress",
                     "--out", str(out / name)]) == 0
    out_text = capsys.readouterr().out
    assert "mpso-table5: ran " in out_text and "(0 failed), 0 already finished" in out_text
    t8 = ResultStore.open(out / "eosma-table8")
    recs = t8.records()
    assert all(r["status"] == "ok" and "hv" in r for r in recs)
    assert t8.load_arrays(recs[0]["trial"])["front_F"].shape[1] == 2
    assert main(["report", str(out)]) == 0
    report = (out / "report.md").read_text()
    assert "## eosma-table8" in report and "## mpso-table5" in report
    assert "#### Hypervolume at P1" in report and "[2.088567, 2.466816]" in report
    assert "| moeosma | paper | 5.07631 | 0.0201 | 1.40 (1) |" in report
    # the uncovered part of the P1 box [0, ref]: 2.088567 x 2.466816 - 5.07631 (paper row)
    assert "| 0.0758 | 1.47 % |" in report and "box [0, ref] (5.1521)" in report
    # the reference-front analysis (moik.fronts): the shipped P1 front, its HV, IGD+ per run
    assert "#### Against the reference front at P1" in report
    assert "reference front: 75 points, HV 5.09615" in report
    assert "#### Against the reference front at P2" in report and "HV 4.28017" in report
    assert "| m-pso | pso | paper | 0 | 465 |" in report
    assert "![Pareto fronts at P1 (first run)](eosma-table8/figures/front-0.png)" in report
    assert (out / "eosma-table8" / "figures" / "front-0.png").exists()
    meta = json.loads((out / "mpso-table5" / "meta.json").read_text())
    assert meta["quick"] is True and meta["algorithms"][:2] == ["m-pso", "pso"]


def test_joint_motion_experiment_draws_the_joint_history(tmp_path):
    """EOSMA Fig. 19a: the best candidate's joint angles per iteration."""
    out = tmp_path / "results"
    assert main(["experiment", "run", "eosma-table9", "--quick", "--workers", "1",
                 "--no-progress", "--out", str(out / "eosma-table9")]) == 0
    store = ResultStore.open(out / "eosma-table9")
    recs = store.records()
    history = store.load_arrays(recs[0]["trial"])["best_x_history"]
    assert history.shape == (21, 7)  # quick size: the initial population + 20 iterations, 7 joints
    assert history[-1].tolist() == recs[0]["best_x"]
    assert main(["report", str(out)]) == 0
    assert (out / "eosma-table9" / "figures" / "joint-history.png").exists()
    report = (out / "report.md").read_text()
    assert "Best candidate joint angles of eosma per iteration" in report
