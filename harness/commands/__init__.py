"""Subcommands of `python -m harness`, one module each (registered in harness/cli.py),
and their helpers: argtypes (option types), invoke (running a command with its
input errors reported).

Imports the tools (harness.analysis, harness.lab), harness.machine and
harness.blocks; only harness/cli.py and the top floor (bench, fuzz, soak,
figures) import it (harness/README.md)."""
