"""Start-up time: a fresh process importing moik and solving one pose, beside numba's floor;
the ``moik`` command's ``--help`` and ``robots``; cold first solves (empty kernel cache).

Each sample is a new Python process (kernels already cached on disk: run any solve once
before). ``floor`` imports numpy and numba and calls one cached kernel, the least any
numba-based solver pays (numba's first call loads its registries, which import
scipy.linalg); ``moik`` imports moik and solves a Puma 560 pose. Samples interleave the
two; medians are printed. Cold start (no kernel cache): ``--cold`` also times first
uses with an empty NUMBA_CACHE_DIR (below).

``moik --help`` and ``moik robots`` (goal <= 0.3 s warm) are timed as fresh processes,
interleaved with the others. ``--cold`` times, each in a fresh process with its own empty
NUMBA_CACHE_DIR, a first ``solve`` (goal <= 10 s), a first ``solve --pareto`` (goal
<= 10 s) and a first unreachable solve (wall and CPU seconds): ``--cold-n`` samples of
each (default 5), interleaved; medians and the range of the wall seconds.

This machine's speed can drift by a third within minutes, so a cold time alone says
little about another machine. ``--baseline REV`` also times each cold first use at
another commit (``git archive REV``, imported through ``PYTHONPATH``, the same Python
and libraries), each of its samples right after the current one: the median ratio of
the pairs carries over to a machine where the baseline's time is known (the issue that
set the goals measured its start commit there). ``--without-background`` times each cold
first use with ``MOIK_BACKGROUND_COMPILE=1`` (a background compile wherever one applies,
even on a busy machine) and, each right after, with ``MOIK_BACKGROUND_COMPILE=0`` (none:
the process compiles every kernel itself), and prints the ratios of the pairs: what the
background compiles save.

``--first-runs`` times only what a newcomer runs first (:data:`FIRST_RUNS`: the README's
main job, a first ``--pareto`` solve, a first plain and a first collision-aware solve
of panda and their ratio, ``moik compile``), each with an
empty kernel cache; its table (docs/results/first-runs.txt) is the one the README's
first-run times are generated from (``python tests/docs_blocks.py --update README.md``).

Run: python benchmarks/startup.py [--n 15] [--cold] [--cold-n 5] [--baseline REV]
[--without-background] [--first-runs] [--out FILE] (``--out`` also writes the printed table
to FILE, e.g. docs/results/startup.txt, which docs/performance.md links to).
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np
from _output import OUT_HELP, table_output

FLOOR = ("import numpy as np, numba\n"
         "@numba.njit(cache=True)\n"
         "def f(x):\n"
         "    return x + 1.0\n"
         "f(np.zeros(3))\n")  # run from a file: numba caches only functions with a source file
MOIK = ("import numpy as np, moik\n"
        "T = np.array([[1, 0, 0, 0.4], [0, 1, 0, 0.2], [0, 0, 1, 0.3], [0, 0, 0, 1.0]])\n"
        "assert moik.solve_ik(moik.get_robot('puma560'), T).success\n")


CLI = ("import sys\nfrom moik.cli import main\n"
       "if __name__ == '__main__':  # moik compile's worker processes import this file\n"
       "    sys.exit(main(sys.argv[1:]))\n")
COLD = {  # the command lines of the cold first uses, and their goals (s)
    "first solve": (["solve", "puma560", "--target", "0.4", "0.2", "0.3"], 10.0),
    "first solve --pareto": (["solve", "iiwa14", "--target", "0.4", "0.2", "0.5", "--pareto",
                              "manipulability,limit_margin", "--pareto-size", "5"], 10.0),
    "first unreachable solve": (["solve", "puma560", "--target", "2", "0", "0"], 10.0),
}

FIRST_RUNS = {  # what a newcomer runs first, each with an empty kernel cache (--first-runs)
    "the README's main job (moik solve eosma7 ... --n-solutions 3)":
        ["solve", "eosma7", "--target", "-24.748737", "100.961941", "50", "--euler", "135",
         "0", "-90", "--deg", "--n-solutions", "3"],
    "a first --pareto solve (moik solve iiwa14 ... --pareto)": COLD["first solve --pareto"][0],
    "a first plain solve of the same arm (moik solve panda ...)":
        ["solve", "panda", "--target", "0.4", "0.2", "0.5"],
    "a first collision-aware solve (moik solve panda ... --self-collision)":
        ["solve", "panda", "--target", "0.4", "0.2", "0.5", "--self-collision"],
    "moik compile (every kernel, once)": ["compile"],
}

SAME_ARM = tuple(what for what in FIRST_RUNS if "moik solve panda" in what)
"""The first plain and collision-aware solves of one arm (issue 39: aware <= 1.5 x plain)."""

# the cold times of commit 62ac347 on the machine that set the goals (the issue that set
# them measured its first --pareto solve there: 20.3 s); with --baseline 62ac347 the ratio
# of the pairs gives the current time on that machine
GOAL_MACHINE = ("62ac347", {"first solve --pareto": 20.3})

SCRIPTS = tempfile.mkdtemp(prefix="moik-startup-")


def wall(code: str, env: dict | None = None, args: list[str] | None = None,
         check: bool = True) -> tuple[float, float]:
    """Wall and child CPU seconds of one fresh process running ``code`` (from a file)."""
    path = os.path.join(SCRIPTS, f"s{abs(hash(code))}.py")
    if not os.path.exists(path):
        with open(path, "w") as f:
            f.write(code)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, path, *(args or [])], check=check, env=env,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   cwd=SCRIPTS)  # no moik in the working folder (a baseline's children)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return time.perf_counter() - t0, cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=15, help="samples of each")
    parser.add_argument("--cold", action="store_true", help="also time the cold first uses")
    parser.add_argument("--cold-n", type=int, default=5,
                        help="samples of each cold first use (interleaved), default 5")
    parser.add_argument("--baseline", metavar="REV",
                        help="with --cold: also time the cold first uses at commit REV, "
                             "interleaved, and print the ratios")
    parser.add_argument("--without-background", action="store_true",
                        help="with --cold: also time the cold first uses without background "
                             "compiles (MOIK_BACKGROUND_COMPILE=0), interleaved, and print "
                             "the ratios")
    parser.add_argument("--first-runs", action="store_true",
                        help="only time what a newcomer runs first (FIRST_RUNS), --cold-n "
                             "samples each with an empty kernel cache")
    parser.add_argument("--out", help=OUT_HELP)
    args = parser.parse_args()
    if args.first_runs:
        with table_output(args.out):
            first_runs(args.cold_n)
        return
    with table_output(args.out), tempfile.TemporaryDirectory() as tree:
        baseline = None
        if args.baseline:
            baseline = (args.baseline, checkout(args.baseline, tree))
            # this tree byte-compiled too (PYTHONDONTWRITEBYTECODE may have left it without:
            # its processes would then compile every module's bytecode, the baseline's not)
            root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
            subprocess.run([sys.executable, "-m", "compileall", "-q",
                            os.path.join(root, "moik")], check=True, stdout=subprocess.DEVNULL)
        measure(args.n, cold=args.cold, cold_n=args.cold_n, baseline=baseline,
                without_background=args.without_background)


def first_runs(n: int) -> None:
    """Print the wall and CPU seconds of each of :data:`FIRST_RUNS`, ``n`` samples each
    (interleaved), each in a fresh process with its own empty NUMBA_CACHE_DIR."""
    samples: dict[str, list[tuple[float, float]]] = {what: [] for what in FIRST_RUNS}
    for _ in range(n):
        for what, argv in FIRST_RUNS.items():
            with tempfile.TemporaryDirectory() as cache:
                env = {**os.environ, "NUMBA_CACHE_DIR": cache}
                samples[what].append(wall(CLI, env=env, args=argv, check=False))
    load = os.getloadavg()[0]
    print(f"first runs, each with an empty kernel cache: {n} sample(s) of each, interleaved; "
          f"load average {load:.1f} after them")
    for what in FIRST_RUNS:
        walls, cpus = np.array(samples[what]).T
        print(f"{what}: median {np.median(walls):.1f} s wall ({walls.min():.1f}-"
              f"{walls.max():.1f}), {np.median(cpus):.1f} s CPU")
    plain, aware = (np.median(np.array(samples[what])[:, 0]) for what in SAME_ARM)
    print(f"collision-aware / plain first solve of panda (medians of wall): {aware / plain:.2f} "
          "(goal <= 1.5)")


def checkout(rev: str, into: str) -> str:
    """The files of commit ``rev`` of this repository under ``into`` (``git archive``),
    byte-compiled."""
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    archive = subprocess.run(["git", "-C", root, "archive", rev], check=True,
                             capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", into], input=archive, check=True)
    subprocess.run([sys.executable, "-m", "compileall", "-q", into], check=True,
                   stdout=subprocess.DEVNULL)  # its bytecode, as main() gives the current tree
    return into


def measure(n: int, *, cold: bool, cold_n: int = 5,
            baseline: tuple[str, str] | None = None, without_background: bool = False) -> None:
    """Print the medians of ``n`` interleaved samples, and of ``cold_n`` interleaved
    samples of each cold first use if asked (and of ``baseline = (rev, folder)``'s, and
    without background compiles if ``without_background``)."""
    wall(MOIK)  # make sure the kernels are cached
    wall(FLOOR)
    floor, moik, helps, robots = [], [], [], []
    for _ in range(n):
        floor.append(wall(FLOOR)[0])
        moik.append(wall(MOIK)[0])
        helps.append(wall(CLI, args=["--help"])[0])
        robots.append(wall(CLI, args=["robots"])[0])
    load = os.getloadavg()[0]
    print(f"{n} samples of each, interleaved; load average {load:.1f} after them")
    print(f"moik --help:  median {np.median(helps):.3f} s (goal <= 0.3 s)")
    print(f"moik robots:  median {np.median(robots):.3f} s (goal <= 0.3 s)")
    print(f"numba floor (numpy + numba + one cached kernel): median {np.median(floor):.3f} s")
    print(f"moik import + first solve (cached kernels):      median {np.median(moik):.3f} s "
          f"(goal <= 0.5 s); moik above the floor: {np.median(moik) - np.median(floor):.3f} s")
    if not cold:
        return
    forced = without_background or bool(baseline)  # a baseline may have no load rule: both
    # start their background compiles wherever one applies, whatever this process's load
    versions: dict[str, dict[str, str]] = {
        "": {"MOIK_BACKGROUND_COMPILE": "1"} if forced else {}}
    if baseline:
        versions["base"] = {"PYTHONPATH": baseline[1], "MOIK_BACKGROUND_COMPILE": "1"}
    if without_background:
        versions["alone"] = {"MOIK_BACKGROUND_COMPILE": "0"}
    samples: dict[tuple[str, str], list[tuple[float, float]]] = {
        (what, version): [] for what in COLD for version in versions}
    loads = []
    for _ in range(cold_n):
        for what, (argv, _goal) in COLD.items():
            loads.append(os.getloadavg()[0])
            for version, extra in versions.items():
                with tempfile.TemporaryDirectory() as cache:
                    env = {**os.environ, **extra, "NUMBA_CACHE_DIR": cache}
                    samples[what, version].append(
                        wall(CLI, env=env, args=argv, check=False))  # unreachable exits 1
    print(f"cold first uses: {cold_n} samples of each, interleaved, each with an empty "
          f"kernel cache; load average before them: median {np.median(loads):.1f} "
          f"({min(loads):.1f}-{max(loads):.1f})"
          + ("; background compiles forced (MOIK_BACKGROUND_COMPILE=1)" if forced else ""))
    for what, (_argv, goal) in COLD.items():
        walls, cpus = np.array(samples[what, ""]).T
        print(f"cold {what} (empty kernel cache): median {np.median(walls):.1f} s wall "
              f"({walls.min():.1f}-{walls.max():.1f}), {np.median(cpus):.1f} s CPU "
              f"(goal <= {goal:g} s)")
        if baseline:
            base = np.array(samples[what, "base"])[:, 0]
            ratios = walls / base
            print(f"  at {baseline[0]}, each run right after: median {np.median(base):.1f} s "
                  f"wall ({base.min():.1f}-{base.max():.1f}); ratio of the pairs: median "
                  f"{np.median(ratios):.2f} ({ratios.min():.2f}-{ratios.max():.2f})")
            there = GOAL_MACHINE[1].get(what)
            if there is not None and baseline[0].startswith(GOAL_MACHINE[0]):
                print(f"  on the machine that set the goal (where {GOAL_MACHINE[0]} takes "
                      f"{there:g} s): {np.median(ratios) * there:.1f} s "
                      f"({ratios.min() * there:.1f}-{ratios.max() * there:.1f}) "
                      f"(goal <= {goal:g} s)")
        if without_background:
            alone = np.array(samples[what, "alone"])
            ratios = walls / alone[:, 0]
            print(f"  without background compiles, each run right after: median "
                  f"{np.median(alone[:, 0]):.1f} s wall ({alone[:, 0].min():.1f}-"
                  f"{alone[:, 0].max():.1f}), {np.median(alone[:, 1]):.1f} s CPU; ratio of "
                  f"the pairs (with / without): median {np.median(ratios):.2f} "
                  f"({ratios.min():.2f}-{ratios.max():.2f})")


if __name__ == "__main__":
    main()
