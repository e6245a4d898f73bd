"""The front panel from the LAB device's R and I rows, decoded when a page looks
(pure logic).

The device writes an R row (the registers, front_panel.panel) and an I row (the
interrupts taken, front_panel.interrupt_counts) at every reported tick: 600 of
each a wall second at x10, nearly all of which no page ever sees (a frame shows
the newest). So the rows are kept as they came and decoded when a frame goes to
a page, with what decoding each as it came gave: the newest R row's panel, with
the interrupts per second of the I rows after it; an I row counts only while the
panel before it is readable. While no page looks, the newest KEEP rows are
kept: the rates' window (one simulated second, at most 60 reported ticks
between two SHOW LAB PANELs) lies well inside them.
"""
from collections import deque

from harness.lab.feed import lab_row
from harness.lab.front_panel import InterruptRates, interrupt_counts, panel, panel_numbers

KEEP = 512                      # R and I rows kept undecoded: over 4 simulated seconds


class PanelFeed:
    def __init__(self, words):
        self.words = words                  # front_panel.WordIndex, names the PC's word
        self.rates = InterruptRates()
        self.waiting = deque(maxlen=KEEP)   # R and I lines (bytes) not decoded yet
        self.shown = None                   # the panel as of the rows decoded so far

    def add(self, line):
        """An R or I line as the device wrote it."""
        self.waiting.append(line)

    def panel(self):
        """The panel for the page (front_panel.panel, with "interrupts" once an I row
        followed its R row), or None while none is readable."""
        rows = [lab_row(line) for line in self.waiting]
        self.waiting.clear()
        last_r = max((i for i, row in enumerate(rows) if row.kind == "R"), default=None)
        readable, counted = self.shown is not None, False
        for i, row in enumerate(rows):
            if row.kind == "R":
                if i == last_r:
                    self.shown = panel(row.fields, self.words)
                    readable, counted = self.shown is not None, False
                else:
                    readable = panel_numbers(row.fields) is not None
            else:
                counts = interrupt_counts(row.fields)
                if readable and counts:
                    self.rates.add(*counts)
                    counted = True                # on the panel shown now
        if counted:
            self.shown["interrupts"] = self.rates.rates()
        return self.shown
