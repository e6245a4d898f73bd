"""The runs behind docs/learning.md: the ASN (blocks 1070-1078, a
reconstruction) learning to move the emulated robot on the printed 1983
servo, by scripted runs (`python -m harness run`: lock-step, deterministic).

    python -m harness.figures.asn_runs OUTDIR [--trials N] [--figures DIR]

Writes in OUTDIR the scripts, their transcripts, the learning run's plant
trace (learn.trace.csv), and
trials.csv (the learning run: a row per trial), trials-again.csv (the same
script run again: must be the same bytes), control.csv (Rate 0: no
learning). Checks, and prints: the model (harness/analysis/asn_model.py)
chooses the FORTH's action at every step and ends with its weights; the
mean steps of the last ten trials against the first ten, learning and
control. Exit status 1 when a check fails. With --figures, draws
asn-learning.png, asn-paths.png and asn-weights.png there (and in OUTDIR).
"""
import argparse
import subprocess
import sys
import time
from pathlib import Path

from harness.analysis import asn_log, asn_model
from harness.analysis import trace as tr

LINE_LIMIT = 900          # simulated s a Trial line may take: 100 steps of at most ~2 s
SAMPLE = 20               # plant trace samples per simulated second


def script_text(trials, rate=None, seed=None):
    """A console script: load, set up (another Rate, another seed), then
    `trials` Trial lines, each followed by SHOW CLK (the trial's end time),
    then .Net."""
    lines = ["# The ASN learning on the emulated robot (make asn-runs, docs/learning.md)",
             f"#simh set plant sample={SAMPLE}",
             "1000 LOAD 1070 LOAD",
             "Set.Up.Robot" + ("" if rate is None else f" {rate} Rate !")
             + ("" if seed is None else f" {seed} Seed0 ! Reset.Net"),
             "#simh show clk"]
    for _ in range(trials):
        lines += ["Trial", "#simh show clk"]
    lines.append(".Net")
    return "\n".join(lines) + "\n"


def run(outdir, name, trials, rate=None, seed=None, keep_trace=False):
    """Run the script; (transcript text, trace path or None, wall seconds).
    Only a kept plant trace stays (each is some 30 MB, the control's 150)."""
    path = outdir / f"{name}.script"
    path.write_text(script_text(trials, rate, seed))
    t0 = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "harness", "run", str(path),
                           "--out", str(outdir), "--line-limit", str(LINE_LIMIT)],
                          capture_output=True, text=True)
    wall = time.monotonic() - t0
    if done.returncode:
        raise SystemExit(f"asn-runs: {name}: python -m harness run failed:\n"
                         f"{done.stdout}{done.stderr}")
    trace = outdir / f"{name}.trace.csv"
    if not keep_trace:
        trace.unlink()
        trace = None
    return (outdir / f"{name}.transcript").read_text(), trace, wall


def agreement(trials, text, params):
    """Steps where the model's action differs from the FORTH's; whether the
    weights .Net printed are the model's after the same trials."""
    net = asn_model.Asn(params)
    actions = asn_log.actions_of(trials)
    differ = [(k, n) for k, n, _, _, a in
              asn_model.replay(net, asn_log.steps_of(trials)) if a != actions[k - 1][n]]
    done, seed, weights = asn_log.parse_net(text)
    same = (done, seed, weights) == (net.trials, net.seed, net.weights)
    return differ, same, net


def means(trials):
    s = [t.n_steps for t in trials]
    return sum(s[:10]) / 10, sum(s[-10:]) / 10


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("outdir", type=Path)
    ap.add_argument("--trials", type=int, default=50)
    ap.add_argument("--figures", type=Path, metavar="DIR")
    ap.add_argument("--other-seeds", type=int, nargs="*", default=[1, 2, 3, 4], metavar="SEED",
                    help="learning runs with these noise seeds too, reported only")
    a = ap.parse_args(argv)
    a.outdir.mkdir(parents=True, exist_ok=True)
    params = asn_model.Params.from_blocks()
    failed = []

    results = {}
    for name, rate in (("learn", None), ("again", None), ("control", 0)):
        text, trace, wall = run(a.outdir, name, a.trials, rate, keep_trace=name == "learn")
        trials = asn_log.parse(text)
        if len(trials) != a.trials:
            raise SystemExit(f"asn-runs: {name}: {len(trials)} trials in the transcript, "
                             f"{a.trials} asked for")
        csv = {"learn": "trials.csv", "again": "trials-again.csv",
               "control": "control.csv"}[name]
        (a.outdir / csv).write_text(asn_log.csv_text(trials, params.goal_size))
        results[name] = (text, trace, trials)
        steps = sum(t.n_steps for t in trials)
        late = sum(t.late for t in trials)
        sim = trials[-1].end_time - trials[0].start_time
        first, last = means(trials)
        print(f"==> {name}: {a.trials} trials, {steps} steps, {late} moves late "
              f"({100 * late / steps:.1f} %), {sim:.1f} simulated s, {wall:.1f} s wall "
              f"(host load inflates it); mean steps first 10 {first:.1f}, last 10 "
              f"{last:.1f} (ratio {last / first:.3f})")
        differ, same, net = agreement(trials, text, params.but(rate=0) if rate == 0 else params)
        print(f"    model: {steps + len(trials) - len(differ)} of {steps + len(trials)} steps "
              f"agree; weights after the run {'the same' if same else 'DIFFER'}")
        if differ or not same:
            failed.append(f"{name}: the model disagrees (first at trial, step {differ[:1]})")

    first, last = means(results["learn"][2])
    if not last <= first / 3:
        failed.append(f"learning: last 10 mean {last:.1f} > a third of the first 10 {first:.1f}")
    c_first, c_last = means(results["control"][2])
    if c_last < c_first * 0.8:
        failed.append(f"control: Rate 0 improved ({c_first:.1f} -> {c_last:.1f})")
    same_csv = (a.outdir / "trials.csv").read_bytes() == (a.outdir / "trials-again.csv").read_bytes()
    print(f"    trials.csv and trials-again.csv: {'the same bytes' if same_csv else 'DIFFER'}")
    if not same_csv:
        failed.append("two runs of the same script wrote different CSVs")

    for seed in a.other_seeds:
        text, _, wall = run(a.outdir, f"seed-{seed}", a.trials, seed=seed)
        trials = asn_log.parse(text)
        first, last = means(trials)
        differ, same, _ = agreement(trials, text, params.but(seed=seed))
        print(f"==> seed {seed}: mean steps first 10 {first:.1f}, last 10 {last:.1f} "
              f"(ratio {last / first:.3f}); model {'agrees' if same and not differ else 'DIFFERS'}; "
              f"{wall:.1f} s wall")
        if differ or not same:
            failed.append(f"seed {seed}: the model disagrees")

    if a.figures:
        draw(a.figures, a.outdir, results, params)
    for f in failed:
        print(f"asn-runs: FAILED: {f}", file=sys.stderr)
    return 1 if failed else 0


def draw(figdir, outdir, results, params):
    from harness.analysis import asn_plots, plots
    figdir.mkdir(parents=True, exist_ok=True)
    text, trace, trials = results["learn"]
    numbers = [n for n in (1, 10, 50) if n <= len(trials)]
    done, _, weights = asn_log.parse_net(text)
    figures = {"asn-learning.png": asn_plots.learning_figure(trials, results["control"][2]),
               "asn-paths.png": asn_plots.paths_figure(trials, numbers, params, tr.read(trace)),
               "asn-weights.png": asn_plots.weights_figure(weights, params, done)}
    for name, fig in figures.items():
        plots.save(fig, [figdir / name, outdir / name])
        print(figdir / name)


if __name__ == "__main__":
    sys.exit(main())
