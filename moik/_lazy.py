"""Public names of a package loaded at their first use (PEP 562), for start-up time.

A package lists ``name -> (module, attribute)`` (``attribute`` ``None``: the module
itself) and binds the two functions :func:`lazy_names` returns as its module-level
``__getattr__`` and ``__dir__``. Nothing here hides an import cycle: the modules named
are imported the ordinary way when a name is first read, and the import-graph test
reads the same imports statically.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping
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
