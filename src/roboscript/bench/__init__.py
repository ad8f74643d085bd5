"""The benchmark: tasks, checks, metrics, trial runner, results and reference programs."""
