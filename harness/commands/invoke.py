"""Running one subcommand with the user's input errors reported as messages
(harness/cli.py; the regression scenarios call the run engine,
harness.machine.script_run.run_file, directly)."""
import sys

PROG = "python -m harness"


def run_reported(args, errors, name):
    """args.run(args); an exception of the types in errors (the command's ERRORS:
    the user's input is wrong) is printed one line each as `PROG NAME: error: ...`
    on stderr, exit status 1."""
    try:
        return args.run(args)
    except errors as err:
        for line in str(err).splitlines():
            print(f"{PROG} {name}: error: {line}", file=sys.stderr)
        return 1
