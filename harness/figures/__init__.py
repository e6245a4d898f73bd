"""The figure makers: the runs whose traces and plots docs/ shows
(`make servo-runs`, `make continuation-runs`), each `python -m harness.figures.NAME`.

The top of the import order, beside harness/cli.py (harness/README.md)."""
