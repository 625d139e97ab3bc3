"""results.jsonl lines: trial records and malformed lines (named by number, skipped)."""

import json

from moik.experiments.records import read_lines, record_problem

GOOD = {"trial": "eosma/0/0", "status": "ok", "algorithm": "eosma", "target": 0, "run": 0}


def test_malformed_lines_are_named_not_raised(tmp_path):
    path = tmp_path / "results.jsonl"
    bad = [b"{}", b"[1,2,3]", b'{"trial": null}', b"", b"not json", b'"text"',
           json.dumps({**GOOD, "run": True}).encode(), json.dumps({**GOOD, "target": "0"}).encode()]
    path.write_bytes(b"\n".join([json.dumps(GOOD).encode(), *bad, json.dumps(GOOD).encode()])
                     + b'\n{"trial": "torn')
    lines = read_lines(path)
    assert lines.records == [GOOD, GOOD] and lines.torn_tail
    assert [n for n, _ in lines.malformed] == list(range(2, 10))
    whys = dict(lines.malformed)
    assert whys[2] == "no 'trial' field" and whys[3] == "a JSON list, not an object"
    assert whys[4] == "'trial' is None, expected a str" and whys[5] == "an empty line"
    assert whys[6].startswith("not JSON") and whys[8] == "'run' is True, expected a int"
    text = lines.describe(path, shown=2)
    assert text.startswith(f"{path}: skipped 8 malformed line(s)") and "and 6 more" in text


def test_a_missing_file_has_no_lines(tmp_path):
    lines = read_lines(tmp_path / "none.jsonl")
    assert lines.records == [] and lines.malformed == [] and not lines.torn_tail
    assert record_problem(GOOD) is None


def test_a_trial_id_must_be_its_algorithm_target_and_run():
    """Before: a line whose algorithm contradicted its trial id counted as finished and was
    silently left out of the report's table."""
    assert record_problem({**GOOD, "algorithm": "other"}) == (
        "trial 'eosma/0/0' does not match its algorithm, target and run (other/0/0)")
    assert "does not match" in record_problem({**GOOD, "run": 1})
    assert "does not match" in record_problem({**GOOD, "target": 2})
    labelled = {**GOOD, "trial": "eosma-fast/3/1", "algorithm": "eosma-fast", "target": 3,
                "run": 1}
    assert record_problem(labelled) is None
