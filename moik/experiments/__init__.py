"""Experiment helpers: the papers' solving protocol, trial runners and result I/O."""
