"""A MoveIt SRDF's disabled pairs as body pairs of a URDF model (moik/collision/srdf.py)."""

import warnings
from pathlib import Path

import numpy as np
import pytest

from moik import load_urdf, solve_ik
from moik.cli import main
from moik.collision.urdf import model_from_urdf
from moik.exceptions import GeometryError, GeometryWarning, ParameterError

# links a and c overlap in every configuration (c's ball 10 mm below a's, the joints between
# them turn 0.2 rad at most about one axis); f is fixed to c, with a ball of its own; the
# base's ball is on c's path near j1 = 1.5 rad
STUCK = (Path(__file__).resolve().parents[1] / "data" / "urdf" / "stuck.urdf").read_text()


def _srdf(*elements: str) -> str:
    return '<robot name="stuck">' + "".join(elements) + "</robot>"


A_C = '<disable_collisions link1="a" link2="c" reason="Default"/>'
A_F = '<disable_collisions link1="f" link2="a" reason="Never"/>'


def _checked(srdf) -> tuple:
    """The body pairs checked with the SRDF (no sampled matrix), and the model."""
    robot = load_urdf(STUCK, tip_link="c")
    model = model_from_urdf(STUCK, robot, samples=0, srdf=srdf)
    names = model.links
    return tuple((names[i], names[j]) for i, j in model.checked_body_pairs()), model


def test_a_body_pair_is_left_unchecked_when_every_link_pair_on_it_is_disabled():
    # c's body also carries f (fixed to c): a - c alone leaves a - f checked, so the body
    # pair stays checked; with a - f disabled too, it is not
    assert _checked(None)[0] == (("base", "b"), ("base", "c"), ("a", "c"))
    assert _checked(_srdf(A_C))[0] == (("base", "b"), ("base", "c"), ("a", "c"))
    pairs, model = _checked(_srdf(A_C, A_F, '<group name="arm"/>'))
    assert pairs == (("base", "b"), ("base", "c"))
    assert "SRDF <SRDF string>: 1 body pairs not checked" in model.source


def test_default_collisions_and_enable_collisions():
    every = '<disable_default_collisions link="a"/>'
    assert _checked(_srdf(every))[0] == (("base", "b"), ("base", "c"))
    again = '<enable_collisions link1="a" link2="f"/>'
    assert _checked(_srdf(every, again))[0] == (("base", "b"), ("base", "c"), ("a", "c"))
    # a link of the URDF off the chain (head, fixed to the base) is ignored
    assert _checked(_srdf('<disable_collisions link1="head" link2="c"/>', A_C, A_F))[0] == \
        (("base", "b"), ("base", "c"))


def test_entries_naming_other_links_are_skipped_with_a_warning():
    """The whole robot's SRDF beside a URDF of one arm: the entries naming links the URDF
    does not have are skipped, named in a warning; the others are used."""
    with pytest.warns(GeometryWarning, match="skipped: elbow, leg"):
        pairs, _ = _checked(_srdf(A_C, A_F, '<disable_collisions link1="a" link2="elbow"/>',
                                  '<disable_default_collisions link="leg"/>'))
    assert pairs == (("base", "b"), ("base", "c"))


@pytest.mark.parametrize(("srdf", "match"), [
    (_srdf('<disable_collisions link1="a" link2="elbow"/>'),
     r"none of its 1 entries names only links of the URDF .*'elbow'"),
    (_srdf('<disable_collisions link1="a"/>'), "needs link1= and link2="),
    (_srdf('<disable_default_collisions/>'), "needs link="),
    ("<robot", "cannot read SRDF"),
    ("<srdf/>", "not an SRDF file: root element <srdf>"),
])
def test_bad_srdf_is_a_geometry_error(srdf, match):
    with pytest.raises(GeometryError, match=match):
        _checked(srdf)


def test_the_srdf_of_load_urdf_serves_the_default_model(tmp_path, monkeypatch):
    """Without the SRDF the pair a - c (in collision in every configuration) rejects every
    answer, with a warning saying so; given to load_urdf, the solve's own model leaves it
    unchecked and solves, silently."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    plain = load_urdf(STUCK, tip_link="c")
    target = plain.fk(np.zeros(3))[:3, 3]
    with pytest.warns(GeometryWarning, match="SRDF"):
        assert solve_ik(plain, target, self_collision=True).status == "collides"
    path = tmp_path / "stuck.srdf"
    path.write_text(_srdf(A_C, A_F))
    robot = load_urdf(STUCK, tip_link="c", srdf=path)
    with warnings.catch_warnings():
        warnings.simplefilter("error", GeometryWarning)
        res = solve_ik(robot, target, self_collision=True)
    assert res.status == "solved"
    with pytest.raises(ParameterError, match="is not a file"):
        load_urdf(STUCK, srdf=tmp_path / "missing.srdf")
    with pytest.raises(ParameterError, match="srdf must be"):
        load_urdf(STUCK, srdf=3)


def test_the_command_line_takes_an_srdf(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    urdf, srdf = tmp_path / "stuck.urdf", tmp_path / "stuck.srdf"
    urdf.write_text(STUCK)
    srdf.write_text(_srdf(A_C, A_F))
    argv = ["solve", str(urdf), "--tip", "c", "--target", "0", "0", "0.2", "--self-collision"]
    assert main([*argv, "--srdf", str(srdf)]) == 0
    assert "collision-free" in capsys.readouterr().out
    assert main(["solve", "panda", "--srdf", str(srdf), "--target", "0.4", "0.2", "0.5"]) == 2
    assert "is a catalog robot" in capsys.readouterr().err
