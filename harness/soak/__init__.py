"""The disk soak (`make soak-disk`): the simulator killed at random instants
while the FORTH writes blocks, and every FLUSHed block checked afterwards.

The top of the import order, beside harness/cli.py (harness/README.md)."""
