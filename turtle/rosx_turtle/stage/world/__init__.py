"""Stage's world files: `worldfile` (sans-I/O syntax), `model` (the `World`), `images`, `load`."""
