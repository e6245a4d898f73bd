"""The LAB device (pdp11-devices/lab/lab.c) in build/pdp11: its rows, its commands,
and that pacing, pausing and stepping leave the machine's run unchanged."""
import os
import re
import threading
import time

import pytest

from harness.lab.protocol import DEVICE_COMMANDS, DEVICE_ROWS, Refused, device_command, \
    device_help
from harness.machine import simh
from harness.machine.build import KERNEL, PDP11_TIMED, ROOT, fresh_disk
from harness.machine.plant_rows import COLUMNS

TYPED = "1000 LOAD\rSet.Up.Robot\r800 800 400 0 Abs.Move\r"
RUN_INSTRUCTIONS = 4_500_000          # 15 simulated seconds: the load, the set-up, the move


def rows(path, kind):
    text = path.read_text() if path.exists() else ""
    return [line.split(",")[1:] for line in text.splitlines() if line.startswith(kind + ",")]


@pytest.fixture
def ctl(tmp_path):
    """The command FIFO, held open read-write by the test (as the lab server does)."""
    fifo = tmp_path / "lab.ctl"
    os.mkfifo(fifo)
    fd = os.open(fifo, os.O_RDWR | os.O_NONBLOCK)
    yield lambda text: os.write(fd, text.encode())
    os.close(fd)


def test_rows_and_commands(tmp_path, ctl):
    out = tmp_path / "lab"
    ctl("watch 140000 140002\ndump 140000 2\nspeed abc\nwatch 140001\nfly\n")
    out_text = simh.run(f"load {KERNEL}\n" + simh.deposit(0o140000, [0o1234, 0o177777]) +
                        f"attach lab {out}\nset lab speed=10\nstep 21000\nshow lab\n"
                        "detach lab\n")
    assert "LAB, running, speed=10x, 2 words watched: 140000=001234 140002=177777" in out_text
    text = out.read_text()
    assert text.startswith("A\nS,0.000000,run,0,on,count,0\n")   # at the attach, before SET
    assert rows(out, "A") == [["140000", "140002"]]
    assert rows(out, "M") == [["140000", str(0o1234), "65535"]]
    assert [e[0] for e in rows(out, "E")] == [
        "speed takes a number from 0 (full speed) to 1000 (times the 11/23's pace)",
        "watch takes at most 64 even octal addresses below 160000",
        "commands: speed X", ]
    samples = rows(out, "W")
    assert [s[1] for s in samples] == ["1", "2", "3", "4"]         # every 5000 instructions
    assert samples[0][0] == "0.016667" and samples[-1][0] == "0.066667"
    assert samples[-1][2:] == [str(0o1234), "65535"]
    plant = rows(out, "P")                       # four samples a tick, every axis
    assert [p[1] for p in plant[:8]] == list("XYZTXYZT")
    assert [round(float(p[0]), 6) for p in plant[::4][:5]] == [0.004167, 0.008333, 0.0125,
                                                              0.016667, 0.020833]
    assert {len(p) for p in plant} == {len(COLUMNS)}  # the plant trace's row, gripper too
    x = plant[0][2:]                             # DAC at zero volts; x drifts on its offset
    assert x[:2] == ["2048", "-58.590"] and float(x[2]) < 0 and x[4] == "0"


def test_power_switches_the_amplifier_rack(tmp_path, ctl):
    """The page's rack switch: power off/on reaches SET PLANT POWER; a bad word
    is refused and changes nothing."""
    out = tmp_path / "lab"
    ctl("power off\npower maybe\n")
    shown = simh.run(f"load {KERNEL}\nattach lab {out}\nstep 6000\nshow plant\ndetach lab\n")
    assert "power=off" in shown
    states = rows(out, "S")
    assert states[0][3] == "on" and states[-1][3] == "off"
    assert [e[0] for e in rows(out, "E")] == ["power takes on or off"]


def test_set_lab_speed_refuses_bad_values_and_keeps_the_old_one(tmp_path):
    out = simh.run("set lab speed=10\nset lab speed=-1\nset lab speed=fast\nshow lab\n")
    assert out.count("LAB: speed takes a number") == 2
    assert "running, speed=10x" in out


def run_servo(tmp_path, name, lab=None, ctl_commands=None):
    disk = fresh_disk(tmp_path, f"{name}.dsk")
    trace = tmp_path / f"{name}.csv"
    script = (f"attach rl0 {disk}\nattach plant {trace}\n"
              + (f"attach lab {lab}\n" if lab else "")
              + f"load {KERNEL}\nstep {RUN_INSTRUCTIONS}\ndetach plant\n")
    if ctl_commands:
        threading.Thread(target=ctl_commands, daemon=True).start()
    out = simh.run(script, keyboard=TYPED, timeout=120)
    return trace.read_bytes(), out


def test_pacing_pausing_and_stepping_change_nothing_the_machine_does(tmp_path, ctl):
    plain, plain_out = run_servo(tmp_path, "plain")
    assert b",X," in plain and "800 800 400 0 Abs.Move  ok" in plain_out

    lab = tmp_path / "lab"

    def paused_at():
        return sorted({float(s[0]) for s in rows(lab, "S") if s[1] == "pause"})

    def user():                        # pause early, step three ticks, go on
        for n, command in enumerate(("step", "step", "step", "run"), start=1):
            deadline = time.monotonic() + 30
            while len(paused_at()) < n and time.monotonic() < deadline:
                time.sleep(0.02)       # each step once the last one has paused
            ctl(command + "\n")
    ctl("speed 100\npanel 7160\npause\n")       # the front panel's rows too
    watched, watched_out = run_servo(tmp_path, "watched", lab, user)
    assert rows(lab, "R")
    assert watched == plain
    assert watched_out.replace(str(tmp_path / "watched"), "") == plain_out.replace(
        str(tmp_path / "plain"), "")
    states, pauses = rows(lab, "S"), paused_at()
    assert [round((b - a) * 60, 3) for a, b in zip(pauses, pauses[1:])] == [1, 1, 1]
    assert states[-1][1] == "run" and float(states[-1][0]) == pauses[-1]


def test_ticks_keep_their_simulated_times_when_rate_changes(tmp_path):
    """SET CLK RATE (time_base.c): the LAB device's pending tick is rescaled too."""
    out = tmp_path / "lab"
    simh.run(f"load {KERNEL}\nattach lab {out}\nset lab speed=10\nstep 21000\n"
             "set clk rate=600000\nstep 40000\ndetach lab\n")
    times = [s[0] for s in rows(out, "W")]
    assert times == ["0.016667", "0.033333", "0.050000", "0.066667",
                     "0.083333", "0.100000", "0.116667", "0.133333"]


def test_the_clock_command_switches_to_the_11_23s_time_and_back(tmp_path, ctl):
    """`clock timed|count` (the page's clock button): SET CLK TIMED between two
    ticks, simulated time continuous; the S rows say which base, and whether this
    simulator can price instructions."""
    out = tmp_path / "lab"
    ctl("clock timed\nclock count\nclock timed\n")      # read at the first tick
    shown = simh.run(f"attach rl0 {fresh_disk(tmp_path)}\nload {KERNEL}\nattach lab {out}\n"
                     f"set lab speed=10\nstep {2 * 13_333_333}\nshow clk\ndetach lab\n",
                     simulator=PDP11_TIMED, keyboard="1000 LOAD\r")
    bases = [s[4:] for s in rows(out, "S")]          # after each command, and each change
    assert [b for i, b in enumerate(bases) if i == 0 or b != bases[i - 1]] == [
        ["count", "1"], ["timed", "1"], ["count", "1"], ["timed", "1"]]
    assert not rows(out, "E")
    assert "rate=13333333 units" in shown                  # the KDF11-A's 75 ns units
    # two seconds of 1000 LOAD in 11/23 time: each tick on its 1/60 s, late by at most
    # what is left of the instruction that crosses it (time_base.c's clock_series)
    times = [float(s[0]) for s in rows(out, "W")]
    assert len(times) >= 119
    late = [t - (k + 1) / 60 for k, t in enumerate(times)]
    assert -1e-6 < min(late) and max(late) < 0.0005, (min(late), max(late))   # 6 decimals


def test_the_clock_command_is_refused_where_the_cpu_does_not_price(tmp_path, ctl):
    """build/pdp11 keeps SIMH's CPU (mk/devices.mk): `clock timed` is refused with where
    to find the 11/23's clock, and the time base stays the count."""
    out = tmp_path / "lab"
    ctl("clock timed\nclock fast\nclock count\n")
    shown = simh.run(f"load {KERNEL}\nattach lab {out}\nstep 11000\nshow clk\ndetach lab\n")
    assert [e[0] for e in rows(out, "E")] == [
        "clock timed needs the CPU that prices instructions: build/pdp11-timed "
        "(python -m harness lab --timed)", "clock takes count or timed"]
    assert {tuple(s[4:]) for s in rows(out, "S")} == {("count", "0")}
    assert "rate=300000 instructions/s" in shown


def test_panel_rows_show_registers_psw_and_device_registers(tmp_path, ctl):
    """`panel ADDR...`: an R row each tick, all octal: R0-R7, the PSW, the word at
    R4 (IP), the KW11-L's LKS, the DRV11's CSR and OUTBUF, the four DACs, the words
    asked for."""
    out = tmp_path / "lab"
    ctl("panel 140000\npanel 140001\n")
    simh.run(f"load {KERNEL}\n" + simh.deposit(0o140000, [0o1234]) +
             f"attach lab {out}\nset lab speed=10\nstep 21000\nshow cpu\ndetach lab\n")
    panel = rows(out, "R")
    assert len(panel) == 4 and all(len(r) == 1 + 8 + 2 + 3 + 4 + 1 for r in panel)
    last = panel[-1]
    registers = [int(v, 8) for v in last[1:9]]
    assert all(0 <= r < 0o200000 for r in registers) and registers[7] % 2 == 0
    psw = int(last[9], 8)
    assert psw >> 14 == 0                            # kernel mode, as the FORTH runs
    lks = int(last[11], 8)
    assert lks & 0o200                               # the KW11-L has ticked (MON)
    assert last[14:18] == ["4000"] * 4               # every DAC at 2048: zero volts
    assert last[18] == "1234"                        # the word asked for
    assert [e[0] for e in rows(out, "E")] == [
        "panel takes at most 8 even octal addresses below 160000"]


# ---- the device's side of the lab protocol: one list, in lab.c and protocol.py --------
LAB_C = ROOT / "pdp11-devices" / "lab" / "lab.c"


def header_section(title, until):
    """The lines of lab.c's header comment from `title` up to `until`."""
    text = LAB_C.read_text().split("*/", 1)[0]
    return text.split(title, 1)[1].split(until, 1)[0].splitlines()


def test_the_device_refuses_an_unknown_command_with_the_protocols_list(tmp_path, ctl):
    out = tmp_path / "lab"
    ctl("fly\n")
    simh.run(f"load {KERNEL}\nattach lab {out}\nstep 11000\ndetach lab\n")
    assert [e[0] for e in rows(out, "E")] == [f"commands: {device_help()}".split(",")[0]]
    assert f"E,commands: {device_help()}\n" in out.read_text()


def test_lab_c_header_lists_the_protocols_commands_and_rows():
    commands = [line.split()[0] for line in header_section("Commands, one per line", "A bad")
                if line.startswith("     ") and line.split() and line[5] != " "]
    assert commands == list(DEVICE_COMMANDS)
    kinds = [line.split(",")[0].strip() for line in header_section("Rows, one per line", "Commands")
             if line.startswith("     ") and line[5] != " " and "," in line]
    assert kinds == list(DEVICE_ROWS)


def test_the_server_writes_only_the_devices_commands():
    for name, args in DEVICE_COMMANDS.items():
        assert device_command(f"{name} {args}".rstrip())
    with pytest.raises(Refused, match="no command 'fly'"):
        device_command("fly 3")


# ---- the front panel's interrupts, I/O breakpoint and one-instruction steps ----------
def test_interrupts_are_counted_per_vector_in_simulated_time(tmp_path, ctl):
    """interrupt_count.c: the KW11-L's vector 100 taken 60 times a simulated second once
    the servo runs, the console's receiver (60) once per typed character; the I rows
    (with the R rows) carry the same running counts."""
    out = tmp_path / "lab"
    ctl("panel\n")
    disk = fresh_disk(tmp_path, "i.dsk")
    # full speed to the last two simulated seconds; x10 (every tick reported) for
    # those: the device's last look at full speed may pass over up to 60 ticks
    text = simh.run(f"attach rl0 {disk}\nattach lab {out}\nload {KERNEL}\n"
                    f"step {RUN_INSTRUCTIONS - 600000}\nset lab speed=10\nstep 600000\n"
                    "show lab interrupts\nstep 300000\nshow lab interrupts\ndetach lab\n",
                    keyboard=TYPED, timeout=120)
    counts = [dict(pair.split("=") for pair in line.split(": ", 1)[1].split())
              for line in text.splitlines() if line.startswith("interrupts taken")]
    assert int(counts[1]["100"]) - int(counts[0]["100"]) == 60      # one simulated second
    assert counts[0]["60"] == str(len(TYPED))                       # a receiver interrupt a key
    ticks = [(float(i[0]), dict(f.split("=") for f in i[1:])) for i in rows(out, "I")]
    (then, before), (now, after) = ticks[-61], ticks[-1]
    assert round(now - then, 6) == 1.0 and int(after["100"]) - int(before["100"]) == 60
    assert int(counts[0]["100"]) <= int(after["100"]) <= int(counts[1]["100"])


def test_an_io_breakpoint_refuses_bad_addresses_and_keeps_the_one_set():
    out = simh.run("set lab iobreak=170440\nset lab iobreak=170441\nset lab iobreak=170460\n"
                   "set lab iobreak=12\nset lab iobreak=DAC\nshow lab iobreak\n"
                   "set lab iobreak=17777546\nshow lab iobreak\nset lab noiobreak\nshow lab iobreak\n")
    assert "IOBREAK: 170441 is not an even I/O page address (160000-177776)" in out
    assert "IOBREAK: no device answers at 170460" in out
    assert "IOBREAK: 12 is not an even I/O page address" in out
    assert "IOBREAK: give an octal I/O page address, as SET LAB IOBREAK=170440" in out
    shown = [line for line in out.splitlines() if "I/O break" in line]
    assert shown == ["I/O break at 170440 (AAV11-A DAC X), read or write",
                     "I/O break at 177546 (KW11-L LKS), read or write", "no I/O break"]


def test_an_io_breakpoint_stops_after_the_access_and_changes_nothing(tmp_path):
    """SET LAB IOBREAK=170440: the servo's first write to DAC X stops the machine with
    the register, the access, the value and the PC; going on, the run is the plain one
    (an EXAMINE of the register at sim> does not stop it)."""
    plain, plain_out = run_servo(tmp_path, "plain")
    disk = fresh_disk(tmp_path, "broken.dsk")
    trace = tmp_path / "broken.csv"
    out = simh.run(f"attach rl0 {disk}\nattach plant {trace}\nload {KERNEL}\n"
                   "set lab iobreak=170440\nset cpu history=64\n"
                   f"step {RUN_INSTRUCTIONS}\nshow cpu history=1\nexamine 170440\n"
                   "set lab noiobreak\nshow time\n", keyboard=TYPED, timeout=120)
    hit = re.search(r"I/O break: write ([0-7]{6}) to 170440 \(AAV11-A DAC X\) at PC ([0-7]{6})",
                    out)
    assert hit, out
    assert out.count("I/O break:") == 1 and "Simulation stopped" in out
    assert re.search(rf"\n{hit.group(2)} [0-7]{{6}}\|.*170440", out)   # the history's last
    executed = int(re.search(r"Time:\s*(\d+)", out).group(1))
    rest = simh.run(f"attach rl0 {fresh_disk(tmp_path, 'again.dsk')}\nattach plant {trace}\n"
                    f"load {KERNEL}\nset lab iobreak=170440\nstep {RUN_INSTRUCTIONS}\n"
                    f"set lab noiobreak\nstep {RUN_INSTRUCTIONS - executed}\ndetach plant\n",
                    keyboard=TYPED, timeout=120)
    assert "I/O break: write" in rest                  # (its line may cut the move's echo)
    assert trace.read_bytes() == plain                 # stopped, gone on: the same run
    assert "Abs.Move  ok" in rest and "800 800 400 0 Abs.Move  ok" in plain_out


def test_halting_and_stepping_instructions_while_paused_change_nothing(tmp_path, ctl):
    """The front panel's one-instruction step: paused, `halt` brings sim> at once; four
    STEPs there, SHOW LAB PANEL writing the registers after each, and a STEP across
    the next tick (it does not wait for the pause); then the run goes on, paused at
    the tick after, until `run`: the plant trace is the plain run's."""
    plain, _ = run_servo(tmp_path, "plain")
    lab = tmp_path / "lab"
    trace = tmp_path / "stepped.csv"

    def pauses():
        return {s[0] for s in rows(lab, "S") if s[1] == "pause"}

    def user():                            # halt once paused; run once paused again
        for n, command in ((1, "halt"), (2, "run")):
            deadline = time.monotonic() + 60
            while len(pauses()) < n and time.monotonic() < deadline:
                time.sleep(0.02)
            ctl(command + "\n")
    ctl("speed 100\npanel\npause\n")
    threading.Thread(target=user, daemon=True).start()
    out = simh.run(f"attach rl0 {fresh_disk(tmp_path, 'stepped.dsk')}\nattach plant {trace}\n"
                   f"attach lab {lab}\nload {KERNEL}\nstep {RUN_INSTRUCTIONS}\n"
                   + "step\nshow lab panel\n" * 4 + "step 6000\nshow lab panel\n"
                   f"step {RUN_INSTRUCTIONS}\ndetach plant\n", keyboard=TYPED, timeout=120)
    assert out.count("Simulation stopped") == 1 and out.count("Step expired") == 6, out
    panels = [line for line in out.splitlines() if line.startswith("PC=")]
    assert len(panels) == 5 and len(set(panels)) == 5          # the registers moved each step
    assert len(pauses()) == 2 and rows(lab, "S")[-1][1] == "run"
    stepped = trace.read_bytes()
    assert len(stepped) > len(plain) and stepped[:len(plain)] == plain
