"""``python -m moik``: the ``moik`` command line (:mod:`moik.cli`)."""

import sys

from moik.cli.main import main

if __name__ == "__main__":
    sys.exit(main())
