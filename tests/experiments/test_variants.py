"""A variant (``extends``) at another budget than its paper's: its report marks the paper's
rows with the paper's budget and its own rows with the run's, instead of printing them side
by side as if comparable."""

import pytest

from moik.cli import main
from moik.experiments.config_files import budget_of, budget_text, read_config
from moik.experiments.registry import experiment_files
from moik.experiments.store import ResultStore
from moik.experiments.tables import Results

RUN = ["--workers", "1", "--no-progress"]


def test_a_variant_keeps_its_papers_budget(tmp_path):
    path = tmp_path / "mpso_single_short.toml"
    path.write_text('extends = "mpso-single"\nname = "mpso-single-short"\niterations = 50\n')
    data = read_config(path, experiment_files())
    assert data["iterations"] == 50
    assert data["paper"]["budget"] == {"iterations": 500, "pop_size": 50}
    assert budget_text(data["paper"]["budget"]) == "500 iterations, population 50"
    assert budget_text({"evaluations": 10000}) == "10000 evaluations"
    assert budget_of({"iterations": 3, "problem": {"evaluations": 9}}) == {
        "iterations": 3, "evaluations": 9}
    base = read_config(experiment_files()["mpso-single"])
    assert "budget" not in base["paper"]  # a paper config's own data (its fingerprint) unchanged


@pytest.mark.parametrize(("iterations", "marked"), [(8, True), (500, False)])
def test_the_report_marks_the_papers_rows_of_a_variant_at_another_budget(
        tmp_path, capsys, iterations, marked):
    path = tmp_path / "mpso_single_short.toml"
    path.write_text(f'extends = "mpso-single"\nname = "mpso-single-short"\nruns = 1\n'
                    f'iterations = {iterations}\npop_size = 50\n')
    out = tmp_path / "r"
    assert main(["experiment", "run", "--config", str(path), *RUN, "--out", str(out)]) == 0
    res = Results(ResultStore.open(out))
    if marked:
        assert res.citation == "paper, at 500 iterations, population 50"
        assert res.source == f"this run, at {iterations} iterations, population 50"
        assert any("not comparable row by row" in n for n in res.notes())
    else:
        assert (res.citation, res.source) == ("paper", "moik")
    assert main(["report", str(out), "--no-figures"]) == 0
    report = (out / "report.md").read_text()
    assert (f"| m-pso | this run, at {iterations} iterations" in report) == marked
    assert ("| m-pso | paper, at 500 iterations, population 50 |" in report) == marked
    capsys.readouterr()
