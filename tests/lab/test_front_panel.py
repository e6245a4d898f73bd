"""The 11/23's front panel: R rows decoded (harness/lab/front_panel.py) and, in a
running lab, the registers, the words named from the dictionary, the block and
line being loaded, and the bus devices' registers reaching the page."""
import re

from harness.lab.dictionary import Memory
from harness.lab.front_panel import WordIndex, decode_psw, panel
from test_sim_prompt_server import answering, session

# full speed: the I/O breakpoint's test waits for a second of 60 interrupts a second
# and the dictionary read that follows (x10 timed out there)
LAB_SPEED = "full"


def test_psw_fields():
    assert decode_psw(0o340) == {"mode": "kernel", "priority": 7, "T": 0,
                                 "N": 0, "Z": 0, "V": 0, "C": 0}
    assert decode_psw(0o300 | 0o20 | 0o5) == {"mode": "kernel", "priority": 6, "T": 1,
                                              "N": 0, "Z": 1, "V": 0, "C": 1}
    assert decode_psw(0o140000)["mode"] == "user"


def test_words_are_named_from_the_dictionary_and_the_map():
    memory = Memory()                      # one chain: a header "SQ" at 1000, cfa 1004
    memory.store(0o2000, [0, 0, 0, 0])     # a vocabulary's four chain heads
    memory.store(0o2000, [0o1000])
    memory.store(0o1000, [0, 2 | (ord("S") << 8), ord("Q")])
    index = WordIndex({0o400: "DUP"})
    index.learn(memory, 0o2000)
    assert index.name_at(0o1006) == "SQ" and index.containing(0o1020) == "SQ"
    assert index.containing(0o500) == "DUP" and index.containing(0o300) is None
    fields = ["1.5"] + ["0"] * 4 + ["1010", "0", "0", "1012"] + ["340", "400"] \
        + ["200", "0", "0", "4000", "4000", "4000", "4000", "1750", "101"]
    shown = panel(fields, index)
    assert shown["pc_in"] == "SQ" and shown["ip_in"] == "SQ" and shown["next"] == "DUP"
    assert shown["psw_fields"]["priority"] == 7
    assert shown["loading"] == {"block": 1000, "line": 1}       # >IN 65: line 1
    assert shown["registers"][4] == {"name": "R4", "role": "IP", "value": "001010"}
    assert panel(["x"], index) is None


def test_the_page_gets_the_panel_while_the_blocks_load(lab_server):
    async def steps(page):
        await page.send({"t": "speed", "v": "x10"})
        await page.type("1000 LOAD\r")
        panels = []

        def kept(message):                   # each panel, until the load's ok
            if message["t"] == "data" and message.get("panel"):
                panels.append(message["panel"])
            return "LOAD  ok" in page.screen
        await page.message(kept, timeout=60)
        await page.send({"t": "speed", "v": "full"})
        return panels
    panels = session(lab_server, steps)
    loading = {p["loading"]["block"] for p in panels if p["loading"]}
    assert loading and loading <= set(range(1000, 1013)), loading
    last = panels[-1]
    assert [r["role"] for r in last["registers"]][4:6] == ["IP", "S (data stack)"]
    assert last["pc_in"] and last["ip_in"]                  # named from the dictionary
    devices = {f'{d["device"]} {d["register"]}': d["value"] for d in last["devices"]}
    assert devices["AAV11-A DAC X"] == "4000" and len(devices["KW11-L LKS"]) == 6


def test_a_breakpoint_on_a_forth_word_stops_with_its_history(lab_server):
    """The page names a word defined a moment ago; the lab reads the dictionary and
    breaks on its code field (through sim>'s own SET CPU HISTORY, BREAK and CONT);
    when the word runs, the page gets the
    instructions before it, each with the word its PC lies in; clearing the
    breakpoint lets the run go on, the word's answer intact."""
    async def steps(page):
        start = len(page.screen)
        await page.type(": TWICE ( n -- 2n ) DUP + ;\r")
        await page.until(r"ok\r\n", start)
        start = len(page.screen)
        await page.send({"t": "break", "word": "twice"})   # defined just now:
        said = await page.until(r"\[lab\] (breakpoint on|no word) [^\r]*\r", start)   # the lab
        assert "breakpoint on twice" in said, said            # reads the dictionary first
        await page.until(r"sim> cont", start)
        await answering(page)                           # the machine runs again
        await page.type("3 TWICE .\r")
        history = (await page.message(lambda m: m["t"] == "history"))["rows"]
        said = page.screen[start:]
        await page.send({"t": "nobreak"})
        await page.until(r"nobreak all[\s\S]*6  ok", start)
        await page.send({"t": "break", "word": "No.Such.Word"})
        await page.until(r"no word No.Such.Word in the dictionary", start)
        return said, history
    said, history = session(lab_server, steps)
    address = re.search(r"breakpoint on twice at ([0-7]{6})", said).group(1)
    assert f"Breakpoint, PC: {address}" in said
    assert len(history) > 5 and all(len(row[0]) == 6 and row[2] for row in history)
    names = [row[3] for row in history]
    assert all(names) and len(set(names)) > 1       # each PC named: the interpreter's words


def test_an_io_breakpoint_and_instruction_steps_from_the_page(lab_server):
    """A bad I/O address is refused before anything is typed, one where no device
    answers by SIMH (nothing set); SET LAB IOBREAK=170440 stops the servo at its
    write of DAC X with the history and the line defining the word it stopped in
    (block 1008's Interrupt.Servo); Step 1 instruction executes one and the panel
    shows the new PC; the interrupts per second come with the panel (60 at vector
    100); Clear goes on."""
    async def steps(page):
        start = len(page.screen)
        await page.type("Set.Up.Robot\r")                    # after 1000 LOAD (above)
        await page.until(r"Set.Up.Robot  ok", start)
        await page.send({"t": "iobreak", "address": "170441"})
        await page.until(r"170441 is not an even I/O page address", start)
        await page.send({"t": "iobreak", "address": "170460"})
        await page.until(r"not set: IOBREAK: no device answers at 170460[\s\S]*cont", start)
        ticking = await page.message(lambda m: m["t"] == "data" and m["panel"] and any(
            v["vector"] == "100" and v["per_s"] == 60.0 for v in m["panel"].get("interrupts", [])))
        await page.message(lambda m: m["t"] == "data" and "Desire.Pos" in m["servo"])
        # the lab has read the loaded dictionary (the servo's words are found in it)
        await page.send({"t": "iobreak", "address": "170440"})
        history = await page.message(lambda m: m["t"] == "history")
        pcs = []
        for _ in range(2):
            await page.send({"t": "stepi"})
            stepped = await page.message(lambda m: m["t"] == "data" and m["panel"] and
                                          m["panel"]["registers"][7]["value"] not in pcs)
            pcs.append(stepped["panel"]["registers"][7]["value"])
        mark = len(page.screen)                              # Step pressed twice at once:
        await page.send({"t": "stepi"})   # the two take turns at sim>
        await page.send({"t": "stepi"})
        await page.until(r"Step expired[\s\S]*Step expired", mark)
        await page.send({"t": "nobreak"})
        await page.until(r"set lab noiobreak[\s\S]*cont", start)
        mark = len(page.screen)
        await page.type("2 3 + .\r")
        await page.until(r"5  ok", mark)
        return page.screen[start:], ticking["panel"]["interrupts"], history, pcs
    said, interrupts, history, pcs = session(lab_server, steps)
    assert said.count("170441") == 1                         # refused here: nothing typed
    rates = {v["vector"]: v for v in interrupts}
    assert rates["100"]["device"] == "KW11-L" and rates["100"]["per_s"] == 60.0
    assert rates["060"]["total"] > 0
    assert re.search(r"I/O break: write [0-7]{6} to 170440 \(AAV11-A DAC X\)", history["what"])
    assert history["what"].endswith("in Interrupt.Servo")
    last = history["rows"][-1]                           # the instruction that wrote DAC X
    assert "170440" in last[2] and last[3] == "Interrupt.Servo"
    assert history["where"] == {"word": "Interrupt.Servo", "block": 1008, "line": 1,
                                "pc": last[0]}
    assert len(pcs) == 2 and said.count("Step expired") == 4
