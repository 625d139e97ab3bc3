"""Public names of a package, or a module, loaded at their first use, for start-up time.

A package lists ``name -> (module, attribute)`` (``attribute`` ``None``: the module
itself) and binds the two functions :func:`lazy_names` returns as its module-level
``__getattr__`` and ``__dir__``. Nothing here hides an import cycle: the modules named
are imported the ordinary way when a name is first read, and the import-graph test
reads the same imports statically.

:func:`lazy_module` is the standard library's :class:`importlib.util.LazyLoader`: a
module object whose code runs at its first attribute access. ``moik.robots.chain``
holds its compiled FK kernels (:mod:`moik.robots.fk_kernels`, which imports numba) this way,
so listing or describing robots (``moik robots``) does not pay numba's import; the
module states the same edge under ``TYPE_CHECKING`` for the import-graph test.
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
from collections.abc import Callable, Mapping
from types import ModuleType
from typing import Any


def lazy_names(package: str, names: Mapping[str, tuple[str, str | None]],
               namespace: dict[str, Any], exported: list[str]
               ) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """``(__getattr__, __dir__)`` for ``package`` loading ``names`` on first use.

    Args:
        package: The package's name (for the AttributeError message).
        names: Public name -> (module, attribute or None).
        namespace: The package's ``globals()``: a loaded name is cached there.
        exported: The package's ``__all__``.
    """

    def __getattr__(name: str) -> Any:  # noqa: N807 (PEP 562's module hook)
        if name not in names:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        module_name, attribute = names[name]
        module = importlib.import_module(module_name)
        value = module if attribute is None else getattr(module, attribute)
        namespace[name] = value
        return value

    def __dir__() -> list[str]:  # noqa: N807
        return sorted({*namespace, *exported})

    return __getattr__, __dir__


def lazy_module(name: str) -> ModuleType:
    """The module ``name``, its code run at the first attribute access (or now if loaded).

    Raises:
        ModuleNotFoundError: ``name`` is not an importable module.
    """
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.find_spec(name)
    if spec is None or spec.loader is None:
        raise ModuleNotFoundError(f"no module named {name!r}", name=name)
    loader = importlib.util.LazyLoader(spec.loader)
    spec.loader = loader
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    loader.exec_module(module)
    parent, _, child = name.rpartition(".")
    if parent:
        setattr(sys.modules[parent], child, module)
    return module
