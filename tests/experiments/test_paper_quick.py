"""Quick sizes of the I-BES and MChOA experiments, run end to end with their report."""

import pytest

from moik.cli import main
from moik.experiments.store import ResultStore

NAMES = ["ibes-table8", "ibes-table9", "ibes-cec2017", "ibes-engineering", "mchoa-table3"]


@pytest.fixture(scope="module")
def quick_results(tmp_path_factory):
    pytest.importorskip("minionpy")
    out = tmp_path_factory.mktemp("paper-quick")
    for name in NAMES:
        assert main(["experiment", "run", name, "--quick", "--workers", "1", "--no-progress",
                     "--out", str(out / name)]) == 0
    assert main(["report", str(out), "--no-figures"]) == 0
    return out


def test_every_quick_trial_finishes(quick_results):
    for name in NAMES:
        recs = ResultStore.open(quick_results / name).records()
        assert recs and all(r["status"] == "ok" for r in recs), name


def test_report_puts_paper_numbers_beside(quick_results):
    report = (quick_results / "report.md").read_text()
    for name in NAMES:
        assert f"## {name}:" in report
    assert "| planar2 | pso | paper | 5.56e-10 | 8.43e-08 | 1.84e-08 | 1.24e-08 |" in report
    assert "| cec2017_F3 | paper | 3.02e-11 + |" in report
    assert "| F1 | mchoa | paper | 0 | 1.45e-16 |" in report
    assert "| F24 | mchoa | paper | 0.5365 | 5.915 |" in report  # beside moik's own F24
    assert "paper rows: MChOA paper, Table 3" in report
    assert "| T1 | q1 | (0.00000, -1.07480, 3.12010) |" in report
    assert "feasible runs" in report


def test_table9_solves_the_locked_puma(quick_results):
    recs = ResultStore.open(quick_results / "ibes-table9").records()
    assert all(len(r["best_x"]) == 3 for r in recs)  # joints 4-6 locked
