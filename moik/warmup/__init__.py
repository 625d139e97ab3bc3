"""Compiling kernels ahead of their first use: ``moik compile``'s families and the
background compiles of a cold first use. Above the solver: it calls the solver's,
problems' and algorithms' public functions, and none of them imports it.

numba compiles a kernel at its first call and caches it on disk (:mod:`moik._jit`); this
package only decides what is called when, by kernel family names:

- :mod:`moik.warmup.families`: the families ``moik compile`` runs, one process each
  (:data:`~moik.warmup.families.FAMILIES`, :func:`~moik.warmup.families.compile_family`).
- :mod:`moik.warmup.beside` and :mod:`moik.warmup.beside_collision`: the families a child
  process compiles beside a cold first use (:data:`BESIDE`; the ``moik`` command starts
  ``"pareto-search"`` before a ``solve --pareto``: :func:`~moik.warmup.beside.beside_pareto`).
- :mod:`moik.warmup.background`: starting that child (``python -m moik.warmup``), where
  a second CPU is free and ``MOIK_BACKGROUND_COMPILE`` is not ``0``.
"""

BESIDE = {
    "front-leaves": "moik.warmup.beside:front_leaves",
    "solve-leaves": "moik.warmup.beside:solve_leaves",
    "pareto-search": "moik.warmup.beside:pareto_search",
    "collision-leaves": "moik.warmup.beside_collision:collision_leaves",
    "collision-stand-in": "moik.warmup.beside_collision:collision_stand_in",
}
"""Each background family's child workload, ``"module:function"`` (``python -m moik.warmup``
imports only its family's module)."""
