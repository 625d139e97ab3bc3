"""The compiled contract (docs/design.md): every compiled kernel outside moik/algorithms takes
at most 6 arguments (the arm as a ChainModel, the target as a TargetSpec, plus arrays), and no
solver module reaches into numba's dispatchers."""

import ast
from pathlib import Path

import moik

ROOT = Path(moik.__file__).parent
MAX_ARGUMENTS = 6


def _kernels():
    for path in sorted(ROOT.rglob("*.py")):
        if "algorithms" in path.relative_to(ROOT).parts:
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.FunctionDef) and any(
                    "jit" in ast.unparse(d) for d in node.decorator_list):
                yield path.relative_to(ROOT), node


def test_the_scan_finds_the_kernels():
    names = {node.name for _, node in _kernels()}
    assert {"ik_objectives", "min_distances", "pose_errors", "run_starts"} <= names


def test_no_kernel_outside_the_algorithms_takes_more_than_six_arguments():
    wide = [f"{path}:{node.lineno} {node.name} ({len(node.args.args)})"
            for path, node in _kernels() if len(node.args.args) > MAX_ARGUMENTS]
    assert not wide, wide
