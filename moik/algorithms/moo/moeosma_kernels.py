"""MOEOSMA's compiled draws: its own order of a generation's random numbers.

Yin et al., Sci. Rep. 12, 9421 (2022), DOI 10.1038/s41598-022-13516-3; the equations,
readings and deviations are in :mod:`moik.algorithms.moo.moeosma`. The maths of a
generation is EOSMA's, written once in :mod:`moik.algorithms.soo.eosma_kernels`
(:func:`~moik.algorithms.soo.eosma_kernels.generation_candidates`: Eqs. 4, 15, 17 with one
leader per agent, built from EO's ``eo_coordinate`` and SMA's ``sma_coordinate`` and
``weights_into``; :func:`~moik.algorithms.soo.eosma_kernels.mutation_candidates`:
Eqs. 16-17). What is MOEOSMA's own is the order in which Algorithm 2 draws the numbers,
into the named slots of :class:`~moik.algorithms.soo.eosma_kernels.GenerationDraws`
(:func:`generation_draws`).

Random numbers: every number of a generation is drawn on the algorithm's numpy
``Generator`` inside the kernel (through a
:class:`~moik.algorithms.generator_handle.GeneratorHandle`; numba's Generator methods
give numpy's stream): the leader of each agent (an archive pool member), the Eq. 4
weights, EO's lambda, r, pool index, r1, r2 (Eqs. 8-9), SMA's vb, A, B (two ``integers``
calls, where EOSMA makes one), the operator test, then the mutation test and Eq. 16's
R1..R3 and SF. Algorithm 2 draws the mutation numbers after the first evaluation;
nothing between consumes the Generator (the evaluation and the memory draw nothing, the
archive merge comes at the end of the iteration), so drawing them in the same call gives
the same stream.
"""

from __future__ import annotations

from moik._jit import jit
from moik.algorithms.soo.eosma_kernels import (
    A_INDEX,
    B_INDEX,
    EO_R,
    GCP_R1,
    GCP_R2,
    LAMBDA,
    LOG_WEIGHT,
    OPERATOR_U,
    ORDER,
    POOL_INDEX,
    VB,
    WEIGHT_R,
    decay_into,
    fill_integers,
    fill_random,
    mutation_draws,
    uniform_into,
)
from moik.algorithms.soo.sma import weight_arguments

__all__ = ["generation_draws"]


@jit
def generation_draws(handle, S, n_pool, t1, a, q, leaders, cells, rows, picks):
    """Every random number of a MOEOSMA generation, in Algorithm 2's order; the mutation test.

    Args:
        handle: A :class:`~moik.algorithms.generator_handle.GeneratorHandle` of the
            algorithm's Generator.
        S: The personal bests' fitness on the Eq. 21 objective (n,), ranked for Eq. 5.
        n_pool: Size of the equilibrium pool (leaders and Eq. 6's members are drawn in it).
        t1: EO's schedule term of Eq. 8. a: The SMA range of Eq. 3 (vb ~ U(-a, a)).
        q: The mutation probability.
        leaders: Out (n,) int: the pool member leading each agent (Eq. 15, SMA case).
        cells, rows, picks: The arrays of a
            :class:`~moik.algorithms.soo.eosma_kernels.GenerationDraws` (filled; the
            caller applies its ``apply_numpy_maths``).

    Returns:
        Whether the mutation runs (Algorithm 2, line 26).
    """
    rng = handle.rng
    n = S.size
    fill_integers(rng, n_pool, leaders.reshape(1, n))
    weight_arguments(S, picks[ORDER], rows[LOG_WEIGHT])  # Eq. 5 and Eq. 4's argument
    fill_random(rng, cells[WEIGHT_R])
    fill_random(rng, cells[LAMBDA])
    decay_into(cells, t1)
    fill_random(rng, cells[EO_R])
    fill_integers(rng, n_pool, picks[POOL_INDEX:POOL_INDEX + 1])
    fill_random(rng, rows[GCP_R1:GCP_R2 + 1])
    uniform_into(rng, -a, a, cells[VB])
    fill_integers(rng, n, picks[A_INDEX:A_INDEX + 1])
    fill_integers(rng, n, picks[B_INDEX:B_INDEX + 1])
    for i in range(n):
        rows[OPERATOR_U, i] = rng.random()
    return mutation_draws(rng, q, rows, picks)
