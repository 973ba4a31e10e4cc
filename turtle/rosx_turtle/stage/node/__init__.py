"""stageros: `stageros.StageNode` (the node) and `run.run_stageros` (the program)."""
