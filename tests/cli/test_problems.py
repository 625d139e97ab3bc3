"""``moik problems``: the IK benchmark registry on the command line."""

import json

from moik.cli import main
from moik.problems import available


def test_problems_lists_the_registry(capsys):
    assert main(["problems"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0].split()[:3] == ["name", "robot", "obj"]
    rows = {line.split()[0]: line.split() for line in out[1:]}
    assert list(rows) == available()
    assert rows["eosma-p1"][1:] == ["eosma7-m", "2", "eosma-euler", "75", "no"]
    assert rows["eosma-p2"][-2:] == ["1", "yes"]
    assert rows["eosma-p1-motion"][2:] == ["3", "eosma-euler", "-", "-"]


def test_problems_json(capsys):
    assert main(["problems", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    by_name = {p["name"]: p for p in data["problems"]}
    assert set(by_name) == set(available())
    assert by_name["sawyer7-reachable"]["reachable"] is True
    assert by_name["sawyer7-unreachable"]["front_points"] > 1
