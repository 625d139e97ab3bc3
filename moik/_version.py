"""The package version, in one place (``moik.__version__``, the results store, the CLI)."""

__version__ = "0.1.0"
