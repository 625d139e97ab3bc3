"""The moik command line."""

from moik.cli import main


def test_robots_lists_catalog(capsys):
    assert main(["robots"]) == 0
    out = capsys.readouterr().out
    assert "eosma7" in out and "irb2600" in out and "modified" in out


def test_fk_prints_paper_pose(capsys):
    assert main(["fk", "eosma7", "45", "0", "45", "0", "45", "0", "0", "--deg"]) == 0
    out = capsys.readouterr().out
    assert "(-24.748737, 100.961941, 50.000000)" in out
    assert "(90.0000, -45.0000, 0.0000)" in out


def test_fk_errors_are_reported(capsys):
    assert main(["fk", "eosma7", "1", "2"]) == 2
    assert "needs 7 joint values, got 2" in capsys.readouterr().err
    assert main(["fk", "nope", "1"]) == 2
    assert "unknown robot 'nope'" in capsys.readouterr().err


def test_solve_reachable_pose(capsys, tmp_path):
    """The README's main command: the pose of (45,0,45,0,45,0,0) deg (ZYX angles
    printed by `moik fk`) is solved exactly, with three distinct solutions."""
    plot = tmp_path / "sol.png"
    args = ["solve", "eosma7", "--target", "-24.748737", "100.961941", "50", "--euler", "135",
            "0", "-90", "--deg", "--n-solutions", "3", "--plot", str(plot)]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "status: solved" in out and "solution 3:" in out and "solution 4:" not in out
    assert (tmp_path / "sol.png").exists() and (tmp_path / "sol.pdf").exists()


def test_solve_with_the_global_search_only(capsys):
    args = ["solve", "eosma7", "--target", "-24.748737", "100.961941", "50", "--euler", "135",
            "0", "-90", "--deg", "--starts", "0"]
    assert main(args) == 0
    assert "status: solved" in capsys.readouterr().out
    assert main(args[:-1] + ["-1"]) == 2
    assert "starts must be an integer >= 0, got -1" in capsys.readouterr().err


def test_solve_errors_are_one_line(capsys):
    assert main(["solve", "eosma7", "--target", "0", "0", "9000"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("moik: error:") and "expected a position in cm" in err


def test_algorithms_lists_registry(capsys):
    assert main(["algorithms"]) == 0
    assert "eosma" in capsys.readouterr().out.split()


def test_experiment_list(capsys):
    assert main(["experiment", "list"]) == 0
    out = capsys.readouterr().out
    for name in ("eosma-table5", "eosma-table8", "mpso-circle", "mpso-table5"):
        assert name in out


def test_experiment_errors_are_one_line(capsys, tmp_path):
    assert main(["experiment", "run", "nope"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("moik: error: unknown experiment 'nope'") and err.count("\n") == 1
    assert main(["report", str(tmp_path)]) == 2
    assert "holds no moik results" in capsys.readouterr().err
    args = ["experiment", "run", "mpso-single", "--quick", "--workers", "1", "--no-progress",
            "--out", str(tmp_path / "r")]
    assert main(args) == 0
    assert main(args) == 2
    assert "pass --resume" in capsys.readouterr().err
    assert main(args + ["--resume"]) == 0
    assert "0 trial(s) (0 failed), 3 already finished" in capsys.readouterr().out
