"""moik/_jit.py and its disk cache (moik/_kernel_cache.py): input normalisation, one
compiled version per kernel, the disk cache and the first-compile notice (in fresh
interpreters), a read-only installation."""

import ast
import contextlib
import io
import json
import os
import shutil
import stat
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import moik
from moik._jit import COMPILE_NOTICE, kernel_array
from moik.kinematics import jacobian as jac
from moik.kinematics import rotation_metrics
from moik.kinematics.jacobian import pose_and_jacobian
from moik.kinematics.orientation import orientation_error
from moik.problems import BiObjectiveIK, PoseIK, PositionIK, ik, random_reachable_targets
from moik.robots import fk_kernels, get_robot, trig

# Runs in a fresh interpreter: FK through the kernels, checked against the oracle.
SCRIPT = """
import numpy as np
import moik
from moik.robots import fk_reference, get_robot
robot = get_robot("eosma7")
Q = robot.random_q(70, rng=np.random.default_rng(0))
assert np.allclose(robot.fk(Q), fk_reference(robot, Q), rtol=0, atol=1e-10)
print(moik.__file__)
"""


def test_kernel_array_normalises_only_when_needed():
    good = np.zeros((3, 7))
    assert kernel_array(good) is good
    wide = np.arange(42.0).reshape(3, 14)
    frozen = np.ones((3, 7))
    frozen.setflags(write=False)
    for value in (wide[:, ::2], frozen, np.ones((3, 7), dtype=np.float32), [[1, 2], [3, 4]],
                  np.asfortranarray(np.ones((3, 7)))):
        arr = kernel_array(value)
        assert arr.dtype == np.float64 and arr.flags.c_contiguous and arr.flags.writeable
        np.testing.assert_array_equal(arr, np.asarray(value, dtype=float))


def test_one_compiled_version_per_kernel():
    """Whatever array layout comes in, each public kernel sees one argument type."""
    robot = get_robot("puma560")
    target = random_reachable_targets(robot, 1, seed=0)[0]
    X = robot.random_q(12, rng=np.random.default_rng(0))
    wide = np.zeros((12, 12))
    wide[:, ::2] = X
    frozen = X.copy()
    frozen.setflags(write=False)
    layouts = [X, wide[:, ::2], frozen, X.astype(np.float32), X.tolist(), np.asfortranarray(X)]
    for Q in layouts:
        robot.fk(Q)
        robot.fk(np.asarray(Q)[0])
        robot.fk_position(Q)
        robot.fk_parts(Q)
        robot.frames(Q)
        pose_and_jacobian(robot, Q)
        jac.parts_and_jacobian(robot, Q)
        for problem in (PositionIK(robot, target.position), PoseIK(robot, target),
                        BiObjectiveIK(robot, target, orientation="zyx-euler")):
            problem.evaluate(np.asarray(Q, dtype=float))
        orientation_error(robot.fk_parts(Q)[0], target.rotation, "frobenius")
    kernels = [fk_kernels.fk_poses, fk_kernels.fk_positions, fk_kernels.fk_rotations_positions,
               fk_kernels.fk_frames, fk_kernels.all_finite, fk_kernels.joint_screen,
               jac.poses_and_jacobians,
               jac.parts_and_jacobians, ik.ik_objectives, rotation_metrics.rotation_errors]
    for kernel in kernels:
        assert len(kernel.signatures) == 1, (kernel.py_func.__name__, kernel.signatures)


def _run(env: dict, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", SCRIPT], env=env, cwd=cwd,
                          capture_output=True, text=True, timeout=600)


def _env(**changes) -> dict:
    env = {k: v for k, v in os.environ.items()
           if not k.startswith("NUMBA_") and k not in ("XDG_CACHE_HOME", "PYTHONPATH")}
    env.update(PYTHONDONTWRITEBYTECODE="1", **changes)
    return env


def test_compiles_once_then_loads_from_the_cache(tmp_path):
    """First run: one notice on stderr while numba compiles, cache files written.
    Second run: loaded from the cache, no notice."""
    cache = tmp_path / "cache"
    root = Path(moik.__file__).parent
    env = _env(NUMBA_CACHE_DIR=str(cache), PYTHONPATH=str(root.parent))
    first = _run(env, tmp_path)
    assert first.returncode == 0, first.stderr
    assert first.stdout.strip() == str(root / "__init__.py")
    assert first.stderr.count(COMPILE_NOTICE) == 1
    assert list(cache.rglob("*.nbi"))
    second = _run(env, tmp_path)
    assert second.returncode == 0, second.stderr
    assert COMPILE_NOTICE not in second.stderr


def _read_only(path: Path) -> None:
    for p in [path, *path.rglob("*")]:
        p.chmod(p.stat().st_mode & ~(stat.S_IWUSR | stat.S_IWGRP | stat.S_IWOTH))


def _writable(path: Path) -> None:
    for p in [path, *path.rglob("*")]:
        p.chmod(p.stat().st_mode | stat.S_IWUSR)


def test_read_only_installation_compiles_without_cache(tmp_path):
    """A package copy that cannot hold a cache (read-only, and for root, whose
    writes permissions do not stop, every __pycache__ blocked by a file), a
    read-only home and an unusable NUMBA_CACHE_DIR: import and FK still work."""
    site = tmp_path / "site"
    package = site / "moik"
    shutil.copytree(Path(moik.__file__).parent, package,
                    ignore=shutil.ignore_patterns("__pycache__"))
    for folder in [package, *[p for p in package.rglob("*") if p.is_dir()]]:
        (folder / "__pycache__").write_text("not a folder")
    home = tmp_path / "home"
    home.mkdir()
    (home / ".cache").write_text("not a folder")
    blocked = tmp_path / "blocked"
    blocked.write_text("not a folder")
    env = _env(PYTHONPATH=str(site), HOME=str(home), NUMBA_CACHE_DIR=str(blocked / "numba"),
               XDG_CACHE_HOME=str(blocked / "xdg"))
    _read_only(site)
    _read_only(home)
    try:
        out = _run(env, tmp_path)
    finally:
        _writable(site)
        _writable(home)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == str(package / "__init__.py")
    assert out.stderr.count(COMPILE_NOTICE) == 1
    assert not list(tmp_path.rglob("*.nbi"))


@pytest.mark.parametrize("name", ["fk_poses", "chain_block", "sin_cos"])
def test_kernels_are_numba_dispatchers(name):
    kernel = getattr(trig if name == "sin_cos" else fk_kernels, name)
    assert hasattr(kernel, "py_func") and hasattr(kernel, "signatures")


# --- the self-healing cache (issue 27, items 1 and 2) ---

def _checked_file(tmp_path: Path):
    from moik._kernel_cache import CheckedCacheFile
    return CheckedCacheFile(cache_path=str(tmp_path), filename_base="kernel-1.py311",
                             source_stamp=(1.0, 2))


@pytest.mark.parametrize("damage", ["truncate", "empty", "flip", "foreign"])
@pytest.mark.parametrize("which", ["index", "data"])
def test_a_damaged_cache_file_is_discarded_unread(tmp_path, damage, which):
    """Index and data files carry a digest: a damaged one is warned about, removed and
    reads as absent (numba then compiles); it never reaches pickle or LLVM."""
    from moik import _kernel_cache
    cache = _checked_file(tmp_path)
    cache.save(("sig", "arch"), {"payload": list(range(100))})
    assert cache.load(("sig", "arch")) == {"payload": list(range(100))}
    path = Path(cache._index_path if which == "index" else cache._data_path("kernel-1.py311.1.nbc"))
    raw = bytearray(path.read_bytes())
    if damage == "truncate":
        raw = raw[: len(raw) // 2]
    elif damage == "empty":
        raw = bytearray()
    elif damage == "flip":
        raw[len(raw) - 7] ^= 0x10
    else:  # intact digest over bytes that are no pickle
        body = b"not a pickle at all"
        raw = bytearray(_kernel_cache.MAGIC + __import__("hashlib").sha256(body).digest() + body)
    path.write_bytes(bytes(raw))
    _kernel_cache.warned.discard("damaged")
    with pytest.warns(moik.exceptions.CacheWarning, match="discarded a damaged kernel cache"):
        assert cache.load(("sig", "arch")) is None
    assert not path.exists()
    cache.save(("sig", "arch"), {"payload": [1]})  # the save after the recompilation heals it
    assert cache.load(("sig", "arch")) == {"payload": [1]}


def test_a_plain_numba_cache_file_is_overwritten_quietly(tmp_path, recwarn):
    """A cache file in numba's own format (written before the digests) is no damage."""
    from numba.core.caching import IndexDataCacheFile
    plain = IndexDataCacheFile(cache_path=str(tmp_path), filename_base="kernel-1.py311",
                               source_stamp=(1.0, 2))
    plain.save(("sig", "arch"), {"payload": 1})
    cache = _checked_file(tmp_path)
    assert cache.load(("sig", "arch")) is None
    cache.save(("sig", "arch"), {"payload": 2})
    assert cache.load(("sig", "arch")) == {"payload": 2}
    assert not [w for w in recwarn if issubclass(w.category, moik.exceptions.CacheWarning)]


# Runs in a fresh interpreter after damaging one cache file of a complete cache.
_HEAL = """
import sys
from pathlib import Path
name, suffix, damage = sys.argv[1:4]
path = next(Path(sys.argv[4]).rglob(f"fk_kernels.{name}-*{suffix}"))
raw = bytearray(path.read_bytes())
if damage == "truncate":
    raw = raw[: len(raw) // 2]
elif damage == "empty":
    raw = bytearray()
else:
    i = int(damage)
    raw[i] ^= 1 << (i % 8)
path.write_bytes(bytes(raw))
""" + SCRIPT


@pytest.fixture(scope="module")
def built_cache(tmp_path_factory):
    """A complete kernel cache of the FK script, built once."""
    tmp = tmp_path_factory.mktemp("built")
    root = Path(moik.__file__).parent
    out = _run(_env(NUMBA_CACHE_DIR=str(tmp / "cache"), PYTHONPATH=str(root.parent)), tmp)
    assert out.returncode == 0, out.stderr
    return tmp / "cache"


@pytest.mark.parametrize("name, suffix, damage", [
    ("joint_screen", ".nbi", "truncate"), ("joint_screen", ".nbi", "empty"),
    ("joint_screen", ".nbi", "300"), ("joint_screen", ".nbc", "truncate"),
    ("joint_screen", ".nbc", "empty"), ("joint_screen", ".nbc", "2000"),
    ("fk_poses", ".nbc", "100"),  # numba aborted the process (SIGABRT) on this flip
])
def test_a_damaged_cache_heals_in_the_next_process(tmp_path, built_cache, name, suffix, damage):
    """Before: EOFError, UnpicklingError or SIGABRT in every later process. Now the
    process that finds the damage warns, recompiles that kernel and rewrites its file."""
    from moik import _kernel_cache
    cache = tmp_path / "cache"
    shutil.copytree(built_cache, cache)
    root = Path(moik.__file__).parent
    env = _env(NUMBA_CACHE_DIR=str(cache), PYTHONPATH=str(root.parent))
    out = subprocess.run([sys.executable, "-c", _HEAL, name, suffix, damage, str(cache)],
                         env=env, cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    assert "CacheWarning: moik: discarded a damaged kernel cache file" in out.stderr
    assert "Traceback" not in out.stderr
    head = len(_kernel_cache.MAGIC) + 32
    for path in cache.rglob(f"fk_kernels.{name}-*.nb[ic]"):  # rewritten, intact
        raw = path.read_bytes()
        assert raw.startswith(_kernel_cache.MAGIC)
        digest = raw[len(_kernel_cache.MAGIC):head]
        assert __import__("hashlib").sha256(raw[head:]).digest() == digest


_FULL_DISK = """
import errno
from moik import _kernel_cache
def full(self, filepath):
    raise OSError(errno.ENOSPC, "No space left on device", filepath)
_kernel_cache.CheckedCacheFile._open_for_write = full
""" + SCRIPT


def test_a_cache_that_cannot_be_written_does_not_fail_the_computation(tmp_path):
    """Every cache write fails with ENOSPC: one warning, correct results, no traceback."""
    root = Path(moik.__file__).parent
    env = _env(NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=str(root.parent))
    out = subprocess.run([sys.executable, "-c", _FULL_DISK], env=env, cwd=tmp_path,
                         capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == str(root / "__init__.py")
    assert out.stderr.count("CacheWarning: moik: cannot write the kernel cache") == 1
    assert "No space left on device" in out.stderr and "Traceback" not in out.stderr


def test_a_full_tmpfs_cache_does_not_fail_the_computation(tmp_path):
    """The real thing: NUMBA_CACHE_DIR on a 64 KiB tmpfs that fills up mid-save."""
    mount = tmp_path / "small"
    mount.mkdir()
    made = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", str(mount)],
                          capture_output=True, text=True)
    if made.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {made.stderr.strip()}")
    try:
        root = Path(moik.__file__).parent
        out = _run(_env(NUMBA_CACHE_DIR=str(mount), PYTHONPATH=str(root.parent)), tmp_path)
    finally:
        subprocess.run(["umount", str(mount)], capture_output=True)
    assert out.returncode == 0, out.stderr
    assert out.stderr.count("CacheWarning: moik: cannot write the kernel cache") == 1
    assert "Traceback" not in out.stderr


def test_forty_single_bit_flips_of_real_cache_files_are_all_caught(tmp_path, built_cache):
    """Every flipped bit of a real index or data file is caught before numba reads it."""
    from moik import _kernel_cache
    rng = np.random.default_rng(40)
    index = next(built_cache.rglob("fk_kernels.fk_poses-*.nbi"))
    data = next(built_cache.rglob("fk_kernels.fk_poses-*.1.nbc"))
    base = index.name[: -len(".nbi")]
    for k in range(40):
        original = (index if k % 2 else data).read_bytes()
        folder = tmp_path / str(k)
        folder.mkdir()
        cache = _kernel_cache.CheckedCacheFile(cache_path=str(folder), filename_base=base,
                                       source_stamp=None)
        raw = bytearray(original)
        bit = int(rng.integers(8 * len(raw)))
        raw[bit // 8] ^= 1 << (bit % 8)
        target = folder / (index if k % 2 else data).name
        target.write_bytes(bytes(raw))
        _kernel_cache.warned.discard("damaged")
        with pytest.warns(moik.exceptions.CacheWarning, match="discarded a damaged"):
            got = cache._load_index() if k % 2 else cache._load_data(data.name)
        assert got in ({}, None) and not target.exists(), (k, bit)


def test_a_long_compilation_prints_progress_lines(monkeypatch, capsys):
    """The notice once, then whole progress lines (kernels so far, seconds) at most every
    PROGRESS_EVERY seconds; events of functions that are not moik kernels are ignored."""
    from numba.core import event

    import moik._jit as jit_module

    kernel = next(iter(jit_module._kernels))
    monkeypatch.setattr(jit_module, "_notice", {"printed": False})
    monkeypatch.setattr(jit_module, "_compiled", {"kernels": 0, "since": 0.0, "last": 0.0,
                                                  "seconds": 0.0, "depth": 0, "began": 0.0})
    listener = jit_module._CompileNotice()

    class Dispatcher:
        py_func = kernel

    def fire(status, func=Dispatcher):
        ev = event.Event(kind="numba:compile", status=status, data={"dispatcher": func})
        (listener.on_start if status == event.EventStatus.START else listener.on_end)(ev)

    monkeypatch.setattr(jit_module, "PROGRESS_EVERY", 1e9)
    fire(event.EventStatus.START)
    fire(event.EventStatus.END)
    assert capsys.readouterr().err == jit_module.COMPILE_NOTICE + "\n"  # quick: no progress line
    monkeypatch.setattr(jit_module, "PROGRESS_EVERY", 0.0)
    fire(event.EventStatus.START)
    fire(event.EventStatus.END)

    class Other:
        py_func = len

    fire(event.EventStatus.START, Other)
    fire(event.EventStatus.END, Other)
    err = capsys.readouterr().err
    assert err.startswith("  ... 2 kernels compiled so far (") and err.count("\n") == 1
    assert jit_module.compile_count() == 2


def test_compile_seconds_count_nested_compilations_once(monkeypatch):
    """A kernel compiling the kernels it calls: the seconds from the outer start to the
    outer end, once; time waited for a background child is added."""
    from numba.core import event

    import moik._jit as jit_module

    kernel = next(iter(jit_module._kernels))
    monkeypatch.setattr(jit_module, "_notice", {"printed": True})
    monkeypatch.setattr(jit_module, "_compiled", {"kernels": 0, "since": 0.0, "last": 0.0,
                                                  "seconds": 0.0, "depth": 0, "began": 0.0})
    clock = iter([10.0, 12.0, 13.5])  # outer start, inner end, outer end
    monkeypatch.setattr(jit_module.time, "perf_counter", lambda: next(clock))
    listener = jit_module._CompileNotice()

    class Dispatcher:
        py_func = kernel

    def fire(status):
        ev = event.Event(kind="numba:compile", status=status, data={"dispatcher": Dispatcher})
        (listener.on_start if status == event.EventStatus.START else listener.on_end)(ev)

    monkeypatch.setattr(jit_module, "PROGRESS_EVERY", 1e9)
    fire(event.EventStatus.START)  # 10.0
    fire(event.EventStatus.START)  # nested: no clock read
    fire(event.EventStatus.END)  # 12.0
    fire(event.EventStatus.END)  # 13.5
    assert jit_module.compile_count() == 2 and jit_module.compile_seconds() == 3.5
    jit_module.add_compile_seconds(0.5)
    assert jit_module.compile_seconds() == 4.0


def test_is_cached_says_which_kernels_the_cache_holds(built_cache, tmp_path):
    """The FK script's cache holds fk_poses (the kernel robot.fk calls), not a front kernel."""
    root = Path(moik.__file__).parent
    script = ("from moik._jit import is_cached\n"
              "from moik.robots.fk_kernels import fk_poses\n"
              "from moik.algorithms.archive.fronts import front_mask_2d\n"
              "print(is_cached(fk_poses), is_cached(front_mask_2d))\n")
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                         env=_env(NUMBA_CACHE_DIR=str(built_cache), PYTHONPATH=str(root.parent)),
                         cwd=tmp_path, timeout=600)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["True", "False"]


# Runs in a fresh interpreter: each StructRef of moik (IK context, collision set, generator
# handle; the IK objectives through the EOSMA run) and the solver's compiled paths.
_PYTHON_KERNELS = """
import json, numpy as np, moik
from pymoo.optimize import minimize
from moik.algorithms import get_algorithm
from moik.problems import PositionIK
robot = moik.get_robot("iiwa14")
T = robot.fk(np.full(7, 0.3))
one = moik.solve_ik(robot, T, n_solutions=2, seed=3)
batch = moik.solve_ik_batch(robot, np.stack([T, robot.fk(np.full(7, -0.4))]), seed=1)
free = moik.solve_ik(robot, T, self_collision=True, seed=2)
run = minimize(PositionIK(robot, T[:3, 3]), get_algorithm("eosma"), ("n_gen", 3), seed=1)
print(json.dumps([one.status, np.asarray(one.q).tolist(), batch.status.tolist(),
                  batch.q.tolist(), free.status, free.min_distance, run.X.tolist(),
                  run.F.tolist()]))
"""


def test_kernels_run_as_python_under_numba_disable_jit(tmp_path):
    """numba's debugging mode runs every kernel as Python. Before: ``RecursionError`` at
    the first IK context (numba's StructRef constructor calls itself there, numba issue
    #7117). Now the same answers, bit for bit, as the compiled kernels give."""
    root = str(Path(moik.__file__).parent.parent)
    out = subprocess.run([sys.executable, "-c", _PYTHON_KERNELS], capture_output=True,
                         text=True, env=_env(NUMBA_DISABLE_JIT="1", PYTHONPATH=root),
                         cwd=tmp_path)
    assert out.returncode == 0, out.stderr[-3000:]
    python = json.loads(out.stdout)
    assert python[0] == "solved" and python[2] == ["solved", "solved"]
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):  # the compiled kernels, in this process
        exec(_PYTHON_KERNELS, {})
    assert python == json.loads(printed.getvalue())


def _jit_decorated(node) -> str | None:
    """'inline' for ``@jit(inline=True)``, 'jit' for ``@jit``, else None."""
    for d in node.decorator_list:
        if isinstance(d, ast.Name) and d.id == "jit":
            return "jit"
        if (isinstance(d, ast.Call) and isinstance(d.func, ast.Name) and d.func.id == "jit"
                and any(k.arg == "inline" and getattr(k.value, "value", False)
                        for k in d.keywords)):
            return "inline"
    return None


def _is_none_branch(statement, arguments) -> bool:
    """``if <argument> is None: ... return ...``: numba prunes by the argument's type before
    it inlines, so a compiled version holds either this branch or what follows it."""
    test = getattr(statement, "test", None)
    return (isinstance(statement, ast.If) and isinstance(test, ast.Compare)
            and isinstance(test.left, ast.Name) and test.left.id in arguments
            and isinstance(test.ops[0], ast.Is) and len(test.comparators) == 1
            and getattr(test.comparators[0], "value", 0) is None
            and isinstance(statement.body[-1], ast.Return) and not statement.orelse)


def _call_sites(statements, name: str, arguments) -> int:
    """Call sites of ``name`` in one compiled version of ``statements`` (the most over the
    versions that numba's pruning of ``is None`` branches gives)."""
    for k, statement in enumerate(statements):
        if _is_none_branch(statement, arguments):
            before = _call_sites(statements[:k], name, arguments)
            return before + max(_call_sites(statement.body, name, arguments),
                                _call_sites(statements[k + 1:], name, arguments))
    return sum(isinstance(c, ast.Call) and isinstance(c.func, ast.Name) and c.func.id == name
               for statement in statements for c in ast.walk(statement))


def test_inlined_helpers_have_one_call_site_in_each_kernel():
    """``@jit(inline=True)`` (moik._jit.jit) is for helpers called once in each kernel that
    calls them: at several sites numba would type and compile a copy per site. A kernel
    that runs a helper in an ``if argument is None:`` branch that returns and again after
    it compiles one of the two per version (numba prunes the other by the argument's type
    before it inlines)."""
    sources = Path(moik.__file__).parent.rglob("*.py")
    trees = [ast.parse(path.read_text()) for path in sources]
    functions = [f for tree in trees for f in ast.walk(tree) if isinstance(f, ast.FunctionDef)]
    inlined = {f.name for f in functions if _jit_decorated(f) == "inline"}
    assert {"weight_arguments", "determinant", "ieee_divide", "lm_start"} <= inlined
    for kernel in (f for f in functions if _jit_decorated(f)):
        arguments = {a.arg for a in kernel.args.args}
        for name in inlined:
            sites = _call_sites(kernel.body, name, arguments)
            assert sites <= 1, (kernel.name, name, sites)


def test_call_sites_count_one_version_of_a_none_branch():
    """The counting above: sites in a returning ``is None`` branch and after it are
    alternatives; sites before it, or in a branch on another test, add up."""
    kernel = ast.parse(
        "def k(a, b):\n"
        "    f(a)\n"
        "    if b is None:\n"
        "        f(b)\n"
        "        return 0\n"
        "    f(a)\n"
        "    if a > 0:\n"
        "        f(a)\n").body[0]
    assert _call_sites(kernel.body, "f", {"a", "b"}) == 1 + max(1, 2)
    assert _call_sites(kernel.body, "f", {"a"}) == 4  # b is not an argument: no pruning


_INLINED_HELPER = """
import numpy as np
from moik.kinematics import criteria_kernels, jacobian
from moik.kinematics.criteria import manipulability
from moik.robots import get_robot

robot = get_robot("iiwa14")
Q = robot.random_q(3, rng=np.random.default_rng(0))
helper = criteria_kernels.determinant
assert helper.targetoptions.get("inline") == "always"
values = manipulability(robot)(Q)
assert not helper.overloads  # compiled within manipulabilities only
J = jacobian.parts_and_jacobian(robot, Q)[2]
A = np.ascontiguousarray(J[0] @ J[0].T)
assert abs(np.sqrt(helper(A)) - values[0]) <= 1e-9 * abs(values[0])
assert helper.overloads  # its own kernel now, called from Python
"""


def test_an_inlined_helper_compiles_only_inside_its_caller():
    """Compiling its caller compiles no module of the helper's own (its dispatcher stays
    empty); called from Python, the helper compiles as a kernel and gives the same value.
    In a fresh interpreter: a test that called the helper before in this one would have
    given it a kernel of its own."""
    out = subprocess.run([sys.executable, "-c", _INLINED_HELPER], capture_output=True,
                         text=True, timeout=600)
    assert out.returncode == 0, out.stderr


_SWAP = """
import shutil, sys
from pathlib import Path
cache = Path(sys.argv[1])
victim = next(cache.rglob("fk_kernels.joint_screen-*.nbc"))
other = next(cache.rglob("fk_kernels.fk_poses-*.nbc"))
shutil.copyfile(other, victim)  # intact, with its own valid digest: another kernel's code
""" + SCRIPT


def test_an_intact_entry_of_another_kernel_is_discarded_and_recompiled(tmp_path, built_cache):
    """Before: a data file that is whole (valid digest) but holds another kernel's code
    loaded without complaint and failed, or computed the wrong thing, when called."""
    cache = tmp_path / "cache"
    shutil.copytree(built_cache, cache)
    root = Path(moik.__file__).parent
    env = _env(NUMBA_CACHE_DIR=str(cache), PYTHONPATH=str(root.parent))
    out = subprocess.run([sys.executable, "-c", _SWAP, str(cache)], env=env, cwd=tmp_path,
                         capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    assert "discarded a kernel cache entry of" in out.stderr and "holds the code of" in out.stderr
    assert "Traceback" not in out.stderr
