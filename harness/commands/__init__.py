"""Subcommands of `python -m harness`, one module each (registered in harness/cli.py),
and their helpers: argtypes (option types), invoke (running a command with its
input errors reported), regression (the scenarios that `regress` runs through `run`).

Imports the tools (harness.analysis, harness.lab, harness.asmcheck), harness.machine
and harness.blocks; only harness/cli.py and the benches import it (harness/README.md)."""
