"""``python -m moik.warmup``: a background family's child (:mod:`moik.warmup.background`)."""

from moik.warmup.background import child_arguments
from moik.warmup.beside import BESIDE

if __name__ == "__main__":
    family, arguments = child_arguments()
    BESIDE[family](**arguments)
