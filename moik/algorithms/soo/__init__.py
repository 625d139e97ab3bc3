"""Single-objective algorithms, one module each."""
