"""Where a word was defined (harness/lab/word_source.py), the interrupts per second
(front_panel.InterruptRates) and the program pane's one-listing-at-a-time rule
(program_pane.LatestQuestion)."""
import asyncio
import threading
import time

from harness.lab.front_panel import InterruptRates, interrupt_counts
from harness.lab.program_pane import LatestQuestion, ProgramPane
from harness.lab.word_source import definition, definitions
from harness.machine.build import PRISTINE_DISK


def block(*lines):
    return [line.ljust(64) for line in lines] + [" " * 64] * (16 - len(lines))


BLOCKS = [
    (1008, block("( Interrupt.Servo )", "CODE Interrupt.Servo ( <>--<>, : Fake )",
                 "    Save-Regs RTI,", ": Install.Int.Servo ( -- )", "  ' Interrupt.Servo 100O ! ;")),
    (1031, block("( a second servo )", ": Ramp ( -- ) ;",
                 "CODE Interrupt.Servo ( -- )  RTI,", ": Install.Int.Servo ;")),
]


def test_definitions_skip_comments_and_find_each_defining_word():
    assert definitions(BLOCKS) == [("INTERRUPT.SERVO", 1008, 1), ("INSTALL.INT.SERVO", 1008, 3),
                                   ("RAMP", 1031, 1), ("INTERRUPT.SERVO", 1031, 2),
                                   ("INSTALL.INT.SERVO", 1031, 3)]
    assert definition("fake", BLOCKS) is None                 # inside a comment
    assert definition("DUP", BLOCKS) is None                  # the kernel's: no line


def test_the_definition_whose_neighbours_match_the_dictionarys_is_taken():
    assert definition("interrupt.servo", BLOCKS) == (1031, 2)            # no clue: the last
    assert definition("Interrupt.Servo", BLOCKS, ["Restore-Regs"], ["Install.Int.Servo"]) \
        == (1031, 2)                                                      # both fit after it
    assert definition("Interrupt.Servo", BLOCKS, ["Change.Speed?"], ["Install.Int.Servo"]) \
        == (1031, 2)
    assert definition("Interrupt.Servo", BLOCKS, ["Ramp"], []) == (1031, 2)
    assert definition("Interrupt.Servo", BLOCKS, ["Ramp"][:0], ["Install.Int.Servo", "Ramp"]) \
        == (1008, 1)                                                      # 1008 then 1031


def test_the_printed_blocks_place_their_words(tmp_path):
    pane = ProgramPane(PRISTINE_DISK)
    # its neighbours in the dictionary after 1000 LOAD, as the server passes them:
    # block 1080 (an 11/03's servo) defines a Velocity too
    assert pane.where_defined("Velocity", ["MaxVel", "State", "Desire.Pos"],
                              ["Increment", "0-Vel", "Command.Status"]) == \
        {"word": "Velocity", "block": 1000, "line": 4}
    assert pane.where_defined("Interrupt.Servo", ["Change.Speed?"], ["Install.Int.Servo"]) == \
        {"word": "Interrupt.Servo", "block": 1008, "line": 1}
    assert pane.where_defined("EMIT") is None and pane.where_defined(None) is None


def test_interrupts_per_second_over_the_last_simulated_second():
    rates = InterruptRates()
    for tick in range(121):                          # two seconds of 60 Hz ticks
        rates.add(tick / 60, {0o100: tick, 0o60: tick // 30})
    shown = rates.rates()
    by_vector = {v["vector"]: v for v in shown}
    assert by_vector["100"] == {"vector": "100", "device": "KW11-L", "total": 120, "per_s": 60.0}
    assert by_vector["060"]["per_s"] == 2.0 and by_vector["300"]["per_s"] == 0.0
    assert [v["vector"] for v in shown][:6] == ["060", "064", "100", "160", "300", "304"]
    assert interrupt_counts(["1.5", "100=90", "60=3"]) == (1.5, {0o100: 90, 0o60: 3})
    assert interrupt_counts(["1.5"]) == (1.5, {}) and interrupt_counts(["x", "1"]) is None
    rates.add(0.0, {})
    assert rates.rates()[2]["per_s"] is None         # a new machine: no second yet


def test_listings_go_one_at_a_time_and_a_superseded_question_is_skipped():
    """The program pane's flake: following 1000 LOAD asked for a dozen listings (a
    SIMH run or two each) at once; the page's own question waited behind them all.
    Now one runs at a time and a page's earlier questions are dropped."""
    ran, running, most = [], [0], [0]
    lock = threading.Lock()

    def work(block):
        with lock:
            running[0] += 1
            most[0] = max(most[0], running[0])
        time.sleep(0.05)
        with lock:
            running[0] -= 1
        ran.append(block)
        return {"block": block}

    async def ask():
        questions = LatestQuestion()
        follow = [questions.answer("page", n, work) for n in range(1000, 1013)]
        other = questions.answer("another page", 200, work)
        return await asyncio.gather(*follow, other)

    answers = asyncio.run(ask())
    assert answers == [{"block": 1000}] + [None] * 11 + [{"block": 1012}, {"block": 200}]
    assert ran == [1000, 1012, 200] and most[0] == 1
