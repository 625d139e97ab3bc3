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
