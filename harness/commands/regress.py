"""`regress`: the regression scenarios (tests/regression), compared or updated."""
from harness import regression
from harness.trace_features import FeatureError

ERRORS = (ValueError, FeatureError)


def configure(parser):
    parser.add_argument("names", nargs="*", metavar="SCENARIO",
                        help="scenario names (default: all in tests/regression/scenarios)")
    parser.add_argument("--update", action="store_true",
                        help="rewrite the golden transcripts and the features' values "
                        "(tolerances and comments kept) and print what changed")
    parser.set_defaults(run=lambda args: regression.main(args.names, args.update))
