"""What the ASN blocks (1070-1078) printed, as trials: each step's counters
and action (`S x y action`, the last step of a trial without an action),
each trial's summary (`T trial steps late payoff`), and the simulated time
SIMH's `SHOW CLK` gave after it in a scripted run's transcript (the script
puts `#simh show clk` after each `Trial` line). Pure parsing; the CSV
columns of build/asn/trials.csv.

    trials = parse(transcript_text)     # [Trial]
    csv_text(trials)                    # header trial,steps,... and a row each
"""
import re
from dataclasses import dataclass, field

STEP = re.compile(r"^S (-?\d+) (-?\d+)(?: (\d+))? *$")
SUMMARY = re.compile(r"^T (\d+) (\d+) (\d+) (-?\d+)(?: +ok)? *$")
CLOCK = re.compile(r"time=([\d.]+)s")
TRIAL_COLUMNS = ("trial", "steps", "reached_goal", "late_moves", "final_payoff",
           "start_x", "start_y", "end_x", "end_y", "end_time_s")


class LogError(ValueError):
    pass


@dataclass
class Trial:
    number: int = 0
    steps: list = field(default_factory=list)   # (x, y, action or None)
    late: int = 0                  # moves Settle gave up waiting for
    payoff: int = 0                # z at the last step: minus the distance left
    start_time: float = None       # simulated s: the SHOW CLK before it
    end_time: float = None         # simulated s, from the SHOW CLK after it

    @property
    def n_steps(self):
        return len(self.steps) - 1       # the last step reads, does not act

    @property
    def path(self):
        return [(x, y) for x, y, _ in self.steps]


def parse(text):
    """The trials in a transcript (or a FORTH line's output), in order."""
    trials, current = [], Trial()
    for line in text.replace("\r", "").split("\n"):
        line = line.strip()
        if m := STEP.match(line):
            x, y, a = m.groups()
            current.steps.append((int(x), int(y), None if a is None else int(a)))
        elif m := SUMMARY.match(line):
            number, steps, late, payoff = map(int, m.groups())
            if steps != current.n_steps:
                raise LogError(f"trial {number}: {steps} steps said, "
                               f"{current.n_steps} printed")
            current.number, current.late, current.payoff = number, late, payoff
            trials.append(current)
            current = Trial()
        elif m := CLOCK.search(line):
            if trials and trials[-1].end_time is None:
                trials[-1].end_time = float(m.group(1))
            current.start_time = float(m.group(1))
    return trials


NET = re.compile(r"^N (\d+) (\d+) *$")
ROW = re.compile(r"^W((?: -?\d+)+)(?: +ok)? *$")


def parse_net(text):
    """.Net's answer: (trials done, seed, weights [element][input])."""
    head, rows = None, []
    for line in text.replace("\r", "").split("\n"):
        line = line.strip()
        if m := NET.match(line):
            head, rows = (int(m.group(1)), int(m.group(2))), []
        elif (m := ROW.match(line)) and head:
            rows.append([int(v) for v in m.group(1).split()])
    if head is None or not rows:
        raise LogError("no .Net answer (N trials seed, then W rows) in the text")
    return head[0], head[1], rows


def steps_of(trials):
    """Each trial's counters, as asn_model.replay takes them."""
    return [[(x, y) for x, y, _ in t.steps] for t in trials]


def actions_of(trials):
    return [[a for _, _, a in t.steps] for t in trials]


def csv_text(trials, goal_size, goal=(1600, 1600)):
    """trials.csv: one row a trial."""
    rows = [",".join(TRIAL_COLUMNS)]
    for t in trials:
        (sx, sy, _), (ex, ey, _) = t.steps[0], t.steps[-1]
        reached = int(abs(ex - goal[0]) <= goal_size and abs(ey - goal[1]) <= goal_size)
        end = "" if t.end_time is None else f"{t.end_time:.3f}"
        rows.append(",".join(str(v) for v in (t.number, t.n_steps, reached, t.late,
                                             t.payoff, sx, sy, ex, ey, end)))
    return "\n".join(rows) + "\n"
