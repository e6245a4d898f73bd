"""Reading and pricing what the machine did: plant traces and their features,
moves, plots, block listings, the KDF11-A instruction timing, the servo one tick
at a time, small hand-assembled PDP-11 programs.

Imports harness.machine and harness.blocks, never the commands or the benches
(harness/README.md)."""
