"""What measures: the drivers of `make bench`'s figures, each run as
`python -m harness.bench.NAME` and printing what it measured.

The top of the import order, beside harness/cli.py: may use every other package;
nothing imports a bench (harness/README.md)."""
