"""The ``roboscript`` command line: one module per family of commands, each adding its own sub-commands
(:mod:`roboscript.cli.main` puts them together)."""
