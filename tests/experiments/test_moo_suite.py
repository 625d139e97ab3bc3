"""The moo-suite(-10k), moo-constrained and moo-reference configs: what they list, quick runs."""

from pathlib import Path

import pytest

from moik.algorithms import available
from moik.cli import main
from moik.experiments.config import load_config
from moik.experiments.store import ResultStore

ROOT = Path(__file__).resolve().parents[2]
SUITE = ROOT / "experiments" / "moo_suite.toml"
REFERENCE = ROOT / "experiments" / "moo_reference.toml"
SUITE_10K = ROOT / "experiments" / "moo_suite_10k.toml"
CONSTRAINED = ROOT / "experiments" / "moo_constrained.toml"
CONSTRAINED_MW = ROOT / "experiments" / "moo_constrained_mw.toml"
OPTIONS = {"moeosma-nsga2-gaussian": ("moeosma", {"diversity": "nsga2-gaussian"}),
           "moalo-first": ("moalo", {"antlion": "first"})}


IK = ["eosma-p1", "mpso-eq16", "sawyer7-unreachable"]  # moik.problems, reference fronts
# pymoo's MOEA/D evaluates one offspring per call (hours at these sizes: the configs'
# comments); studies/moead_vs_pymoo.py compares it with moik's moead instead
LEFT_OUT = {"moead-pymoo"}


def _every_multi_objective() -> list[str]:
    return [name for name in available("multi-objective") if name not in LEFT_OUT]


@pytest.mark.parametrize(("path", "evaluations", "runs", "ik"), [(SUITE, 25_000, 10, IK),
                                                                (SUITE_10K, 10_000, 5, IK)])
def test_the_suite_lists_every_multi_objective_algorithm_and_the_random_baseline(
        path, evaluations, runs, ik):
    cfg = load_config(path)
    assert sorted(cfg.labels) == sorted([*_every_multi_objective(), *OPTIONS, "random-search"])
    assert {a.label: (a.name, {k: v for k, v in a.params.items() if k != "pop_size"})
            for a in cfg.algorithms if a.label in OPTIONS} == OPTIONS
    assert cfg["problem"]["evaluations"] == evaluations and cfg["runs"] == runs
    assert cfg["pop_size"] == 100 and cfg["proposed"] == "nsga2"
    assert [t.name for t in cfg.targets] == ["zdt1", "zdt2", "zdt3", "zdt4", "zdt6", "dtlz1",
                                              "dtlz2", *ik]
    n_var = {t.name: t.params["n_var"] for t in cfg.targets if t.name not in ik}
    assert n_var == {"zdt1": 30, "zdt2": 30, "zdt3": 30, "zdt4": 10, "zdt6": 10, "dtlz1": 7,
                     "dtlz2": 12}
    assert {t.params.get("n_obj") for t in cfg.targets if t.name.startswith("dtlz")} == {3}


def test_the_constrained_suite_lists_every_algorithm_on_bnh_osy_srn_tnk():
    cfg = load_config(CONSTRAINED)
    assert sorted(cfg.labels) == sorted([*_every_multi_objective(), "random-search"])
    assert [t.name for t in cfg.targets] == ["bnh", "osy", "srn", "tnk"]
    assert cfg["problem"]["evaluations"] == 25_000 and cfg["runs"] == 10


def test_the_mw_suite_lists_every_algorithm_on_mw1_mw2_mw3():
    cfg = load_config(CONSTRAINED_MW)  # moik's algorithms and the reference, NSGA-II
    assert sorted(cfg.labels) == sorted(n for n in _every_multi_objective() if n != "sms-emoa")
    assert [t.name for t in cfg.targets] == ["mw1", "mw2", "mw3"]
    assert cfg["problem"]["evaluations"] == 50_000 and cfg["runs"] == 2
    assert cfg["pop_size"] == 100 and cfg["proposed"] == "nsga2"


def test_the_reference_setting_is_zdt1_3_at_100_iterations():
    cfg = load_config(REFERENCE)
    assert [t.name for t in cfg.targets] == ["zdt1-30", "zdt2-30", "zdt3-30", "zdt1-5",
                                              "zdt2-5", "zdt3-5"]
    assert "evaluations" not in cfg["problem"] and cfg["iterations"] == 100
    assert {a.label: a.params["pop_size"] for a in cfg.algorithms}["mssa"] == 200


@pytest.fixture(scope="module")
def quick_results(tmp_path_factory):
    out = tmp_path_factory.mktemp("moo-quick")
    for path in (SUITE, REFERENCE, CONSTRAINED, CONSTRAINED_MW):
        name = path.stem.replace("_", "-")
        assert main(["experiment", "run", "--config", str(path), "--quick", "--workers", "1",
                     "--no-progress", "--out", str(out / name)]) == 0
    assert main(["report", str(out), "--no-figures"]) == 0
    return out


def test_every_quick_trial_finishes_with_its_metrics(quick_results):
    for name in ("moo-suite", "moo-reference", "moo-constrained", "moo-constrained-mw"):
        recs = ResultStore.open(quick_results / name).records()
        assert recs and all(r["status"] == "ok" for r in recs), name
        assert all((r["igd"] is None or r["igd"] >= 0) and r["hv"] >= 0 for r in recs)
        assert all(r["n_infeasible"] == 0 for r in recs), name  # no infeasible member reported
    recs = ResultStore.open(quick_results / "moo-suite").records()
    assert len(recs) == len(load_config(SUITE).labels) * 2 * 2  # two quick targets, two runs
    assert {r["n_eval"] for r in recs if r["algorithm"] == "random-search"} == {200}


def test_the_report_has_the_tables(quick_results):
    report = (quick_results / "report.md").read_text()
    assert "## moo-suite:" in report and "## moo-reference:" in report
    assert "#### zdt1: IGD and HV over the runs" in report
    assert "#### dtlz2: IGD and HV over the runs" in report
    assert "#### Mean ranks over the problems (1 = best)" in report
    assert "| algorithm | IGD mean | IGD std | IGD vs nsga2 |" in report
    assert "200 evaluations per run" in report
    assert "HV reference point [1.1, 1.1, 1.1]" in report
    assert "## moo-constrained:" in report and "#### osy: IGD and HV over the runs" in report
    assert "HV reference point [-37.8, 83.6]" in report and "infeasible reported" in report
    assert "## moo-constrained-mw:" in report and "#### mw1: IGD and HV over the runs" in report
    assert "| feasible runs | infeasible reported |" in report
    assert "#### Mean HV as a share of nsga2's" in report
    assert "#### Mean IGD over random-search's (below 1: better than uniform sampling)" in report


def test_the_docs_pages_and_blocks_are_generated(quick_results, tmp_path):
    docs = tmp_path / "docs"
    docs.mkdir()
    (docs / "reproducing.md").write_text("<!-- generated: moo-suite summary -->\n"
                                         "<!-- end generated -->\n")
    assert main(["report", str(quick_results), "--docs", str(docs), "--no-figures"]) == 0
    page = (docs / "results" / "moo-suite-quick.md").read_text()
    assert "#### Mean ranks over the problems (1 = best)" in page
    block = (docs / "reproducing.md").read_text()
    assert "- lowest mean IGD per problem: zdt1 " in block
    assert "| algorithm | mean IGD rank | mean HV rank | IGD vs nsga2 +/=/- |" in block
