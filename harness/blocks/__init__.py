"""FORTH blocks as text files and as RL02 disk images (pack, export, check).

The bottom of the import order: imports no other harness package
(harness/README.md)."""
