"""``python -m moik.warmup``: a background family's child (:mod:`moik.warmup.background`)."""

import importlib

from moik.warmup import BESIDE
from moik.warmup.background import child_arguments

if __name__ == "__main__":
    family, arguments = child_arguments()
    module, name = BESIDE[family].split(":")
    getattr(importlib.import_module(module), name)(**arguments)
