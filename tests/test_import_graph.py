"""The package's import graph (design.md, Layout): the dependency direction holds,
there is no import cycle between moik modules, and no function-local import
hides one. Read from the source with :mod:`ast` (imports inside functions count)."""

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1] / "moik"
ORDER = ("exceptions", "_toml", "_validate", "_paths", "_kernel_cache", "_jit",
         "_version", "_lazy", "robots", "kinematics", "collision", "fronts", "problems")
INDEPENDENT = {"algorithms": {"algorithms", "exceptions", "_validate", "_jit"},
               "metrics": {"metrics", "exceptions", "_validate", "_jit", "_lazy"}}
LAZY = {("cli", "moik.plotting"),  # matplotlib only when a plot is asked for
        ("cli", "moik.solver")}  # the parser reads the solver's defaults only for `solve --help`


def _graph():
    modules = {}
    for path in ROOT.rglob("*.py"):
        parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        modules[".".join(parts)] = path

    def resolve(name):
        while name and name not in modules:
            name = name.rsplit(".", 1)[0] if "." in name else ""
        return name

    edges, local = {m: set() for m in modules}, []
    for mod, path in modules.items():
        tree = ast.parse(path.read_text())
        functions = [f for f in ast.walk(tree)
                     if isinstance(f, ast.FunctionDef | ast.AsyncFunctionDef)]
        inner = {id(n) for f in functions for n in ast.walk(f)
                 if isinstance(n, ast.Import | ast.ImportFrom)}
        for node in ast.walk(tree):
            names = []
            from_moik = isinstance(node, ast.ImportFrom) and node.level == 0 and (
                node.module or "").startswith("moik")
            if from_moik:
                subs = [f"{node.module}.{a.name}" for a in node.names
                        if f"{node.module}.{a.name}" in modules]
                names = subs if len(subs) == len(node.names) else [node.module, *subs]
            elif isinstance(node, ast.Import):
                names = [a.name for a in node.names if a.name.startswith("moik")]
            for target in filter(None, (resolve(n) for n in names)):
                if target != mod:
                    edges[mod].add(target)
                    if id(node) in inner:
                        local.append((mod, target))
    return edges, local


def _area(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else ""


def test_dependency_direction():
    edges, _ = _graph()
    wrong = []
    for mod, targets in edges.items():
        a = _area(mod)
        for t in targets:
            b = _area(t)
            if a in ORDER and b in ORDER and ORDER.index(b) > ORDER.index(a):
                wrong.append((mod, t))
            if a in INDEPENDENT and b not in INDEPENDENT[a]:
                wrong.append((mod, t))
            if a in ORDER and b not in ORDER:
                wrong.append((mod, t))
    assert not wrong


def test_only_the_command_line_imports_the_warmup():
    """moik.warmup (what compiles ahead of a first use) sits above the solver, the problems
    and the algorithms, whose public functions it calls; of moik, only the command line
    (``moik compile``, ``moik solve --pareto``) imports it."""
    edges, _ = _graph()
    users = {mod for mod, targets in edges.items()
             if _area(mod) != "warmup" and any(_area(t) == "warmup" for t in targets)}
    assert users and {_area(mod) for mod in users} == {"cli"}, users


def test_no_import_cycle_and_no_hidden_local_import():
    edges, local = _graph()
    assert {(_area(m) or m.split(".")[-1], t) for m, t in local} <= LAZY, local
    index, low, stack, on, cycles, counter = {}, {}, [], set(), [], [0]

    def visit(v):  # Tarjan's strongly connected components
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                cycles.append(sorted(comp))

    for v in edges:
        if v not in index:
            visit(v)
    assert not cycles
