"""`regress`: the regression scenarios (tests/regression), compared or updated."""
import argparse

from harness.analysis.trace_features import FeatureError
from harness.blocks.disk import DiskError
from harness.analysis import regression
from harness.controllers.scripted import run_five_file
from harness.machine.build import PRISTINE_DISK
from harness.machine.script_run import check_start_image

ERRORS = (ValueError, FeatureError, DiskError)

DESCRIPTION = """\
Run the regression scenarios of tests/regression/scenarios (each NAME.script
through `run`, boot included) and compare each transcript with NAME.expected
and its plant trace with NAME.features; or, with --update, rewrite those
goldens from this run and print what changed (review it before committing).
docs/console.md describes the files.

Exit status: 0 when every scenario run agrees with its goldens (or --update
finished); 1 when a scenario differs, a named scenario does not exist, a
features file is bad or build/robot.dsk is unusable; 2 for a bad option."""


def configure(parser):
    parser.description = DESCRIPTION
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.add_argument("names", nargs="*", metavar="SCENARIO",
                        help="scenario names (default: all in tests/regression/scenarios)")
    parser.add_argument("--update", action="store_true",
                        help="rewrite the golden transcripts and the features' values "
                        "(tolerances and comments kept) and print what changed")
    parser.set_defaults(run=run)


def run(args):
    """Every scenario boots a copy of build/robot.dsk: check it once, before any."""
    check_start_image(PRISTINE_DISK)
    return regression.main(args.names, args.update, five_runner=run_five_file)
