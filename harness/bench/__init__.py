"""The drivers behind the long make targets, each run as `python -m harness.bench.NAME`:
make bench's figures, the runs that make docs' traces and figures (servo_runs,
continuation_runs), the disk soak and the console fuzz.

The top of the import order, beside harness/cli.py: may use every other package;
nothing imports a bench (harness/README.md)."""
