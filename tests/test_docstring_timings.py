"""At most ten measured times are typed in moik's docstrings: measurements and their
history live in docs/performance.md and docs/results/ (where a benchmark regenerates
them), not in the code's prose, where they go stale."""

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1] / "moik"
MOST = 10
# a number (or a range) with a unit of time: 5 us, 0.2 s, 7-16 us, 12 ms, 6 ns, 3 seconds;
# not maths (10 s^3, 60 s - 180 s^2) nor "s.t."
TIMING = re.compile(r"(?<![\w.^])\d+(?:\.\d+)?(?:\s*(?:-|to)\s*\d+(?:\.\d+)?)?\s*"
                    r"(?:ms|us|µs|ns|s|seconds?|minutes?)(?![\w^(])(?!\.t\b)(?!\s*[-+]\s*\d)")


def timings() -> list[str]:
    """``path:line: timing`` for every timing in a docstring (any string statement) of moik."""
    found = []
    for path in sorted(ROOT.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant)
                    and isinstance(node.value.value, str)):
                found += [f"{path.relative_to(ROOT.parent)}:{node.lineno}: {m.group(0)}"
                          for m in TIMING.finditer(node.value.value)]
    return found


def test_the_pattern_finds_timings_and_skips_maths():
    text = "costs 7-16 us, 0.2 s, 12 ms and 6 ns; q0 + dq (10 s^3 - 15 s^4); min f s.t. g"
    assert [m.group(0) for m in TIMING.finditer(text)] == ["7-16 us", "0.2 s", "12 ms", "6 ns"]


def test_at_most_ten_timings_in_moik_docstrings():
    found = timings()
    assert len(found) <= MOST, "\n".join(found)
