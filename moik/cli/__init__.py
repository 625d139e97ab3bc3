"""The ``moik`` command line (also ``python -m moik``).

Subcommands:
    moik robots [ROBOT]              list the catalog, or one robot's joints, DH rows, unit, source
    moik algorithms                  list the registered algorithms (name, kind, source)
    moik fk ROBOT q1 ... qn [--deg]  print the end-effector pose (full precision)
    moik solve ROBOT --target x y z [--euler a b c [--deg]] ...   solve IK
    moik solve ROBOT --target ... --pareto CRITERIA ...   the Pareto set of exact solutions
    moik batch ROBOT TARGETS --out RESULT [--workers N] [--scene FILE] [--self-collision]
                                     [--clearance D] [--tol T]   solve a .npy/CSV file of targets
    moik compile [--processes N]     compile every kernel family once, in parallel processes
    moik experiment list             list the papers' experiments
    moik experiment run NAME [--quick] [--workers N] [--resume] [--out DIR] [--dask-scheduler A]
    moik experiment run --config FILE [...]   run your own config file (TOML)
    moik report DIR [DIR ...]        Markdown report of each results folder (DIR/report.md)
    moik report DIR [DIR ...] --docs DOCS   regenerate DOCS/results/NAME.md and the generated
                                     blocks of DOCS/reproducing.md from the results

ROBOT is a catalog name (``moik robots``) or a URDF file (``--base``/``--tip``
name the chain's first and last links). Joint values on the command line are
radians, or degrees with ``--deg`` (prismatic joints always in the robot's unit).

``--json`` (robots, algorithms, fk, solve, solve --pareto) prints one JSON object on
stdout for scripts (strict JSON: a number that is not finite, e.g. the ``min_distance``
of an answer with no pair near anything, ``inf``, is ``null``); lengths are in the
robot's unit, angles and revolute joint values in radians, prismatic joint values in
the robot's unit. ``fk``, ``solve`` and
``solve --pareto`` share one schema family: every document has ``"command"``,
``"robot"``, ``"unit"``, ``"joint_names"`` and ``"q"`` (the joint vector the command
is about), and the solving ones ``"target"``, ``"status"``, ``"success"``, ``"n_eval"``,
``"time_s"``, ``"position_error"``, ``"orientation_error"`` (geodesic, rad) and
``"solutions"`` (each ``{"q", "position_error", "orientation_error"}``):

* ``robots``: ``{"robots": [{"name", "dof", "kind", "unit", "source"}]}``;
  ``robots ROBOT``: ``{"name", "dof", "kind", "unit", "source", "joints": [{"name",
  "type", "lower", "upper"}], "dh": {"a", "alpha", "d", "theta"} or null, "base", "tool"}``.
* ``algorithms``: ``{"algorithms": [{"name", "kind", "source"}]}``.
* ``fk`` (``"command": "fk"``): the common keys, ``"pose"`` (4x4), ``"position"``,
  ``"rotation"``, ``"zyx_euler"``, ``"eosma_euler"``, ``"within_limits"``.
* ``solve`` (``"command": "solve"``): the common and solving keys, ``"n_solutions"``
  (how many distinct solutions were asked for), ``"fewer_solutions"`` (solved, but
  fewer distinct solutions found than asked for), ``"front"``
  (``[[position_error, orientation_error], ...]`` or null), ``"plots"`` (files).
* ``solve --pareto`` (``"command": "pareto"``): the common and solving keys (``q``: the
  compromise member, or null when no exact solution was found; ``solutions``: every
  member), ``"objectives"``, ``"senses"``, ``"F"`` (criteria of each member),
  ``"compromise"`` (index or null), ``"redundant"``, ``"n_exact"``, ``"plots"``.

Exit status: 0 done (``solve``: solved; ``batch``: every target solved), 1 ``solve`` not
solved (``batch``: some target not solved), 2 bad input (a bad command line too) or an
unusable file or folder (one line on stderr, never a traceback), 130 interrupted by
Ctrl-C, 143 by SIGTERM (one line: ``moik: interrupted (SIGTERM)``). The parser
(:mod:`moik.cli.parser`) imports nothing heavy, and each subcommand's module is
imported only when that subcommand runs, so ``moik --help`` answers at once.
"""

from moik.cli.main import main
from moik.cli.parser import build_parser

__all__ = ["build_parser", "main"]
