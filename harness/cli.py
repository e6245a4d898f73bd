"""The harness command line: one subcommand per module in harness/commands.

Each command module defines NAME, HELP, configure(parser) (adds its arguments and
sets `run`, a function args -> exit status) and lists in ERRORS the exception types
that mean "the user's input is wrong": they are reported as one clear message each
line, with exit status 1.  Adding a command = adding a module and a
line to COMMANDS.
"""
import argparse
import sys

from harness.commands import console, disk, lab, listing, plot, regress, run, timing

COMMANDS = (console, lab, run, regress, disk, plot, timing, listing)


def build_parser():
    parser = argparse.ArgumentParser(
        prog="python -m harness",
        description="Tools for the 1983 Cartesian robot on an emulated PDP-11/23.")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for module in COMMANDS:
        module.configure(sub.add_parser(module.NAME, help=module.HELP,
                                        description=module.HELP))
    return parser


def main(argv=None):
    """Run one command; returns the exit status (0 ok, 1 failed, 2 usage error)."""
    parser = build_parser()
    args = parser.parse_args(argv)
    errors = tuple(e for m in COMMANDS for e in getattr(m, "ERRORS", ()))
    name = " ".join(filter(None, (args.command, getattr(args, "action", None))))
    try:
        return args.run(args)
    except errors as err:
        for line in str(err).splitlines():
            print(f"{parser.prog} {name}: error: {line}", file=sys.stderr)
        return 1
