"""The servo's watched words as a history (pure logic): the ticks at which their
values changed, so the page's scope draws a word such as Desire.Pos as the step
it is, at the tick it stepped, instead of today's value across the window.

Only changes are kept: a word that holds its value costs nothing, and a page
holding the last change before a window knows the value all through it. At full
speed more ticks change than a frame carries: every k-th is kept, and always the
last (the page then draws the step up to k ticks late, and says the run was
thinned)."""
from harness.lab.servo_watch import DUMPED


class WordHistory:
    def __init__(self, keep):
        self.keep = keep                 # at most this many changes wait for a frame
        self.ticks = []                  # [time_s, {name: value}] not yet sent
        self.last = None

    def add(self, time_s, servo):
        """The words read at one tick (ServoWatch.values); kept when they changed."""
        values = {name: value for name, value in servo.items() if name not in DUMPED}
        if values != self.last:
            self.last = values
            self.ticks.append([time_s, values])
            del self.ticks[:-self.keep]

    def take(self, budget):
        """The changes since the last call, at most about `budget` of them."""
        ticks, self.ticks = self.ticks, []
        if len(ticks) <= budget:
            return ticks
        k = -(-len(ticks) // budget)
        kept = ticks[::k]
        return kept if kept[-1] is ticks[-1] else kept + [ticks[-1]]
