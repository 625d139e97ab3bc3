"""``moik batch ROBOT TARGETS --out RESULT``: .npy and CSV in, .npz and CSV out, bad files."""

import csv
import json
import os
import re

import numpy as np
import pytest

from moik import solve_ik_batch
from moik.cli import batch, main
from moik.kinematics.orientation import zyx_euler
from moik.robots import get_robot

SCENE = {"obstacles": [{"name": "table", "type": "halfspace", "normal": [0, 0, 1],
                        "offset": 0.0}],
         "allowed": [["table", "panda_link0"], ["table", "panda_link1"]]}


@pytest.fixture(scope="module")
def poses():
    robot = get_robot("panda")
    return robot.fk(robot.random_q(40, rng=np.random.default_rng(11)))


def test_npy_round_trip_with_the_bar(tmp_path, poses, capsys, monkeypatch):
    monkeypatch.setattr(batch, "PROGRESS_MIN", 10)
    np.save(tmp_path / "t.npy", poses)
    code = main(["batch", "panda", str(tmp_path / "t.npy"), "--out", str(tmp_path / "r.npz"),
                 "--workers", "2", "--seed", "3"])
    out, err = capsys.readouterr()
    assert code == 0 and "40/40 solved" in out and "solutions/s" in out
    assert "moik batch" in err and "40/40" in err  # the tqdm bar, at its end
    with np.load(tmp_path / "r.npz") as res:
        ref = solve_ik_batch("panda", poses, seed=3, workers=1)
        np.testing.assert_array_equal(res["q"], ref.q)
        assert list(res["status"]) == list(ref.status) and "min_distance" not in res
        np.testing.assert_array_equal(res["position_error"], ref.position_error)


def test_csv_round_trip_positions_and_poses(tmp_path, poses, capsys):
    angles = np.array([zyx_euler(T[:3, :3]) for T in poses])  # (yaw, pitch, roll)
    with (tmp_path / "t.csv").open("w") as f:
        f.write("x,y,z,roll,pitch,yaw\n")
        for T, (yaw, pitch, roll) in zip(poses, np.degrees(angles), strict=True):
            f.write(" ".join(repr(float(v)) for v in (*T[:3, 3], roll, pitch, yaw)) + "\n")
    code = main(["batch", "panda", str(tmp_path / "t.csv"), "--deg", "--out",
                 str(tmp_path / "r.csv"), "--scene", str(_scene(tmp_path))])
    assert code in (0, 1) and "/40 solved" in capsys.readouterr().out
    rows = list(csv.DictReader((tmp_path / "r.csv").open()))
    robot = get_robot("panda")
    assert len(rows) == 40 and "min_distance" in rows[0]
    for row, T in zip(rows, poses, strict=True):
        q = np.array([float(row[name]) for name in robot.joint_names])
        if row["status"] == "solved":
            assert float(row["min_distance"]) >= 0.0
            np.testing.assert_allclose(robot.fk(q), T, atol=1e-8)
    np.savetxt(tmp_path / "p.csv", poses[:5, :3, 3], delimiter=",")
    assert main(["batch", "panda", str(tmp_path / "p.csv"), "--out",
                 str(tmp_path / "p.npz")]) == 0


def _scene(tmp_path):
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(SCENE))
    return path


def test_unsolved_targets_exit_1(tmp_path, poses, capsys):
    far = poses[:3].copy()
    far[0, :3, 3] += 5.0
    np.save(tmp_path / "t.npy", far)
    assert main(["batch", "panda", str(tmp_path / "t.npy"), "--out",
                 str(tmp_path / "r.npz")]) == 1
    assert "2/3 solved (1 unreachable)" in capsys.readouterr().out


@pytest.mark.parametrize(("content", "match"), [
    (np.zeros((4, 3, 4)), r"poses \(n, 4, 4\) or positions \(n, 3\), got shape \(4, 3, 4\)"),
    (np.zeros((0, 3)), "holds no target"),
    (np.array([[0.1, np.nan, 0.3]]), "target 0 holds NaN"),
    ("not-a-rotation", "target 1 is not a pose"),
    (b"garbage", "not a numpy .npy file"),
    ("a,b,c\n1,2\n", "line 2: expected 3"),
    ("1,2,x\n", "line 1: expected numbers"),
    ("x,y,z\n# only a header and a comment\n", "holds no target"),
    ("0.3,0.1,0.5,0,0,0\n0.3,0.1,0.5,0,nan,0\n", "target 1 holds NaN"),
    ("0.3,0.1,0.5,0,0,0\n0.3,0.1,0.5,90,0,45\n", "target 1 has angles .* add --deg"),
    ("0.3,0.1,0.5\n20,0,0\n", r"targets\[1\]: position .* more than 10x its reach"),
    ("0.3,,0.1,0.5\n", "line 1: an empty field"),
    ("0.3,1_0,0.5\n", "line 1: expected numbers"),
    (None, "does not exist"),
])
def test_bad_files_exit_2_with_one_line(tmp_path, poses, capsys, content, match):
    path = tmp_path / ("t.csv" if isinstance(content, str) and content[0] in "0123456789xa"
                       else "t.npy")
    if isinstance(content, np.ndarray):
        np.save(path, content)
    elif content == "not-a-rotation":
        bad = poses[:3].copy()
        bad[1, :3, :3] *= 1.5
        np.save(path, bad)
    elif isinstance(content, bytes):
        path.write_bytes(content)
    elif isinstance(content, str):
        path.write_text(content)
    assert main(["batch", "panda", str(path), "--out", str(tmp_path / "r.npz")]) == 2
    err = capsys.readouterr().err
    assert err.startswith("moik: error:") and err.count("\n") == 1
    assert re.search(match, err), err


def test_a_npy_header_declaring_more_than_memory_is_one_line(tmp_path, capsys):
    """Before: a truncated .npy whose header says (10**12, 3) ended in numpy's
    _ArrayMemoryError traceback and exit 1."""
    path = tmp_path / "t.npy"
    with open(path, "wb") as f:
        np.lib.format.write_array_header_1_0(f, {"descr": "<f8", "fortran_order": False,
                                                 "shape": (10**12, 3)})
        f.write(np.zeros(6).tobytes())
    assert main(["batch", "panda", str(path), "--out", str(tmp_path / "r.npz")]) == 2
    err = capsys.readouterr().err
    assert err.startswith("moik: error:") and err.count("\n") == 1
    assert "does not fit in memory" in err, err


def test_bad_out_and_options(tmp_path, poses, capsys):
    np.save(tmp_path / "t.npy", poses[:2])
    for argv, match in ((["--out", str(tmp_path / "r.txt")], "--out must end in"),
                        (["--out", str(tmp_path / "no" / "r.npz")], "does not exist"),
                        (["--out", str(tmp_path / "r.npz"), "--clearance", "0.1"],
                         "--clearance was given but nothing is checked")):
        assert main(["batch", "panda", str(tmp_path / "t.npy"), *argv]) == 2
        assert match in capsys.readouterr().err


def test_out_is_a_new_name_or_a_regular_file_checked_before_solving(tmp_path, poses, capsys,
                                                                     monkeypatch):
    """A link, a folder, a FIFO or the targets file itself as --out: refused before any
    target is solved (exit 2, one line); what a link points to is never written."""
    np.save(tmp_path / "t.npy", poses[:2])
    (tmp_path / "victim.txt").write_text("keep")
    (tmp_path / "link.npz").symlink_to(tmp_path / "victim.txt")
    (tmp_path / "dir.npz").mkdir()
    (tmp_path / "t.csv").write_text("0.3,0.1,0.5\n")
    cases = [(["t.npy", "--out", "link.npz"], "symbolic link"),
             (["t.npy", "--out", "dir.npz"], "not a regular file"),
             (["t.csv", "--out", "t.csv"], "is the targets file")]
    if hasattr(os, "mkfifo"):
        os.mkfifo(tmp_path / "fifo.npz")
        cases.append((["t.npy", "--out", "fifo.npz"], "not a regular file"))
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(batch, "solve_ik_batch", None)  # never reached
    for argv, match in cases:
        assert main(["batch", "panda", *argv]) == 2
        err = capsys.readouterr().err
        assert match in err and err.count("\n") == 1, err
    assert (tmp_path / "victim.txt").read_text() == "keep"


def test_a_bom_header_and_trailing_commas_are_read_deg_without_angles_refused(tmp_path, capsys):
    """Excel's "CSV UTF-8" (a byte-order mark before the header) and a trailing comma per
    line read as plain CSV; --deg with targets that have no angles is refused (exit 2)."""
    path = tmp_path / "t.csv"
    path.write_text("\ufeffx,y,z,\n0.3,0.1,0.5,\n0.3,0.2,0.5,\n", encoding="utf-8")
    assert main(["batch", "panda", str(path), "--out", str(tmp_path / "r.npz")]) == 0
    assert "2/2 solved" in capsys.readouterr().out
    assert main(["batch", "panda", str(path), "--deg", "--out", str(tmp_path / "r.npz")]) == 2
    assert "--deg applies to the angles" in capsys.readouterr().err
