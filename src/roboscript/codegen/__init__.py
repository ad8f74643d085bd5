"""Code generation: prompts, the main and function-generating agents, the static checker, the sandbox, repair."""
