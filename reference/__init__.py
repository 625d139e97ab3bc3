"""Line-by-line numpy ports of the authors' MATLAB codes, to run beside moik's implementations.

Used by ``studies/moo_quality.py`` (section "reference codes side by side") to tell a
bug from a method's weakness: where moik's algorithm and the port of its reference
code give the same picture on the same problem and budget, the weakness is the
method's. Each port keeps the code's control flow, its order of operations and its
quirks (noted inline); only the random streams differ (numpy instead of MATLAB), and
evaluations are vectorized where the code evaluates one agent at a time without the
others seeing the result. Ports (files as published):

- ``moeosma_reference``: Shihong-Yin/MOEOSMA, ``MOEOSMA_for_CEC2020/MOEOSMA.m``,
  ``UpdateArchive.m``, ``RankingProcess.m``, ``HandleFullArchive.m``,
  ``RouletteWheelSelection.m`` (``mode="paper"`` swaps in the paper's Eq. 16 mutation
  and a1 = a2 = 2 for the code's random a1, a2 and ``X + SF (X_R1 - X_R2)``);
- ``mogwo_reference``: Mirjalili's MOGWO 1.0 (``MOGWO.m``, ``SelectLeader.m``,
  ``DeleteFromRep.m``, ``CreateHypercubes.m``, ``GetGridIndex.m``);
- ``malo_reference``: Mirjalili's MOALO 1.0 (``MALO.m``, ``Random_walk_around_antlion.m``);
- ``mssa_reference``: Mirjalili's MSSA 1.0 (``MSSA.m``);
- ``moda_reference``: Mirjalili's MODA 1.0 (``MODA.m``, ``Levy.m``);
- ``momvo_reference``: Mirjalili's MOMVO 1.0 (``MOMVO.m``);
- ``choa_reference``: Khishe & Mosavi's ChOA 1.0 (``chimp.m``; single-objective);
- ``mo_csa_reference``: Askarzadeh's ``CSA.m``, one flock per objective (the MO-m-PSO
  paper's construction; it publishes no code), on the EOSMA authors' archive files;
  the last four with Mirjalili's shared archive files (``UpdateArchive.m``,
  ``RankingProcess.m``, ``HandleFullArchive.m``, ``RouletteWheelSelection.m``).

The MSSA/MOALO/MODA codes were read in the copies of github.com/mxd888/MOAOA_For_MOVRPD
(``MO_For_CEC2020/``), which carry Mirjalili's version-1.0 headers. MOMVO.m is not
there; it was read in github.com/Natee-Panagant/Comparative-study-of-truss-sizing-
optimisation-problems-in-MATLAB, ``Algorithms/MOMVO.m`` (commit aeb246c7), which carries
Mirjalili's MOMVO version-1.0 header (its adapter added a penalty and constraint values
G around the loop), and in github.com/Zionist1923/MOMVO_Based_MMGEMS, ``MOMVO.m``
(commit bda128e7, a re-headed copy without constraints); their main loops agree line
for line.

Constrained problems: the codes handle none. The MOGWO port and the ports on Mirjalili's
shared archive (MSSA, MOALO, MODA, MOMVO) then use constraint-domination in their archive
updates, the rule of moik's archives (only the feasible rows compete once one is
feasible; before that only those of the smallest total violation); the search itself
is the code's. The MOEOSMA port is for unconstrained problems only.

Every function takes a pymoo problem, the population size, the number of iterations
and a numpy Generator and returns ``(archive_X, archive_F, n_eval)``. They live by
family in ``reference/mirjalili.py`` (Mirjalili's shared archive), ``reference/mogwo.py``,
``reference/eosma.py`` (the EOSMA authors' archive) and ``reference/common.py``; this module
lists them (:data:`REFERENCES`).
"""


from __future__ import annotations

from .choa import choa_reference
from .eosma import mo_csa_reference, moeosma_reference
from .mirjalili import malo_reference, moda_reference, momvo_reference, mssa_reference
from .mogwo import mogwo_reference

REFERENCES = {
    "moeosma": moeosma_reference,
    "mogwo": mogwo_reference,
    "moalo": malo_reference,
    "mssa": mssa_reference,
    "moda": moda_reference,
    "momvo": momvo_reference,
    "mo-csa": mo_csa_reference,
}
"""moik registry name -> port of its reference code (multi-objective)."""

SINGLE_REFERENCES = {"choa": choa_reference}
"""moik registry name -> port of its reference code (single-objective: the best point)."""

