"""The harness command line: one subcommand per module in harness/commands.

COMMANDS names each subcommand and its one-line help. Its module (imported only
when that subcommand runs, so `run` does not pay for matplotlib) defines
configure(parser) (adds its arguments and sets `run`, a function args -> exit
status) and lists in ERRORS the exception types that mean "the user's input is
wrong": they are reported as one clear message each line, with exit status 1.
An option the subcommand does not know prints that subcommand's usage, exit 2.
Adding a command = adding a module and a line to COMMANDS.
"""
import argparse
import importlib
import sys

from harness.commands.invoke import PROG, run_reported

COMMANDS = {
    "console": "the interactive FORTH console on the robot's PDP-11/23 (what make run starts)",
    "lab": "the lab bench: the FORTH console, the robot, a scope and the servo in a browser page",
    "run": "run a console script on a fresh copy of the disk: transcript and plant trace",
    "regress": "run the regression scenarios against their goldens, or --update them",
    "disk": "RL02 block disk images: pack block text files, export blocks to text",
    "plot": "draw PNG/SVG figures from a plant trace (CSV from ATTACH PLANT)",
    "timing": "price the executions of a piece of PDP-11 code on a KDF11-A (11/23)",
    "listing": "list blocks beside the addresses and words each line compiled or assembled",
    "tick": "walk the 1983 servo one 60 Hz tick at a time: its arrays, counters and DACs",
    "controllers": "the 11/23 and four LSI-11/03 axis controllers in lock-step on one plant",
}


def command_module(name):
    return importlib.import_module(f"harness.commands.{name}")


def build_parser(argv):
    """The parser, with the arguments of the subcommand named in argv (if any)."""
    chosen = next((a for a in argv if not a.startswith("-")), None)
    parser = argparse.ArgumentParser(
        prog=PROG,
        description="Tools for the 1983 Cartesian robot on an emulated PDP-11/23.")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    subparsers = {}
    for name, text in COMMANDS.items():
        subparsers[name] = sub.add_parser(name, help=text, description=text)
        if name == chosen:
            command_module(name).configure(subparsers[name])
    return parser, subparsers


def main(argv=None):
    """Run one command; returns the exit status (0 ok, 1 failed, 2 usage error)."""
    argv = sys.argv[1:] if argv is None else list(argv)
    parser, subparsers = build_parser(argv)
    args, unknown = parser.parse_known_args(argv)
    if unknown:
        subparsers[args.command].error(f"unrecognized arguments: {' '.join(unknown)}")
    errors = getattr(command_module(args.command), "ERRORS", ())
    name = " ".join(filter(None, (args.command, getattr(args, "action", None))))
    return run_reported(args, errors, name)
