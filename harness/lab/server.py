"""The lab bench's web server (web.py): the page, its assets, one websocket.

The messages both ways are defined once, in protocol.py; every message from a
page is checked against it, and one that is not the protocol's gets one `error`
back and changes nothing. Who may connect: guard.py.

One keyboard per lab: one source (a page, or the shell the lab was started in)
holds it; the others watch and are told who holds it; a page takes it with its
button (`take`), the shell with ^T. The first to type takes it when nobody holds
it. A new holder starts on an empty line (^U after an unfinished one), so lines
never mix.
"""
import asyncio
import json
import signal
import sys
from pathlib import Path

from harness.lab import breakpoints, guard, lesson_checks, protocol, shell_terminal, web
from harness.lab.feed import (WordRows, lab_row, memory_of, other_lines, plant_lines,
                              plant_rows, thin)
from harness.lab.front_panel import PANEL_WORDS, WordIndex
from harness.lab.panel_feed import PanelFeed
from harness.lab.program_pane import LatestQuestion, ProgramPane
from harness.lab.rack_hint import RackHint
from harness.lab.servo_watch import PER_AXIS, SINGLE, ServoWatch
from harness.lab.word_history import WordHistory
from harness.lab.session import SPEEDS, Simulator
from harness.machine.build import BUILD
from harness.machine.console_session import quiet_stdout
from harness.machine.kernel_layout import BODY

STATIC = Path(__file__).resolve().parent / "static"
NODE_MODULES = BUILD / "lab" / "node_modules"
VENDOR = {  # URL name -> file installed by `npm ci` (mk/lab.mk)
    "xterm.js": "@xterm/xterm/lib/xterm.js",
    "xterm.css": "@xterm/xterm/css/xterm.css",
    "addon-fit.js": "@xterm/addon-fit/lib/addon-fit.js",
    "uplot.js": "uplot/dist/uPlot.iife.min.js",            # the scope (lab-scope.js)
    "uplot.css": "uplot/dist/uPlot.min.css",
}
FRAME_S = 1 / 30                 # how often plant rows and the servo's words go out
FULL_SPEED_FRAME_S = 1 / 10      # at full speed: snapshots anyway, and Chromium's drawing
                                 # would take the simulator's core (docs/lab.md, cost)
UNWATCHED_S = 0.1                # no page: how often what a frame would carry is dropped
                                 # (an idle lab's wake-ups are most of its CPU)
PROBE_S = 1.0                    # how often the dictionary's heads are looked at
DICTIONARY_WAIT_S = 2.0          # a breakpoint's word not known: at most this for a probe
ROWS_PER_FRAME = 400             # more than this (fast runs) are thinned per axis
FRONT_PANEL_ROWS = (b"R", b"I")  # the LAB device's rows panel_feed.py decodes
TICKS_PER_FRAME = 100            # changes of the watched words per frame (word_history.py)
SCROLLBACK = 1 << 17
SHELL = "the shell"
TAKE_KEY = b"\x14"               # ^T in the shell: take the keyboard
SEND_WAIT_S = 2.0                # leaving: at most this long for the last frames to go


class Lab:
    """The simulator, the servo watch and the connected pages."""

    def __init__(self, simulator, disk, symbols, speed="real", read_only=False, lister=None,
                 timed=False):
        self.sim = Simulator(simulator, disk, self.on_console, self.on_lab, self.on_ended,
                             speed, page=self.to_pages, read_only=read_only, timed=timed,
                             watched=lambda: bool(self.pages))
        self.shell_echo = None           # the shell's terminal, when it types too
        self.watch = ServoWatch(symbols)
        self.dictionary_read = asyncio.Event()   # a probe's answer read (read_dictionary)
        self.rack_hint = RackHint()
        self.program = ProgramPane(disk, lister)   # the program pane's blocks and listings
        self.listings = LatestQuestion()           # one listing at a time, the latest asked
        self.disk = disk
        self.checking = set()                # exercises whose check runs now
        self.words = WordIndex({address: name for name, address in symbols.items()})
        self.panel_command = "panel " + " ".join(f"{symbols[name] + BODY:o}"
                                                 for name in PANEL_WORDS)
        self.front = PanelFeed(self.words)   # the 11/23's front panel (front_panel.py)
        self._console_tail = b""
        self.pages = {}                  # websocket -> its name ("page 3")
        self.opened = 0
        self.holder = None               # who holds the keyboard: a websocket, SHELL, None
        self.scrollback = bytearray()
        self.rows = []                   # plant rows decoded for the next frame (feed.py)
        self.status = {"time": 0.0, "tick": 0, "state": "run", "speed": speed, "power": "off",
                       "clock": "timed" if timed else "count", "timable": timed, "waiting": 0}
        self.servo = {}
        self.word_rows = WordRows()
        self.ticks = WordHistory(20 * TICKS_PER_FRAME)   # the words' changes, for the scope
        self.sent = None                 # the status and servo words the pages last had
        self.done = asyncio.Event()
        self.safe = None
        self.sending = set()             # frames queued to pages, not yet written

    # ---- from the simulator ---------------------------------------------------------
    def on_console(self, data):
        if self.shell_echo:
            self.shell_echo(data)
        self.to_pages(data)
        self._console_tail = (self._console_tail + data)[-200:]
        hit = breakpoints.HIT.search(self._console_tail)      # a breakpoint was hit
        io_hit = breakpoints.IO_HIT.search(self._console_tail)
        if hit or io_hit:
            self._console_tail = b""
            self.sim.prompted.clear()         # SIMH's prompt follows: the history waits for it
            pc = int((hit or io_hit).group(1 if hit else 2), 8)
            what = io_hit.group(1).decode() if io_hit else f"Breakpoint at PC {pc:06o}"
            asyncio.ensure_future(self.show_history(what, self.words.containing(pc), pc))

    async def show_history(self, what, word, pc):
        """The instructions before a breakpoint, each with its word, to the pages; and
        where that word was defined, for the program pane (which also marks the PC's
        row of the listing)."""
        text = await self._at_sim([f"show cpu history={breakpoints.SHOWN}"], stop=False)
        where = await asyncio.to_thread(self.program.where_defined, word,
                                        *self.words.neighbours(word)) if word else None
        if where:
            where["pc"] = f"{pc:06o}"
        self.broadcast({"t": "history", "rows": breakpoints.named_history(text, self.words),
                        "what": f"{what}, in {word}" if word else what, "where": where})

    async def set_break(self, word):
        if isinstance(word, str) and self.words.address_of(word) is None:
            await self.read_dictionary()         # defined since the last probe?
        lines, said = breakpoints.break_lines(self.words, word)
        self.note(said)
        if lines:
            await self._at_sim(lines)

    async def read_dictionary(self, wait_s=DICTIONARY_WAIT_S):
        """Probe the dictionary now (not at the next PROBE_S) and wait until the
        answer is read: a word defined a moment ago is known by name. Not while
        SIMH has the machine stopped (the device answers only while it runs)."""
        if self.sim.watcher.at_simh:
            return
        self.dictionary_read.clear()
        for command in self.watch.probe():
            self.sim.command(command)
        try:
            await asyncio.wait_for(self.dictionary_read.wait(), wait_s)
        except asyncio.TimeoutError:
            pass                                 # the names as they were

    async def set_iobreak(self, address):
        """SET LAB IOBREAK (io_break.c) at sim>; SIMH's refusal (no device answers
        there) is shown and nothing is set; the machine goes on either way."""
        lines, said = breakpoints.iobreak_lines(address)
        self.note(said)
        if not lines:
            return
        refused = breakpoints.IO_REFUSED.search(await self._at_sim(lines))
        if refused:
            self.note(f"not set: {refused.group(0)}")
        await self._at_sim(["cont"])

    async def step_instruction(self):
        """One instruction at sim> (stopping there first, at a tick), then the front
        panel as it stands (SHOW LAB PANEL writes an R row)."""
        await self._at_sim(breakpoints.STEP_LINES)

    async def _at_sim(self, lines, stop=True):
        try:
            return await self.sim.simh_lines(lines, stop=stop)
        except asyncio.TimeoutError:                  # SIMH busy (a long STEP, a LOAD of
            self.on_console(b"\r\n[lab] SIMH did not come to its prompt within 10 s"
                            b"\r\n")                   # its own): nothing more is typed
            return ""

    def to_pages(self, data):
        self.scrollback += data
        del self.scrollback[:-SCROLLBACK]
        self.broadcast({"t": "con", "d": data.decode("latin-1")})

    def on_lab(self, block):
        """The LAB device's whole lines, as read (bytes). P, R and I rows, most of the
        stream, are decoded only for a page: P rows as they come while one is
        connected, R and I rows when a frame goes out (panel_feed.py); the others
        act at once."""
        if self.pages:
            self.rows += plant_rows(plant_lines(block))
            del self.rows[:-20 * ROWS_PER_FRAME]     # a page that cannot keep up skips
        for line in other_lines(block):
            if line.startswith(b"W,"):
                self.tick_words(*self.word_rows.read(line))
            elif line.partition(b",")[0] in FRONT_PANEL_ROWS:
                self.front.add(line)
            else:
                row = lab_row(line)
                if row:                              # not ",..."
                    self.device_row(row)

    def tick_words(self, time, tick, words):
        """A W row: the watched words at a tick."""
        self.status["time"], self.status["tick"] = time, tick
        servo = self.watch.values(words)
        if servo is not self.servo:          # else the same words: no change to keep
            self.servo = servo
            self.ticks.add(time, servo)
        hint = self.rack_hint.update(self.status["power"], time, self.servo)
        if hint:
            self.on_console(f"\r\n{hint}\r\n".encode())

    def device_row(self, row):
        if row.kind == "M":
            for command in self.watch.on_memory(*memory_of(row)):
                self.sim.command(command)
            if self.watch.settled():
                self.dictionary_read.set()
        elif row.kind == "A":
            self.watch.on_addresses([int(a, 8) for a in row.fields])
            self.words.learn(self.watch.memory, self.watch.vocabulary)   # a fresh dictionary
            if self.watch.settled():
                self.dictionary_read.set()
        elif row.kind == "S":
            self.status["time"] = float(row.fields[0])
            self.status["state"] = row.fields[1]
            if len(row.fields) > 5:
                self.status["power"], self.status["clock"] = row.fields[3:5]
                self.status["timable"] = row.fields[5] == "1"
        elif row.kind == "E":
            print(f"[lab] the LAB device refused a command: {','.join(row.fields)}",
                  file=sys.stderr)

    def on_ended(self, safe):
        self.safe = safe
        self.broadcast({"t": "ended", "safe": safe})
        self.done.set()

    # ---- to the pages ---------------------------------------------------------------
    def broadcast(self, message):
        text = json.dumps(message)
        for ws in list(self.pages):
            self.send_later(ws, text)

    def tell(self, ws, message):
        self.send_later(ws, json.dumps(message))

    def send_later(self, ws, text):
        """Queue a frame to one page. A page that closes between the check and the
        write is not an error: its socket's handler forgets it on the way out."""
        async def send():
            try:
                await ws.send_str(text)
            except ConnectionError:        # web.py's ConnectionResetError is one
                pass
        if not ws.closed:
            task = asyncio.ensure_future(send())
            self.sending.add(task)
            task.add_done_callback(self.sending.discard)

    async def sent_all(self, timeout=SEND_WAIT_S):
        """Wait until every frame queued so far is written (the last report, `ended`),
        at most `timeout` seconds (a page that does not read)."""
        if self.sending:
            await asyncio.wait(set(self.sending), timeout=timeout)

    def refresh_status(self):
        """The status's parts the device's rows do not bring."""
        self.status["waiting"] = self.sim.waiting()
        self.status["prompt"] = self.sim.watcher.at_simh     # SIMH's sim>: stopped

    def hello(self, ws):
        self.refresh_status()
        return {"t": "hello", "stops": self.sim.stops, "plant": self.sim.plant.message(),
                "per_axis": PER_AXIS, "single": SINGLE, "status": self.status,
                "con": self.scrollback.decode("latin-1"), "keyboard": self.keyboard(ws)}

    def note(self, text):
        """A line from the lab to everyone who watches (pages and shell)."""
        self.on_console(f"\r\n[lab] {text}\r\n".encode())

    # ---- the keyboard ---------------------------------------------------------------
    def holder_name(self):
        return SHELL if self.holder == SHELL else self.pages.get(self.holder)

    def keyboard(self, ws):
        return {"t": "keyboard", "holder": self.holder_name(), "you": self.holder is ws}

    def take(self, source):
        if self.holder is source:
            return
        self.sim.erase_line()
        self.holder = source
        for ws in list(self.pages):
            self.tell(ws, self.keyboard(ws))
        if self.shell_echo and source != SHELL:
            self.shell_echo(f"\r\n[lab] {self.holder_name()} holds the keyboard now; "
                            "^T takes it back.\r\n".encode())

    def release(self, source):
        if self.holder is source:
            self.holder = None
            for ws in list(self.pages):
                self.tell(ws, self.keyboard(ws))

    def may_type(self, source):
        if self.holder is None:
            self.take(source)
        return self.holder is source

    def shell_keys(self, data):
        """The shell's keys: ^T takes the keyboard; typed while a page holds it,
        they are refused with a line saying so."""
        if TAKE_KEY in data:
            self.take(SHELL)
            data = data.replace(TAKE_KEY, b"")
        if data and not self.may_type(SHELL):
            self.shell_echo(f"\r\n[lab] {self.holder_name()} holds the keyboard: "
                            "^T takes it.\r\n".encode())
            return
        self.typed(data)

    def typed(self, data, page=False):
        """Keys from the shell (the full SIMH console) or a page (through the guard
        of the page's sim>: session.page_keys)."""
        for note in (self.sim.page_keys(data) if page else self.sim.keys(data)):
            self.note(note)

    async def frames(self):
        while not self.done.is_set():
            await asyncio.sleep(frame_interval(self.status["speed"]) if self.pages
                                else UNWATCHED_S)
            rows, self.rows = thin(self.rows, ROWS_PER_FRAME), []
            ticks = self.ticks.take(TICKS_PER_FRAME)
            if not self.pages:
                continue                 # nobody looks: nothing is decoded (docs/lab.md, cost)
            self.refresh_status()
            panel = self.front.panel()
            state = json.dumps([self.status, self.servo, panel])
            if news(rows + ticks, state, self.sent):
                self.broadcast({"t": "data", "rows": rows, "status": self.status,
                                "servo": self.servo, "panel": panel, "ticks": ticks})
                self.sent = state

    async def probes(self):
        self.sim.command(self.panel_command)     # R rows from now on
        while not self.done.is_set():
            for command in self.watch.probe():
                self.sim.command(command)
            await asyncio.sleep(PROBE_S)

    # ---- from the pages -------------------------------------------------------------
    def on_text(self, ws, text):
        """One message from a page: checked against the protocol, then acted on;
        a bad one gets one `error` back and changes nothing."""
        try:
            kind, message = protocol.parse(text)
            getattr(self, f"on_{kind}")(ws, message)
        except protocol.Refused as why:
            self.tell(ws, {"t": "error", "why": str(why)})

    def on_key(self, ws, message):
        data = message["d"].encode("latin-1", "replace")
        if not self.may_type(ws):
            raise protocol.Refused(f"{self.holder_name()} holds the keyboard: "
                                   "take it to type here")
        room = self.sim.room()
        if len(data) > room and data.strip(b"\x03\x05"):      # ^C and ^E always go
            raise protocol.Refused(f"the input queue is full ({self.sim.waiting()} characters "
                                   f"waiting, room for {room}): send again later")
        self.typed(data, page=True)
        self.tell(ws, {"t": "input", "waiting": self.sim.waiting(), "room": self.sim.room()})

    def on_take(self, ws, message):
        self.take(ws)

    def on_speed(self, ws, message):
        self.status["speed"] = message["v"]
        self.sim.command(f"speed {SPEEDS[message['v']]}")

    def on_power(self, ws, message):
        self.sim.command(f"power {message['v']}")

    def on_clock(self, ws, message):     # the time base: the count, or the 11/23's own
        if message["v"] == "timed" and not self.status["timable"]:
            raise protocol.Refused("the 11/23's clock needs the simulator that prices each "
                                   "instruction: start the lab with --timed (make lab TIMED=1)")
        self.sim.command(f"clock {message['v']}")

    def on_pause(self, ws, message):
        self.sim.command("pause")

    def on_run(self, ws, message):
        at_sim = self.sim.watcher.at_simh    # stopped at sim> (a step, a breakpoint): go on
        if at_sim:
            self.must_hold(ws)
        self.sim.command("run")
        if at_sim:
            asyncio.ensure_future(self._at_sim(["cont"]))

    def on_step(self, ws, message):
        self.sim.command("step")

    def on_break(self, ws, message):     # a breakpoint on a FORTH word (breakpoints.py)
        self.must_hold(ws)
        asyncio.ensure_future(self.set_break(message["word"]))

    def on_iobreak(self, ws, message):   # ... on an I/O register's access (io_break.c)
        self.must_hold(ws)
        asyncio.ensure_future(self.set_iobreak(message["address"]))

    def on_stepi(self, ws, message):     # one instruction (front panel)
        self.must_hold(ws)
        asyncio.ensure_future(self.step_instruction())

    def on_nobreak(self, ws, message):
        self.must_hold(ws)
        asyncio.ensure_future(self._at_sim(breakpoints.clear_lines()))

    def on_program(self, ws, message):   # read only: the page's editor types at the FORTH
        async def answer():
            told = await self.listings.answer(ws, message["block"], self.program.message)
            if told:
                self.tell(ws, told)
        asyncio.ensure_future(answer())

    def on_check(self, ws, message):     # the lessons: an exercise's own check, on the host
        exercise = message["exercise"]
        if exercise in self.checking:
            raise protocol.Refused(f"exercise {exercise}'s check is running already")
        self.checking.add(exercise)

        async def answer():
            try:
                ok, text = await lesson_checks.run_check(exercise, self.disk)
            finally:
                self.checking.discard(exercise)
            self.broadcast({"t": "checked", "exercise": exercise, "text": text, "ok": ok})
        asyncio.ensure_future(answer())

    def must_hold(self, ws):
        """Breakpoints and steps are typed at sim>: only by the keyboard's holder."""
        if not self.may_type(ws):
            raise protocol.Refused(f"{self.holder_name()} holds the keyboard: "
                                   "take it to set breakpoints here")


def frame_interval(speed):
    """Seconds between two data messages: fewer at full speed, where every frame
    shows a jump of several simulated seconds and the page's drawing competes
    with the simulator for the host's cores."""
    return FULL_SPEED_FRAME_S if speed == "full" else FRAME_S


def news(rows, state, sent):
    """Whether a frame holds anything the pages have not had: a paused run sends
    nothing, so the page does not redraw an unchanged picture 30 times a second."""
    return bool(rows) or state != sent


def make_app(lab, token, port_of):
    """The server's handler (web.Server); port_of() gives the port it listens on."""

    def check(request, websocket=False):
        why = guard.refusal(request.host, request.query.get("token") if websocket else None,
                            token, port_of(), request.headers.get("origin"), websocket)
        if why:
            raise web.Forbidden(f"lab: {why}\n")

    async def page(request):
        check(request)
        return web.Response.file(STATIC / "lab.html", [("Cache-Control", "no-store")])

    async def asset(request, name):
        check(request)
        path = STATIC / name if name in {p.name for p in STATIC.iterdir()} else None
        if name in VENDOR:
            path = NODE_MODULES / VENDOR[name]
        if path is None or not path.is_file():
            raise web.NotFound(f"lab: no asset {name} (run make lab-assets)\n")
        return web.Response.file(path)

    async def socket(request):
        check(request, websocket=True)
        ws = await request.websocket()   # 4 MB at most a message (web.py); protocol.py less
        lab.opened += 1
        lab.pages[ws] = f"page {lab.opened}"
        try:
            await ws.send_str(json.dumps(lab.hello(ws)))
            lab.sent = None               # the next frame brings it the servo's words
            async for msg in ws:
                if msg.type == web.TEXT:
                    lab.on_text(ws, msg.data)
                else:
                    lab.tell(ws, {"t": "error", "why": "binary messages are not the lab's"})
        except ConnectionError:           # the page left before its hello went out
            pass
        finally:
            lab.pages.pop(ws, None)
            lab.listings.forget(ws)
            lab.release(ws)

    async def handle(request):
        if request.method not in ("GET", "HEAD"):
            raise web.Refused(f"lab: {request.method} is not the lab's\n", 405)
        if request.path == "/":
            return await page(request)
        if request.path == "/ws":
            return await socket(request)
        folder, _, name = request.path.rpartition("/")
        if folder == "/assets" and name:
            return await asset(request, name)
        raise web.NotFound("lab: not found\n")

    return handle


def deaf_to_late_interrupts(loop):
    """The simulator has ended (its blocks flushed or reported): a ^C from here on has
    nothing left to stop. Without this, asyncio puts Python's own SIGINT handler back
    when the loop closes, and a ^C in that instant ended the process by the signal
    (status -2) instead of with the lab's answer."""
    loop.remove_signal_handler(signal.SIGINT)
    signal.signal(signal.SIGINT, signal.SIG_IGN)


async def serve(simulator, disk, symbols, port, speed, announce, read_only=False, lister=None,
                timed=False):
    """Run the lab until the user leaves; True if every UPDATEd block was written
    and the disk detached, None if the simulator exited by itself."""
    token = guard.new_token()
    lab = Lab(simulator, disk, symbols, speed, read_only, lister, timed)
    server = web.Server(make_app(lab, token, lambda: server.port))
    await server.start("127.0.0.1", port)
    lab.sim.start()
    loop = asyncio.get_running_loop()
    # the ways out before the URL: a starter that reads it and dies at once sends its
    # ^C (launch.py's parent-death signal) within a millisecond, which must find these
    loop.add_signal_handler(signal.SIGINT, lambda: asyncio.ensure_future(lab.sim.close()))
    loop.add_signal_handler(signal.SIGTERM, lambda: asyncio.ensure_future(lab.sim.close()))
    loop.add_signal_handler(signal.SIGHUP, lambda: (quiet_stdout(),
                                                    asyncio.ensure_future(lab.sim.close())))
    announce(f"http://127.0.0.1:{server.port}/?token={token}")
    shell = shell_terminal.attach(loop, lab.shell_keys)
    if shell:
        lab.shell_echo = shell[0]
    tasks = [asyncio.ensure_future(lab.frames()), asyncio.ensure_future(lab.probes())]
    try:
        await lab.done.wait()
        deaf_to_late_interrupts(loop)
        await lab.sent_all()                      # the last messages reach the pages
    finally:
        for task in tasks:
            task.cancel()
        for ws in list(lab.pages):                # else cleanup waits for the pages to go
            await ws.close()
        await server.stop()
        if shell:
            shell[1]()
    return lab.safe
