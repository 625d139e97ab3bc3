"""The moik command line."""

import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from moik import __version__, get_robot
from moik.cli import main
from moik.robots.catalog import DATA

FLOAT = r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?"


def _numbers(line: str) -> np.ndarray:
    """The numbers inside the parentheses of a printed line."""
    inside = line[line.rindex("(") + 1:line.rindex(")")]
    return np.array([float(v) for v in inside.split(",")])


def _tokens(line: str) -> list[str]:
    """The numbers inside the parentheses of a printed line, as printed."""
    return [v.strip() for v in line[line.rindex("(") + 1:line.rindex(")")].split(",")]


def _args(values) -> list[str]:
    return [repr(float(v)) for v in values]


def _line(out: str, start: str) -> str:
    return next(line for line in out.splitlines() if line.startswith(start))


def _json(capsys) -> dict:
    return json.loads(capsys.readouterr().out)


def test_robots_lists_catalog(capsys):
    assert main(["robots"]) == 0
    out = capsys.readouterr().out
    assert "eosma7" in out and "irb2600" in out and "modified" in out
    assert re.search(r"panda\s+7\s+general chain", out)


def test_robots_json_lists_every_catalog_robot(capsys):
    assert main(["robots", "--json"]) == 0
    robots = {r["name"]: r for r in _json(capsys)["robots"]}
    assert {"iiwa14", "panda", "ur5", "puma560-urdf", "eosma7"} <= set(robots)
    assert robots["irb2600"] == {"name": "irb2600", "dof": 6, "kind": "modified DH",
                                 "unit": "mm", "source": get_robot("irb2600").source}


def test_robots_name_prints_dh_rows_and_units(capsys):
    assert main(["robots", "scara4"]) == 0
    out = capsys.readouterr().out
    assert "scara4: 4 DOF, standard DH, lengths in m" in out and "I-BES paper" in out
    assert "limits in deg; prismatic in m" in out and "alpha(deg)" in out
    assert re.search(r"3 q3\s+prismatic\s+0\s+1\s+0\s+0\s+0\s+0", out)  # limits in m
    assert re.search(r"2 q2\s+revolute\s+-180\s+180\s+0.4\s+180\s+0\s+0", out)


def test_robots_name_json_has_joint_names_and_radians(capsys):
    assert main(["robots", "ur5", "--json"]) == 0
    info = _json(capsys)
    assert info["kind"] == "general chain" and info["dh"] is None and info["unit"] == "m"
    assert [j["name"] for j in info["joints"]][:2] == ["shoulder_pan_joint",
                                                       "shoulder_lift_joint"]
    assert info["joints"][2] == {"name": "elbow_joint", "type": "revolute",
                                 "lower": -3.14159265359, "upper": 3.14159265359}  # as in the file
    assert main(["robots", "rokbani5", "--json"]) == 0
    info = _json(capsys)
    np.testing.assert_array_equal(info["dh"]["alpha"], get_robot("rokbani5").alpha)
    assert info["base"] == np.eye(4).tolist()


def test_robots_urdf_file_with_base_and_tip(capsys):
    urdf = str(DATA / "ur5_robot.urdf")
    assert main(["robots", urdf, "--base", "base_link", "--tip", "wrist_3_link"]) == 0
    out = capsys.readouterr().out
    assert "6 DOF, general chain" in out and "base_link -> wrist_3_link" in out
    assert "wrist_3_joint" in out


def test_algorithms_lists_registry(capsys):
    assert main(["algorithms"]) == 0
    out = capsys.readouterr().out
    assert "eosma" in out.split() and "multi-objective" in out
    assert main(["algorithms", "--json"]) == 0
    kinds = {a["name"]: a["kind"] for a in _json(capsys)["algorithms"]}
    assert kinds["eosma"] == "single-objective" and kinds["moeosma"] == "multi-objective"


def test_version_and_python_dash_m(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0 and capsys.readouterr().out.strip() == f"moik {__version__}"
    done = subprocess.run([sys.executable, "-m", "moik", "fk", "planar2", "0", "0"],
                          capture_output=True, text=True, timeout=300,
                          cwd=Path(__file__).parents[1])
    assert done.returncode == 0, done.stderr
    assert "position (m): (0.6499999999999999, 0.0, 0.0)" in done.stdout  # 0.35 + 0.30


def test_fk_prints_paper_pose(capsys):
    """Full precision (repr of floats): the printed pose is the computed one."""
    assert main(["fk", "eosma7", "45", "0", "45", "0", "45", "0", "0", "--deg"]) == 0
    out = capsys.readouterr().out
    position = _numbers(_line(out, "position (cm):"))
    np.testing.assert_allclose(position, [-24.748737, 100.961941, 50.0], atol=5e-7)
    T = get_robot("eosma7").fk(np.radians([45, 0, 45, 0, 45, 0, 0]))
    np.testing.assert_array_equal(position, T[:3, 3])  # every digit printed
    np.testing.assert_allclose(_numbers(_line(out, "EOSMA Eq. 26 Euler")), [90, -45, 0],
                               atol=1e-9)
    np.testing.assert_allclose(_numbers(_line(out, "ZYX Euler")), [135, 0, -90], atol=1e-9)


def test_fk_json(capsys):
    assert main(["fk", "scara4", "0.1", "0.2", "0.3", "0.4", "--json"]) == 0
    info = _json(capsys)
    robot = get_robot("scara4")
    T = robot.fk([0.1, 0.2, 0.3, 0.4])
    np.testing.assert_array_equal(info["pose"], T)
    np.testing.assert_array_equal(info["position"], T[:3, 3])
    assert info["q"] == [0.1, 0.2, 0.3, 0.4] and info["within_limits"] is True
    assert info["joint_names"] == ["q1", "q2", "q3", "q4"] and info["unit"] == "m"


def test_fk_deg_keeps_prismatic_joints_in_the_unit(capsys):
    assert main(["fk", "scara4", "90", "0", "0.25", "0", "--deg", "--json"]) == 0
    assert _json(capsys)["q"] == [np.pi / 2, 0.0, 0.25, 0.0]


def test_fk_errors_are_reported(capsys):
    assert main(["fk", "eosma7", "1", "2"]) == 2
    assert "needs 7 joint values, got 2" in capsys.readouterr().err
    assert main(["fk", "nope", "1"]) == 2
    err = capsys.readouterr().err
    assert "unknown robot 'nope'" in err and "or a URDF file" in err
    assert main(["fk", "planar2", "0", "nan"]) == 2
    assert "must be finite" in capsys.readouterr().err


@pytest.mark.parametrize("q", [["30", "60", "45", "60", "60"], ["100", "20", "70", "150", "10"]])
def test_fk_text_round_trips_to_solve_on_a_5dof_arm(capsys, q):
    """A 5-DOF arm reaches only a 5-D set of poses: printed to 4 decimals, the
    pose of `moik fk` is off that set and cannot be solved; printed in full it is."""
    assert main(["fk", "rokbani5", *q, "--deg"]) == 0
    out = capsys.readouterr().out
    position = _tokens(_line(out, "position (cm):"))
    euler = _tokens(_line(out, "ZYX Euler"))
    args = ["solve", "rokbani5", "--target", *position, "--euler", *euler, "--deg"]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "status: solved" in out
    first = _line(out, "solution 1:").split(":")[1].split()
    np.testing.assert_allclose([float(v) for v in first], [float(v) for v in q], atol=1e-5)
    if q[0] == "30":  # the pose rounded to 4 decimals, as `moik fk` printed it before
        rounded = [f"{float(v):.4f}" for v in position + euler]
        assert main(["solve", "rokbani5", "--target", *rounded[:3], "--euler", *rounded[3:],
                     "--deg"]) == 1
        assert "status: not-converged" in capsys.readouterr().out


def test_fk_json_round_trips_to_solve(capsys):
    assert main(["fk", "rokbani5", "0.4", "1.1", "0.9", "0.7", "1.3", "--json"]) == 0
    pose = _json(capsys)
    args = ["solve", "rokbani5", "--target", *_args(pose["position"]), "--euler",
            *_args(pose["zyx_euler"]), "--json"]
    assert main(args) == 0
    res = _json(capsys)
    assert res["status"] == "solved" and res["success"] is True
    assert res["position_error"] < 1e-8 and res["orientation_error"] < 1e-8


def test_solve_reachable_pose(capsys, tmp_path):
    """The README's main command: the pose of (45,0,45,0,45,0,0) deg (ZYX angles
    printed by `moik fk`) is solved exactly, with three distinct solutions; a plot
    path without extension gives the .png and the .pdf."""
    plot = tmp_path / "sol"
    args = ["solve", "eosma7", "--target", "-24.748737", "100.961941", "50", "--euler", "135",
            "0", "-90", "--deg", "--n-solutions", "3", "--plot", str(plot)]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "status: solved" in out and "solution 3:" in out and "solution 4:" not in out
    assert (tmp_path / "sol.png").exists() and (tmp_path / "sol.pdf").exists()
    # every solution prints its errors
    assert len(re.findall(rf"position error {FLOAT} cm, orientation error {FLOAT} rad", out)) == 3


def test_solve_json_lists_every_solution_with_errors(capsys):
    args = ["solve", "eosma7", "--target", "-24.748737", "100.961941", "50", "--euler", "135",
            "0", "-90", "--deg", "--n-solutions", "2", "--json"]
    assert main(args) == 0
    res = _json(capsys)
    assert res["status"] == "solved" and res["unit"] == "cm" and len(res["solutions"]) == 2
    assert res["q"] == res["solutions"][0]["q"] and res["front"] is None
    robot = get_robot("eosma7")
    for sol in res["solutions"]:
        T = robot.fk(sol["q"])  # radians
        err = np.linalg.norm(T[:3, 3] - res["target"]["position"])
        assert err == pytest.approx(sol["position_error"], abs=1e-12)
        assert sol["position_error"] < 1e-6 and sol["orientation_error"] < 1e-8


def test_prismatic_joints_are_printed_in_the_unit(capsys):
    """Every solution prints prismatic joints in metres, never through degrees."""
    args = ["solve", "scara4", "--target", "0.3", "0.2", "0.5", "--n-solutions", "2"]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "(deg; prismatic in m)" in out
    for k in (1, 2):
        q = [float(v) for v in _line(out, f"solution {k}:").split(":")[1].split()]
        assert q[2] == pytest.approx(0.1, abs=1e-6)  # z = 0.8 - d3 - 0.2
    assert len(re.findall(r"position error", out)) == 2


def test_solve_urdf_path_with_tip(capsys):
    urdf = str(DATA / "panda.urdf")
    robot = get_robot("panda")
    q = np.array([0.1, -0.4, 0.2, -1.8, 0.3, 1.4, 0.5])
    T = robot.fk(q)
    assert main(["fk", urdf, *_args(q), "--tip", "panda_hand_tcp", "--json"]) == 0
    np.testing.assert_array_equal(_json(capsys)["pose"], T)
    args = ["solve", urdf, "--tip", "panda_hand_tcp", "--target", *_args(T[:3, 3]),
            "--json"]
    assert main(args) == 0
    res = _json(capsys)
    assert res["status"] == "solved" and res["joint_names"][0] == "panda_joint1"
    assert main(["solve", urdf, "--tip", "nope", "--target", "0", "0", "0.5"]) == 2
    assert "unknown link 'nope'" in capsys.readouterr().err


def test_solve_q_current_tol_and_max_evals(capsys):
    robot = get_robot("eosma7")
    q0 = np.radians([40.0, -10, 30, 20, 40, 10, 5])
    p = robot.fk(q0)[:3, 3]
    args = ["solve", "eosma7", "--target", *_args(p), "--q-current", "40", "-10", "30", "20",
            "40", "10", "5", "--deg", "--tol", "1e-6", "1e-6", "--max-evals", "2000", "--json"]
    assert main(args) == 0
    res = _json(capsys)
    assert res["status"] == "solved" and res["position_error"] <= 1e-6
    np.testing.assert_allclose(res["q"], q0, atol=1e-6)  # q_current already solves it
    assert main(args[:-1] + ["--tol", "1", "2", "3"]) == 2
    assert "--tol takes 1 number" in capsys.readouterr().err


def test_unsolved_wording_is_honest(capsys):
    """not-converged: the best candidate; unreachable pose: the utopia compromise."""
    pose = ["--target", "-25", "100", "50", "--euler", "0", "0", "0", "--deg"]
    assert main(["solve", "eosma7", *pose, "--max-evals", "300", "--starts", "0"]) == 1
    out = capsys.readouterr().out
    assert "status: not-converged" in out and "best candidate:" in out
    assert "utopia" not in out and "not converged: the best candidate" in out
    assert main(["solve", "eosma7", "--target", "200", "0", "0", "--euler", "0", "0", "0"]) == 1
    out = capsys.readouterr().out
    assert "status: unreachable" in out and "compromise:" in out
    assert "the compromise above is the one closest to the utopia point" in out
    assert main(["solve", "eosma7", "--target", "200", "0", "0"]) == 1
    out = capsys.readouterr().out
    assert "status: unreachable" in out and "out of reach" in out and "utopia" not in out


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
    # a position whose squared norm overflows: the error alone, no numpy warning before it
    assert main(["solve", "eosma7", "--target", "0", "1e300", "0"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("moik: error:") and err.count("\n") == 1, err


@pytest.mark.parametrize("seed", ["-1", "-7"])
def test_negative_seed_is_a_one_line_error(capsys, seed):
    assert main(["solve", "planar2", "--target", "0.3", "0.2", "0", "--seed", seed]) == 2
    captured = capsys.readouterr()
    assert captured.err == f"moik: error: --seed must be an integer >= 0, got {seed}\n"
    assert captured.out == ""


@pytest.mark.parametrize("plot, written", [
    ("out.d/fig", ["out.d/fig.png", "out.d/fig.pdf"]),
    ("sub/p2.svg", ["sub/p2.svg"]),
    ("sub/p2.PDF", ["sub/p2.PDF"]),
    ("sub/v1.0", None),  # an unknown extension is refused, not cut off
])
def test_plot_paths(capsys, tmp_path, monkeypatch, plot, written):
    (tmp_path / "out.d").mkdir()
    (tmp_path / "sub").mkdir()
    monkeypatch.chdir(tmp_path / "sub")
    args = ["solve", "planar2", "--target", "0.3", "0.2", "0", "--plot", f"../{plot}"]
    if written is None:
        assert main(args) == 2
        assert "--plot file must end in .png, .pdf, .svg" in capsys.readouterr().err
        return
    assert main(args) == 0
    files = sorted(str(p.relative_to(tmp_path)) for p in tmp_path.rglob("*") if p.is_file())
    assert files == sorted(written)
    assert "plot written to ../" in capsys.readouterr().out


def test_plot_folder_is_checked_before_solving(capsys, tmp_path):
    args = ["solve", "eosma7", "--target", "10", "10", "10", "--plot", str(tmp_path / "no" / "x")]
    assert main(args) == 2
    captured = capsys.readouterr()
    assert captured.out == ""  # nothing solved
    assert captured.err.startswith("moik: error: --plot folder") and "does not exist" in \
        captured.err and captured.err.count("\n") == 1
    (tmp_path / "file").write_text("")
    assert main(args[:-1] + [str(tmp_path / "file" / "x.png")]) == 2
    assert "is a file, not a folder" in capsys.readouterr().err
    assert main(args[:-1] + [str(tmp_path)]) == 2
    assert "--plot needs a file name" in capsys.readouterr().err


def test_experiment_list(capsys):
    assert main(["experiment", "list"]) == 0
    out = capsys.readouterr().out
    for name in ("eosma-table5", "eosma-table8", "mpso-circle", "mpso-table5"):
        assert name in out


@pytest.mark.parametrize("argv", [["algorithms"], ["experiment", "list"], ["robots"],
                                  ["problems"]])
def test_listings_are_columns_sized_to_their_content(capsys, argv):
    """Every column starts where its header starts, on every row, and is separated from
    the one before it by at least two spaces (no name runs into the next column)."""
    assert main(argv) == 0
    lines = capsys.readouterr().out.splitlines()
    header = lines[0]
    starts = [m.start() for m in re.finditer(r"\S+", header)]
    assert len(starts) >= 3
    for line in lines[1:]:
        for a, b in zip(starts[:-1], starts[1:], strict=True):
            assert line[a:b].strip() and line[b - 2:b] == "  ", (header[a:b].strip(), line)


def test_unwritable_out_is_a_one_line_error(capsys, tmp_path):
    (tmp_path / "file").write_text("")
    args = ["experiment", "run", "mpso-single", "--quick", "--workers", "1", "--no-progress",
            "--out", str(tmp_path / "file" / "r")]
    assert main(args) == 2
    err = capsys.readouterr().err
    assert err.startswith("moik: error: cannot ") and err.count("\n") == 1
    assert "is a file" in err or "Not a directory" in err  # the results store says which


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


def test_the_parser_help_names_match_the_library():
    from moik.cli.parser import CRITERIA_NAMES, EXPERIMENTS_ENV
    from moik.experiments.registry import ENV_VAR
    from moik.kinematics.criteria import CRITERIA

    assert tuple(CRITERIA) == CRITERIA_NAMES and EXPERIMENTS_ENV == ENV_VAR


def test_solve_help_shows_the_librarys_defaults(capsys):
    """The parser writes no default of its own: ``moik solve --help`` reads each from the
    signature of solve_ik / solve_ik_pareto, and an option not given is not passed."""
    import inspect

    from moik.cli.parser import LIBRARY_DEFAULTS, build_parser, given
    from moik.solver import solve_ik, solve_ik_pareto

    with pytest.raises(SystemExit):
        main(["solve", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    functions = {"solve_ik": solve_ik, "solve_ik_pareto": solve_ik_pareto}
    for dest, (function, keyword) in LIBRARY_DEFAULTS.items():
        default = inspect.signature(functions[function]).parameters[keyword].default
        assert f"default {default}" in text, dest
    args = build_parser().parse_args(["solve", "panda", "--target", "0.4", "0.1", "0.5",
                                      "--starts", "7"])
    assert given(args, *LIBRARY_DEFAULTS) == {"starts": 7}


@pytest.mark.parametrize(("argv", "absent"), [
    (["--help"], ["numpy", "numba", "scipy", "pymoo"]),
    (["robots"], ["numba", "scipy", "pymoo"]),
    (["robots", "ur5"], ["numba", "scipy", "pymoo"]),
])
def test_help_and_the_catalog_import_nothing_heavy(argv, absent):
    code = (f"import sys\nfrom moik.cli import main\ntry:\n    main({argv!r})\n"
            "except SystemExit:\n    pass\n"
            f"print(sorted(m for m in {absent!r} if m in sys.modules), file=sys.stderr)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stderr.strip().splitlines()[-1] == "[]"


PANDA_URDF = str(DATA / "panda.urdf")


@pytest.mark.parametrize(("argv", "said"), [
    (["solve", "eosma7", "--target", "10", "50", "40", "--euler", "135", "0", "-90"],
     "--euler angles [135.0, 0.0, -90.0] exceed 2 pi in magnitude; they are radians: add --deg"),
    (["robots", PANDA_URDF], "give --tip one of ['panda_hand_tcp', 'panda_leftfinger'"),
    (["solve", "eosma7", "--target", "10", "50", "40", "--n-solutions", "0"],
     "--n-solutions must be an integer >= 1, got 0"),
    (["solve", "eosma7", "--target", "10", "50", "40", "--max-evals", "0"],
     "--max-evals must be an integer >= 1"),
    (["solve", "eosma7", "--target", "10", "50", "40", "--starts", "-1"],
     "--starts must be an integer >= 0"),
    (["solve", "eosma7", "--target", "10", "50", "40", "--pareto", "joint_motion"],
     "criterion 'joint_motion' needs --q-current"),
    (["solve", "eosma7", "--target", "10", "50", "40", "--pareto", "manipulability",
      "--pareto-size", "0"], "--pareto-size must be an integer >= 1"),
    (["solve", "eosma7", "--target", "10", "50", "40", "--algorithm", "nope"],
     "--algorithm: unknown algorithm 'nope'"),
    (["solve", "eosma7", "--target", "10", "50", "40", "--pareto", "manipulability",
      "--pareto-method", "nope"], "--pareto-method: unknown algorithm 'nope'"),
])
def test_errors_name_the_command_line_options(capsys, argv, said):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert said in err, err
    for word in ("degrees=True", "tip_link=", "q_current", "n_solutions", "max_evals"):
        assert word not in err


def test_joint_values_in_degrees_without_deg_are_warned_about(capsys):
    assert main(["fk", "eosma7", "45", "0", "45", "0", "45", "0", "0"]) == 0
    err = capsys.readouterr().err
    assert err.count("DegreesWarning") == 0 and err.count("look like degrees") == 1
    assert ("moik: warning: the joint values for robot 'eosma7': joint 1 (q1) = 45 is more "
            "than a turn beyond its limits") in err and "add --deg" in err
    assert "q is outside the joint limits: joint 1 (q1) = 45 above its upper limit" in err
    assert main(["fk", "eosma7", "45", "0", "45", "0", "45", "0", "0", "--deg"]) == 0
    assert "warning" not in capsys.readouterr().err
    main(["solve", "eosma7", "--target", "-24.748737", "100.961941", "50", "--q-current",
          "45", "0", "45", "0", "45", "0", "0", "--json"])
    err = capsys.readouterr().err
    assert err.count("look like degrees") == 1 and "--q-current for robot 'eosma7'" in err


def test_the_limits_warning_names_each_joint_outside(capsys):
    assert main(["fk", "eosma7", "0", "1", "0", "0", "0", "0", "-1"]) == 0
    err = capsys.readouterr().err
    assert ("q is outside the joint limits: joint 2 (q2) = 1 above its upper limit 0.523599; "
            "joint 7 (q7) = -1 below its lower limit -0.523599") in err


def test_fk_solve_and_pareto_json_share_one_schema_family(capsys):
    """The keys every document has, and those of the solving ones (moik.cli's docstring)."""
    common = {"command", "robot", "unit", "joint_names", "q"}
    solving = common | {"target", "status", "success", "n_eval", "time_s", "position_error",
                        "orientation_error", "solutions", "plots"}
    main(["fk", "planar2", "0.1", "0.2", "--json"])
    fk = json.loads(capsys.readouterr().out)
    target = ["--target", *map(str, fk["position"])]
    main(["solve", "planar2", *target, "--json"])
    solve = json.loads(capsys.readouterr().out)
    main(["solve", "planar2", *target, "--pareto", "manipulability", "--json"])
    pareto = json.loads(capsys.readouterr().out)
    assert common <= set(fk) and fk["command"] == "fk"
    assert solving <= set(solve) and solve["command"] == "solve" and solve["n_solutions"] == 1
    assert solving <= set(pareto) and pareto["command"] == "pareto"
    assert solve["status"] == pareto["status"] == "solved"
    for doc in (solve, pareto):
        assert set(doc["solutions"][0]) == {"q", "position_error", "orientation_error"}
        assert set(doc["target"]) == {"position", "rotation"}


def test_fewer_solutions_than_asked_are_said(capsys):
    """planar2 has two branches for a reachable position: asking for 5 finds 2, and says so."""
    assert main(["solve", "planar2", "--target", "0.4", "0.2", "0", "--n-solutions", "5"]) == 0
    assert "note: found 2 of the 5 distinct solutions requested" in capsys.readouterr().out
    main(["solve", "planar2", "--target", "0.4", "0.2", "0", "--n-solutions", "5", "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert doc["fewer_solutions"] is True and len(doc["solutions"]) == 2
    assert doc["n_solutions"] == 5 and "found 2 of the 5" in doc["detail"]


_BLOCKING = ("import importlib, sys, time\nm = importlib.import_module('moik.cli.main')\n"
             "def handler(spec):\n"
             "    def run(args):\n"
             "        print('ready', flush=True)\n"
             "        time.sleep(60)\n"
             "    return run\n"
             "m._handler = handler\nsys.exit(m.main(['robots']))\n")


@pytest.mark.parametrize("sig, status, name", [("SIGTERM", 143, "SIGTERM"),
                                               ("SIGINT", 130, "SIGINT")])
def test_a_signal_ends_any_command_with_one_line(sig, status, name):
    """Before: SIGTERM at start-up exited silently, SIGINT printed a traceback."""
    import signal

    proc = subprocess.Popen([sys.executable, "-c", _BLOCKING], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "ready"
    proc.send_signal(getattr(signal, sig))
    _, err = proc.communicate(timeout=30)
    assert proc.returncode == status
    assert err.strip() == f"moik: interrupted ({name})"


@pytest.mark.parametrize("argv, match", [
    (["solve", "planar2", "--target", "1", "0", "0", "--n-solutions", "1000000000"],
     "n-solutions must be at most 100000"),
    (["solve", "planar2", "--target", "1", "0", "0", "--scene", "/dev/zero"],
     "not a regular file"),
    (["experiment", "run", "--config", "/dev/null"], "not a regular file"),
])
def test_untrusted_arguments_end_in_one_line_and_status_2(argv, match, capsys):
    """Before: --n-solutions 1000000000 allocated 67 GiB; /dev/zero was read without limit;
    --config /dev/null 'does not exist'."""
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and re.search(match, err), err


@pytest.mark.parametrize("argv", [
    ["experiment", "run", "tiny", "--out", ""],
    ["solve", "planar2", "--target", "1", "0", "0", "--pareto", ""],
    ["report", "x", "--docs", ""],
])
def test_empty_paths_and_lists_are_refused(argv, capsys):
    """Before: --out "" and --pareto "" silently meant the defaults."""
    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert err.startswith("moik: error: ") and err.count("\n") == 1
    assert "expected a non-empty value" in err


def test_json_output_is_strict(capsys):
    """``--json`` documents are strict JSON: a non-finite number (an ``inf`` distance) is
    ``null``, never ``Infinity``, which strict parsers refuse."""
    import json as _json

    import numpy as _np

    from moik.cli.output import print_json
    print_json({"d": float("inf"), "q": _np.array([1.0, _np.nan]), "n": _np.int64(3),
                "rows": [{"x": _np.float64(-_np.inf)}]})
    text = capsys.readouterr().out
    assert "Infinity" not in text and "NaN" not in text
    assert _json.loads(text) == {"d": None, "q": [1.0, None], "n": 3, "rows": [{"x": None}]}
