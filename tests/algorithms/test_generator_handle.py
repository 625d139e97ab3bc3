"""The compiled handle on a numpy Generator (moik.algorithms.generator_handle)."""

import copy
import pickle

import numpy as np

from moik._jit import jit
from moik.algorithms.generator_handle import GeneratorHandles


@jit
def draw_three(handle):
    return handle.rng.random(3)


def test_the_handle_draws_on_the_generator_itself():
    rng, ref = np.random.default_rng(5), np.random.default_rng(5)
    handles = GeneratorHandles()
    np.testing.assert_array_equal(draw_three(handles.of(rng)), ref.random(3))
    assert rng.random() == ref.random()  # one stream, shared with numpy
    np.testing.assert_array_equal(draw_three(handles.of(rng)), ref.random(3))


def test_a_new_generator_gets_a_new_handle_and_copies_start_empty():
    handles = GeneratorHandles()
    first = handles.of(np.random.default_rng(0))
    assert handles.of(np.random.default_rng(0)) is not first
    rng = np.random.default_rng(1)
    assert handles.of(rng) is handles.of(rng)
    for other in (copy.deepcopy(handles), pickle.loads(pickle.dumps(handles))):
        assert isinstance(other, GeneratorHandles)
        np.testing.assert_array_equal(draw_three(other.of(np.random.default_rng(2))),
                                      np.random.default_rng(2).random(3))
