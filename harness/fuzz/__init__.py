"""The console fuzz (`make fuzz`): generated FORTH lines typed at the machine
until it breaks or the lines run out; its line maker is pure and tested alone.

The top of the import order, beside harness/cli.py (harness/README.md)."""
