"""The harness: drives the emulated PDP-11/23, packs and exports block disks,
runs scripted regressions, draws plots and listings. Its packages by role and
their one-way import order: harness/README.md."""
