"""`regress`: the regression scenarios (tests/regression), compared or updated."""
from harness import regression
from harness.commands.run import PRISTINE, check_start_image
from harness.disk import DiskError
from harness.trace_features import FeatureError

NAME = "regress"
HELP = "run the regression scenarios against their goldens, or --update them"
ERRORS = (ValueError, FeatureError, DiskError)


def configure(parser):
    parser.add_argument("names", nargs="*", metavar="SCENARIO",
                        help="scenario names (default: all in tests/regression/scenarios)")
    parser.add_argument("--update", action="store_true",
                        help="rewrite the golden transcripts and the features' values "
                        "(tolerances and comments kept) and print what changed")
    parser.set_defaults(run=run)


def run(args):
    """Every scenario boots a copy of build/robot.dsk: check it once, before any."""
    check_start_image(PRISTINE)
    return regression.main(args.names, args.update)
