"""TOML parsing: the standard library's :mod:`tomllib` (Python >= 3.11), else ``tomli``.

``tomli`` is the package the standard library's parser came from (same API); it is a
dependency of moik on Python 3.10 only (``pyproject.toml``).
"""

import sys

if sys.version_info >= (3, 11):
    from tomllib import TOMLDecodeError, load, loads
else:  # pragma: no cover - Python 3.10
    from tomli import TOMLDecodeError, load, loads

__all__ = ["TOMLDecodeError", "load", "loads"]
