"""The papers' experiment configs, one file per table or figure (see README.md here).

This folder is shipped inside the moik wheel as the package ``moik.paper_configs``
(``pyproject.toml`` maps it); :mod:`moik.experiments.registry` finds the files.
Each config is a TOML data file (``*.toml``, shipped as package data), never run as code.
"""
