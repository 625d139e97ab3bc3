"""``moik experiment list|run`` (moik.cli.experiment): a user's own config files."""

import pytest
import tomli_w

from moik.cli import main
from moik.experiments.registry import ENV_VAR
from moik.experiments.store import ResultStore

RUN = ["--quick", "--workers", "1", "--no-progress"]


def _write(folder, tiny, stem="tiny_test"):
    path = folder / f"{stem}.toml"
    path.write_text("# A user's experiment.\n" + tomli_w.dumps(tiny))
    return path


def test_run_a_config_file_given_with_config(tmp_path, capsys, tiny):
    path = _write(tmp_path, tiny)
    out = tmp_path / "r"
    assert main(["experiment", "run", "--config", str(path), *RUN, "--out", str(out)]) == 0
    assert "tiny-test: ran 4 trial(s) (0 failed)" in capsys.readouterr().out
    store = ResultStore.open(out)
    assert store.meta["config_path"] == str(path) and len(store.records()) == 4


def test_configs_in_the_env_var_folders_are_listed_and_run_by_name(tmp_path, capsys,
                                                                   monkeypatch, tiny):
    folder = tmp_path / "mine"
    folder.mkdir()
    _write(folder, tiny)
    monkeypatch.setenv(ENV_VAR, str(folder))
    assert main(["experiment", "list"]) == 0
    listing = capsys.readouterr().out
    assert "tiny-test" in listing and "tiny position experiment" in listing
    assert "eosma-table5" in listing  # the packaged ones are still there
    assert main(["experiment", "run", "tiny-test", *RUN, "--out", str(tmp_path / "r")]) == 0
    assert "tiny-test: ran 4 trial(s)" in capsys.readouterr().out


def test_a_bad_config_file_is_one_error_line(tmp_path, capsys, tiny):
    path = _write(tmp_path, dict(tiny, runs=0))
    assert main(["experiment", "run", "--config", str(path), *RUN]) == 2
    err = capsys.readouterr().err
    assert err.startswith("moik: error: ") and "runs must be an integer >= 1, got 0" in err


def test_name_or_config_exactly_one(tmp_path, capsys, tiny):
    path = _write(tmp_path, tiny)
    for args in (["experiment", "run"], ["experiment", "run", "tiny-test", "--config", str(path)]):
        with pytest.raises(SystemExit) as exc:
            main(args)
        assert exc.value.code == 2
    assert "--config" in capsys.readouterr().err


def test_counts_must_be_positive_integers(capsys):
    for bad in ("0", "2.0", "x"):
        with pytest.raises(SystemExit):
            main(["experiment", "run", "mpso-single", "--workers", bad])
        assert f"expected a positive integer, got '{bad}'" in capsys.readouterr().err


def test_a_config_holding_code_is_refused_not_run(tmp_path, capsys, tiny):
    marker = tmp_path / "ran"
    code = tmp_path / "tiny_test.py"
    code.write_text(f"open({str(marker)!r}, 'w').close()\nEXPERIMENT = {tiny!r}\n")
    assert main(["experiment", "run", "--config", str(code), *RUN]) == 2
    err = capsys.readouterr().err
    assert "experiment configs are TOML data files (.toml); this is Python code" in err
    disguised = tmp_path / "tiny_test.toml"
    disguised.write_text(code.read_text())
    assert main(["experiment", "run", "--config", str(disguised), *RUN]) == 2
    err = capsys.readouterr().err
    assert "not valid TOML" in err and "looks like Python code" in err
    assert not marker.exists()


def test_a_users_variant_extends_a_paper_config(tmp_path, capsys):
    path = tmp_path / "mpso_single_short.toml"
    path.write_text('extends = "mpso-single"\nname = "mpso-single-short"\nruns = 2\n')
    assert main(["experiment", "run", "--config", str(path), *RUN, "--limit", "1",
                 "--out", str(tmp_path / "r")]) == 0
    assert "mpso-single-short: ran 1 trial(s) (0 failed)" in capsys.readouterr().out
