"""Driving the emulated PDP-11/23: build/pdp11 (SIMH) with the FORTH kernel, through
a pty or SIMH scripts, line by line in lock-step with simulated time (scripted runs,
the robot), or joined to the user's terminal (the console); and the one home of the
facts the rest reads: where the build is (build), the kernel's layout
(kernel_layout), the plant's row and SHOW PLANT (plant_rows).

Imports only harness.blocks (the disk image's size and block ranges); everything
else in the harness builds on this package (harness/README.md)."""
