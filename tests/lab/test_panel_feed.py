"""The front panel decoded when a page looks (harness/lab/panel_feed.py): the same
panel, interrupts per second included, as decoding every R and I row as it came."""
import json
import random

from harness.lab.feed import lab_row
from harness.lab.front_panel import InterruptRates, WordIndex, interrupt_counts, panel
from harness.lab.panel_feed import KEEP, PanelFeed

WORDS = WordIndex({0o400: "DUP", 0o1000: "SQ"})


class OneByOne:
    """How the server read R and I rows before: each decoded as it came."""

    def __init__(self):
        self.panel, self.rates = None, InterruptRates()

    def add(self, line):
        row = lab_row(line)
        if row.kind == "R":
            self.panel = panel(row.fields, WORDS)
        else:
            counts = interrupt_counts(row.fields)
            if self.panel and counts:
                self.rates.add(*counts)
                self.panel["interrupts"] = self.rates.rates()


def r_row(time, pc, readable=True):
    fields = [f"{time:.6f}"] + ["0"] * 7 + [f"{pc:o}", "340", "400", "200", "0", "0"] \
        + ["4000"] * 4 + ["1750", "101"]
    return ("R," + ",".join(fields if readable else fields[:5] + ["9"] + fields[6:])).encode()


def i_row(time, tick, readable=True):
    return f"I,{time:.6f},100={tick},60={tick // 30}{'' if readable else ',x=1'}".encode()


def stream(rng, ticks):
    """R and I rows as the device writes them at 60 reported ticks a simulated
    second, with unreadable ones, a lone I, a lone R and a machine reset among them."""
    lines, time = [], 0.0
    for tick in range(ticks):
        time = 0.0 if tick == ticks // 2 else time + 1 / 60          # a new machine
        if rng.random() > 0.05:
            lines.append(r_row(time, 0o1000 + 2 * tick, rng.random() > 0.1))
        if rng.random() > 0.05:
            lines.append(i_row(time, tick, rng.random() > 0.1))
    return lines + [b"R", b"I", b"I,2.0", b"R,x"]


def test_the_panel_is_the_one_decoding_each_row_gave():
    rng = random.Random(18)
    lines = stream(rng, 600)
    for end in range(len(lines) - 4, len(lines) + 1):                  # the odd rows last
        feed, before, looked = PanelFeed(WORDS), OneByOne(), 0
        for i, line in enumerate(lines[:end]):
            feed.add(line)
            before.add(line)
            if rng.random() < 0.2 or i == end - 1:                    # a frame goes out
                assert json.dumps(feed.panel()) == json.dumps(before.panel)
                looked += 1
        assert looked > 100
    assert before.panel is None                                       # b"R,x" at the end


def test_while_no_page_looks_the_newest_rows_are_kept():
    lines = [row for tick in range(1200) for row in (r_row(tick / 60, 0o1000),
                                                      i_row(tick / 60, tick))]
    feed, before = PanelFeed(WORDS), OneByOne()
    for line in lines:
        feed.add(line)
        before.add(line)
    assert len(feed.waiting) == KEEP
    shown = feed.panel()
    assert shown["interrupts"][2]["per_s"] == 60.0
    assert json.dumps(shown) == json.dumps(before.panel)
