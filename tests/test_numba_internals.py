"""Every numba internal moik relies on exists in the installed numba, and that numba is in
the range pyproject.toml allows (the range the project is tested with).

moik reaches below numba's public API in a few places: its kernel cache subclasses numba's
per-function cache (``moik/_kernel_cache.py``), ``moik/_jit.py`` swaps a dispatcher's cache
and listens to numba's compile events, the compiled records are StructRefs
(``numba.experimental``), and the algorithms' bounded integers call numba's fill below
``Generator.integers``. A numba release may rename or drop any of them; this test says
which one, and where moik uses it, before anything fails obscurely.
"""

import importlib
import inspect
import re
from pathlib import Path

import numba
import pytest

from moik.algorithms.archive.fronts import front_mask_2d

PYPROJECT = Path(__file__).resolve().parents[1] / "pyproject.toml"

# (module, attribute path, parameters it must take or None, where moik uses it)
INTERNALS = [
    ("numba.core.caching", "FunctionCache", None, "_kernel_cache.KernelCache's base"),
    ("numba.core.caching", "FunctionCache._index_key", ("sig", "codegen"),
     "_kernel_cache.KernelCache._index_key (the key with moik's sources digest)"),
    ("numba.core.caching", "FunctionCache._load_overload", ("sig", "target_context"),
     "_kernel_cache.KernelCache._load_overload"),
    ("numba.core.caching", "FunctionCache.save_overload", ("sig", "data"),
     "_kernel_cache.KernelCache.save_overload"),
    ("numba.core.caching", "FunctionCache.disable", (), "_kernel_cache.KernelCache.save_overload"),
    ("numba.core.caching", "IndexDataCacheFile", None, "_kernel_cache.CheckedCacheFile's base"),
    ("numba.core.caching", "IndexDataCacheFile.__init__",
     ("cache_path", "filename_base", "source_stamp"), "_kernel_cache.KernelCache.__init__"),
    ("numba.core.caching", "IndexDataCacheFile._load_index", (),
     "_kernel_cache.CheckedCacheFile._load_index, _jit.is_cached"),
    ("numba.core.caching", "IndexDataCacheFile._load_data", ("name",),
     "_kernel_cache.CheckedCacheFile._load_data"),
    ("numba.core.caching", "IndexDataCacheFile._data_path", ("name",),
     "_kernel_cache.CheckedCacheFile._load_data"),
    ("numba.core.caching", "IndexDataCacheFile._open_for_write", ("filepath",),
     "_kernel_cache.CheckedCacheFile._open_for_write"),
    ("numba.core.event", "Listener", None, "_jit._CompileNotice's base"),
    ("numba.core.event", "register", ("kind", "listener"), "_jit (the compile notice)"),
    ("numba.core.types", "StructRef.preprocess_fields", ("fields",), "_jit.StructType"),
    ("numba.core.types", "unliteral", None, "_jit.StructType.preprocess_fields"),
    ("numba.core.types", "NoneType", None, "collision/compiled.py's overloads"),
    ("numba.experimental.structref", "register", None,
     "the StructRefs of solver/context.py, collision/compiled.py, problems/ik_kernels.py, "
     "algorithms/generator_handle.py"),
    ("numba.experimental.structref", "define_proxy", ("py_class", "struct_typeclass", "fields"),
     "_jit.define_struct"),
    ("numba.experimental.structref", "StructRefProxy", None, "the StructRefs' proxies"),
    ("numba.core.extending", "overload", None, "problems/ik_kernels.py (objectives_row)"),
    ("numba.extending", "overload", None, "collision/compiled.py"),
    ("numba.np.random.random_methods", "random_bounded_uint64_fill",
     ("bitgen", "low", "rng", "size", "dtype"),
     "algorithms/soo/eosma_kernels.py (fill_integers)"),
    ("numba.core.cpu", "CPUTargetOptions.no_cfunc_wrapper", None, "_jit.JIT_OPTIONS"),
    ("numba.core.cpu", "CPUTargetOptions.inline", None, "_jit.jit(inline=True)"),
    ("numba", "config.DISABLE_JIT", None, "_jit.define_struct"),
]


def _installed_range() -> tuple[str, str]:
    text = PYPROJECT.read_text()
    found = re.search(r'"numba>=([\d.]+),<([\d.]+)"', text)
    assert found, "pyproject.toml must pin numba as \"numba>=A,<B\" (moik uses its internals)"
    return found.group(1), found.group(2)


def _version(text: str) -> tuple[int, ...]:
    return tuple(int(part) for part in re.findall(r"\d+", text)[:2])


def test_the_installed_numba_is_in_the_range_pyproject_allows():
    low, high = _installed_range()
    assert _version(low) <= _version(numba.__version__) < _version(high), (
        f"numba {numba.__version__} is outside the range moik is tested with (>={low},<{high} "
        "in pyproject.toml): check tests/test_numba_internals.py with it, then widen the range")


@pytest.mark.parametrize(("module", "path", "parameters", "where"), INTERNALS,
                         ids=[f"{m}.{p}" for m, p, _, _ in INTERNALS])
def test_every_numba_internal_moik_uses_exists(module, path, parameters, where):
    message = (f"moik uses numba's {module}.{path} in {where}; numba {numba.__version__} "
               "has no such {}: adapt that code before allowing this numba in pyproject.toml")
    try:
        value = importlib.import_module(module)
    except ImportError:
        pytest.fail(message.format("module"))
    for name in path.split("."):
        if not hasattr(value, name):
            pytest.fail(message.format("name"))
        value = getattr(value, name)
    if parameters is not None:
        names = tuple(p for p in inspect.signature(value).parameters if p != "self")
        assert names[:len(parameters)] == parameters, message.format(
            f"signature (it takes {names}, moik passes {parameters})")


def test_the_cache_attributes_moik_reads_are_set_by_numba():
    """What KernelCache and is_cached read of a live cache (instance attributes numba sets
    in its constructors), and the dispatcher's ``_cache`` that _jit.jit replaces."""
    cache = front_mask_2d._cache
    missing = [name for name, owner in [
        ("_cache_path", cache), ("_impl", cache), ("_name", cache), ("_cache_file", cache),
        ("filename_base", getattr(cache, "_impl", None)),
        ("locator", getattr(cache, "_impl", None)),
        ("_index_path", cache._cache_file), ("_version", cache._cache_file),
        ("_source_stamp", cache._cache_file)] if not hasattr(owner, name)]
    assert not missing, (f"numba {numba.__version__}'s cache objects lack {missing}, which "
                         "moik/_kernel_cache.py reads")
    assert callable(cache._impl.locator.get_source_stamp)
    assert hasattr(numba.njit(lambda x: x), "_cache"), "_jit.jit replaces a dispatcher's _cache"


def test_the_compile_event_moik_listens_to_is_a_numba_event():
    from numba.core import event

    assert "numba:compile" in event._builtin_kinds, (
        f"numba {numba.__version__} fires no 'numba:compile' event (moik/_jit.py's notice)")
