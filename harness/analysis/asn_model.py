"""The Associative Search Network of blocks 1070-1075 (docs/learning.md), in
Python, step for step and bit for bit: the same 16-bit fixed point (FORTH's
`*/` and `/` round towards zero, cells wrap at 16 bits), the same
pseudo-random sequence, the same order of operations. A RECONSTRUCTION
after Barto, Sutton & Brouwer 1981 and Barto & Sutton 1981 (see the doc),
not 1983 code.

    net = Asn(Params.from_blocks())       # the parameters the blocks load
    net.start_trial()
    action = net.step(cx, cy)             # counters read at a step -> 0..3,
                                          # or None: the trial ends here
    net.weights                           # [output][input], 16-bit

The model does not simulate the robot: given the counters the FORTH read at
each step, it must choose the actions the FORTH chose (tests/learning). The
`ideal_plant` below is only for exploring parameters off the emulator.
"""
import re
from dataclasses import dataclass, replace
from pathlib import Path

from harness.machine.build import ROOT

BLOCKS = ROOT / "blocks"
PARAMETER_BLOCK = 1070
FIELDS, FIELD_SPACING, FIELD_REACH = 9, 400, 800   # per axis; counts
N_IN, N_OUT = 2 * FIELDS, 4     # the fields along x, then y; +x -x +y -y
W_LIMIT, R_LIMIT = 16000, 1000
ACTIONS = ("+x", "-x", "+y", "-y")


@dataclass(frozen=True)
class Params:
    arena: int = 3200           # side of the square arena, counts (0..arena)
    goal_x: int = 1600
    goal_y: int = 1600
    step_size: int = 400        # counts per move
    goal_size: int = 200        # |dx| and |dy| at most this: at the goal
    max_steps: int = 100
    rate: int = 16              # learning rate c, in 1/16384 per count of payoff
    noise: int = 8192           # noise amplitude at first, units of s
    cooling: int = 10           # the noise falls as cooling / (cooling + trials)
    seed: int = 1983

    # the FORTH names of the fields, as block 1070 defines them
    NAMES = {"arena": "Arena", "goal_x": "Goal.X", "goal_y": "Goal.Y",
             "step_size": "Step.Size", "goal_size": "Goal.Size",
             "max_steps": "Max.Steps", "rate": "Rate", "noise": "Noise", "cooling": "Cooling",
             "seed": "Seed0"}

    @classmethod
    def from_blocks(cls, blocks=BLOCKS):
        """The values block 1070 gives (`N VAR Name` / `N CON Name`)."""
        text = (Path(blocks) / f"{PARAMETER_BLOCK}.txt").read_text()
        found = dict((name, int(n)) for n, name in
                     re.findall(r"(-?\d+)\s+(?:VAR|CON)\s+(\S+)", text))
        missing = [f for f in cls.NAMES.values() if f not in found]
        if missing:
            raise ValueError(f"block {PARAMETER_BLOCK} defines no {', '.join(missing)}")
        return cls(**{field: found[name] for field, name in cls.NAMES.items()})

    def but(self, **changes):
        return replace(self, **changes)


def cell(n):
    """n as a signed 16-bit cell."""
    n &= 0xFFFF
    return n - 0x10000 if n & 0x8000 else n


def quot(a, b):
    """FORTH's / : the quotient rounded towards zero."""
    q = abs(a) // abs(b)
    return q if (a < 0) == (b < 0) else -q


def star_slash(a, b, c):
    """FORTH's */ : a*b with a 32-bit product, divided by c towards zero."""
    return cell(quot(a * b, c))


def field(pos, centre):
    """Block 1071's Field: a receptive field's response, 64 at its centre
    falling linearly to 0 at FIELD_REACH counts from it."""
    return max(0, 64 - star_slash(abs(pos - centre), 64, FIELD_REACH))


def sense(x, y):
    """Block 1071's Sense: the input pattern at counters x, y: FIELDS
    fields along x, then FIELDS along y."""
    return ([field(x, k * FIELD_SPACING) for k in range(FIELDS)]
            + [field(y, k * FIELD_SPACING) for k in range(FIELDS)])


class Asn:
    def __init__(self, params=None):
        self.p = params or Params.from_blocks()
        self.weights = [[0] * N_IN for _ in range(N_OUT)]
        self.seed = self.p.seed
        self.trials = 0
        self.start_trial()

    # -- block 1072: the pseudo-random noise
    def random(self):
        self.seed = (self.seed * 25173 + 13849) & 0xFFFF
        return self.seed

    def jitter(self):
        """Block 1072's Jitter: uniform, +-noise cooled to noise * cooling /
        (cooling + trials done)."""
        amplitude = star_slash(self.p.noise, self.p.cooling, self.p.cooling + self.trials)
        return star_slash((self.random() >> 8) - 128, amplitude, 128)

    # -- block 1072: the elements
    def activation(self, j, x):
        return cell(sum(star_slash(self.weights[j][i], x[i], 256) for i in range(N_IN)))

    def choose(self, x):
        """Block 1072's Choose: the element whose weighted sum plus noise is
        largest acts (the first of equals); one axis moves a step."""
        best, choice = -32767, 0
        for j in range(N_OUT):
            s = cell(self.activation(j, x) + self.jitter())
            if s > best:
                best, choice = s, j
        return choice

    def learn(self, r):
        """Block 1073's Learn: w_ij += c r (y_j - 1/4) x_i, x the pattern
        acted on, y_j 1 for the element that acted and 0 for the others:
        3d for it, -d for each other, d = c r x_i / 4."""
        for i in range(N_IN):
            d = star_slash(cell(self.x_was[i] * self.p.rate), r, 16384)
            for j in range(N_OUT):
                w = cell(self.weights[j][i] + (3 * d if j == self.act else -d))
                self.weights[j][i] = min(max(w, -W_LIMIT), W_LIMIT)

    def payoff(self, x, y):
        return -(abs(x - self.p.goal_x) + abs(y - self.p.goal_y))

    def at_goal(self, x, y):
        return (abs(x - self.p.goal_x) <= self.p.goal_size
                and abs(y - self.p.goal_y) <= self.p.goal_size)

    # -- block 1074: one step of a trial
    def start_trial(self):
        self.steps, self.act, self.z_was, self.x_was = 0, 0, 0, [0] * N_IN
        self.blocked = 0

    def step(self, x, y):
        """Counters x, y read at the step: the action (0..3), or None when
        the trial ends (at the goal, or after max_steps)."""
        pattern, z = sense(x, y), self.payoff(x, y)
        if self.steps > 0:
            r = z - self.z_was - self.blocked * self.p.step_size
            self.learn(min(max(r, -R_LIMIT), R_LIMIT))
        self.z_was = z
        if self.at_goal(x, y) or self.steps >= self.p.max_steps:
            return None
        self.act = self.choose(pattern)
        self.x_was = pattern
        self.steps += 1
        return self.act

    def target(self, action, desired):
        """Block 1074's Act.Move: the new x y target from the old one;
        self.blocked is 1 when the arena's edge stopped the move."""
        x, y = desired
        d = self.p.step_size if action % 2 == 0 else -self.p.step_size
        nx, ny = (x, y + d) if action // 2 else (x + d, y)
        clip = lambda v: min(max(v, 0), self.p.arena)
        self.blocked = int((clip(nx), clip(ny)) != (nx, ny))
        return clip(nx), clip(ny)


START_CORNERS = ((0, 0), (3200, 0), (3200, 3200), (0, 3200))


def start_of(trial, p):
    """Block 1075's Start: trial k (from 1) starts at corner (k-1) mod 4."""
    cx, cy = START_CORNERS[(trial - 1) % 4]
    return min(cx, p.arena), min(cy, p.arena)


def ideal_plant(net, trials, hunt=30):
    """Trials on a stand-in for the robot: each move reaches its target
    within +-hunt counts (pseudo-random, fixed seed). For exploring
    parameters only; the figures and tests use the emulated robot."""
    import random
    rng = random.Random(7)
    steps = []
    for k in range(1, trials + 1):
        net.start_trial()
        desired = start_of(net.trials + 1, net.p)
        while True:
            x, y = (v + rng.randint(-hunt, hunt) for v in desired)
            a = net.step(x, y)
            if a is None:
                break
            desired = net.target(a, desired)
        net.trials += 1
        steps.append(net.steps)
    return steps


def replay(net, trials):
    """Run the model on what the FORTH read: `trials` is a list of trials,
    each a list of (x, y) counters, one per step (the last one the step that
    ended it). Yields (trial, step, x, y, the model's action or None), the
    servo's targets kept as block 1074 keeps them in Desire.Pos."""
    for k, steps in enumerate(trials, start=1):
        net.start_trial()
        desired = start_of(net.trials + 1, net.p)
        for n, (x, y) in enumerate(steps):
            action = net.step(x, y)
            yield k, n, x, y, action
            if action is None:
                break
            desired = net.target(action, desired)
        net.trials += 1
