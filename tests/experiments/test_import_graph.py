"""No import cycle between moik.experiments modules, and no function-local import to dodge one.

Read from the source with :mod:`ast`, so a cycle hidden behind an import inside a
function counts as well. Imports inside functions are allowed only for the heavy
or optional libraries that only one code path needs (:data:`LAZY`).
"""

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[2] / "moik" / "experiments"

LAZY = {"distributed", "tqdm", "matplotlib", "matplotlib.pyplot", "pandas"}
"""Dask (optional extra, only ``--dask-scheduler``), tqdm (optional), matplotlib (only drawing),
pandas (optional, only ``load_results(..., as_frame=True)``)."""


def _modules() -> dict[str, Path]:
    out = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(PACKAGE.parents[1]).with_suffix("").parts
        out[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return out


def _imported(node: ast.AST, module: str, is_package: bool) -> list[str]:
    if isinstance(node, ast.Import):
        return [a.name for a in node.names]
    base = node.module or ""
    if node.level:
        parts = module.split(".")[: None if is_package else -1]
        parts = parts[: len(parts) - node.level + 1]
        base = ".".join(parts + ([base] if base else []))
    return [base] + [f"{base}.{a.name}" for a in node.names]


def _graph() -> tuple[dict[str, set[str]], list[tuple[str, int, list[str]]]]:
    modules = _modules()
    graph, local = {}, []
    for name, path in modules.items():
        tree = ast.parse(path.read_text())
        top = {id(n) for n in tree.body}
        graph[name] = set()
        for node in ast.walk(tree):
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                names = _imported(node, name, path.name == "__init__.py")
                graph[name] |= {n for n in names if n in modules and n != name}
                if id(node) not in top:
                    local.append((name, node.lineno, names))
    return graph, local


def _cycle(graph: dict[str, set[str]]) -> list[str] | None:
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(v: str) -> list[str] | None:
        state[v] = 1
        stack.append(v)
        for w in sorted(graph[v]):
            if state.get(w) == 1:
                return stack[stack.index(w):] + [w]
            if w not in state and (found := visit(w)):
                return found
        state[v] = 2
        stack.pop()
        return None

    for v in sorted(graph):
        if v not in state and (found := visit(v)):
            return found
    return None


def test_no_import_cycle_between_experiments_modules():
    graph, _ = _graph()
    assert "moik.experiments.kinds.ik" in graph and graph["moik.experiments.kinds"]
    assert _cycle(graph) is None


def test_function_local_imports_are_only_the_lazy_libraries():
    _, local = _graph()
    assert [(m, line, names) for m, line, names in local if names[0] not in LAZY] == []


def test_the_cycle_finder_finds_one():
    assert _cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert _cycle({"a": {"b"}, "b": set()}) is None
