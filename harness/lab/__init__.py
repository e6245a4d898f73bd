"""The lab bench: the FORTH console, the robot, a scope and the servo's variables,
live in a browser page (python -m harness lab; docs/lab.md)."""
