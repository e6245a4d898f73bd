"""`run SCRIPT`: a scripted, deterministic console session (docs/console.md)."""
import argparse
import sys
from pathlib import Path

from harness.commands.argtypes import absolute_path, positive
from harness.machine.build import KERNEL, PDP11, PDP11_TIMED, PRISTINE_DISK
from harness.machine.script_run import ERRORS, run_file  # noqa: F401 (ERRORS: cli reports them)
from harness.machine.scripted_machine import ScriptError

DESCRIPTION = """\
Boot the FORTH on the robot's PDP-11/23 from a fresh copy of the disk image
(never the image itself), type the script's lines one at a time, each only
after the previous one was answered, at full speed, and write:

  the transcript   what the terminal showed (LF line ends)
  the plant trace  the CSV of ATTACH PLANT (docs/plots.md)

Script: one FORTH line per line; blank lines skipped; '# text' is a comment;
directives: '#wait SECONDS' lets simulated time pass with no input, '#simh CMD'
runs a SIMH SHOW, SET, EXAMINE or DEPOSIT command (its output goes into the
transcript). The run is deterministic: the same script gives the same bytes.

Exit status 0 if every line was answered " ok"; 1 if a line failed (named as
SCRIPT:LINE: the error), the script is bad, or the machine could not be run;
2 for a bad option. Outputs are written whole (temporary file, then renamed)
into directories that must exist (--out is not created, as plot's is not);
a run that fails still writes them, one that cannot start writes nothing."""


def configure(parser):
    parser.description = DESCRIPTION
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.add_argument("script", metavar="SCRIPT", help="the console script")
    parser.add_argument("--out", metavar="DIR",
                        help="directory for the outputs (default: the script's)")
    parser.add_argument("--transcript", metavar="FILE",
                        help="transcript file (default: DIR/NAME.transcript)")
    parser.add_argument("--trace", metavar="FILE",
                        help="plant trace file (default: DIR/NAME.trace.csv)")
    parser.add_argument("--disk", metavar="IMAGE", default=str(PRISTINE_DISK),
                        help="disk image to start from, copied and never changed "
                        "(default: build/robot.dsk)")
    parser.add_argument("--keep-going", action="store_true",
                        help="go on past FORTH errors (the exit status is still 1)")
    parser.add_argument("--line-limit", type=positive, default=60.0, metavar="SECONDS",
                        help="simulated seconds a line may run before it is stopped "
                        "and reported (default 60)")
    parser.add_argument("--kernel", metavar="LDA", default=str(KERNEL),
                        help="the FORTH kernel to load (default build/kernel.lda); its "
                        "symbol map is the .map file beside it")
    parser.add_argument("--timed", action="store_true",
                        help="11/23 time: each instruction takes its KDF11-A time (SET CLK "
                        "TIMED, on build/pdp11-timed) instead of 1/300000 s; the clock "
                        "ticks every real 1/60 s")
    parser.add_argument("--simulator", type=absolute_path, help=argparse.SUPPRESS)
    parser.set_defaults(run=run)


def output_paths(args):
    """(transcript, trace) paths from the options and the script's name."""
    source = Path(args.script)
    out = Path(args.out) if args.out else source.parent
    stem = source.name[:-len(source.suffix)] if source.suffix else source.name
    return (Path(args.transcript) if args.transcript else out / f"{stem}.transcript",
            Path(args.trace) if args.trace else out / f"{stem}.trace.csv")


def run(args):
    transcript_path, trace_path = output_paths(args)
    if args.out and Path(args.out).exists() and not Path(args.out).is_dir():
        raise ScriptError(f"--out {args.out}: not a directory (--out names the directory "
                          "for both outputs; --transcript and --trace name files)")
    steps, result = run_file(args.script, transcript_path, trace_path, disk=args.disk,
                             keep_going=args.keep_going, line_limit=args.line_limit,
                             kernel=args.kernel,
                             simulator=args.simulator or (PDP11_TIMED if args.timed else PDP11),
                             settings=("set clk timed",) if args.timed else ())
    for failure in result.failures:
        print(failure.where(args.script), file=sys.stderr)
    forth_lines = sum(1 for s in steps if s.kind == "forth")
    print(f"{args.script}: {result.steps_run} of {len(steps)} steps run "
          f"({forth_lines} FORTH lines in the script), {len(result.failures)} failed; "
          f"transcript {transcript_path}, trace {trace_path}")
    return 1 if result.failures else 0
