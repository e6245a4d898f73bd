"""Which lines typed at SIMH's sim> prompt the lab page may run (pure logic).

The page's terminal is SIMH's console, and SIMH can run host shell commands (`!`),
read and write any file the server's user may (ATTACH, SAVE, DUMP, SET CONSOLE
LOG=, `SHOW @FILE`, `EXAMINE @FILE`, DEPOSIT into a disk unit) and open listening
sockets (ATTACH DZ, SET CONSOLE TELNET=). Whoever holds the page's URL would hold
the host. So a line from the page runs only when it is one of the commands below,
decided as SIMH 3.8.1 decides it (scp.c): the first word upper-cased and taken as
the first command-table entry it begins (harness.machine.simh_command), switches
(-X) skipped, SET's device named exactly and its modifiers matched the same way in
the device's own modifier table, in the table's order. The lab's own shell and
`make run` keep the full console.
"""
import re

from harness.machine.simh_command import simh_command

EXITS = ("EXIT", "QUIT", "BYE")   # SIMH FLUSHes the FORTH's blocks first (leave_check.c)
MAX_LINE = 200      # SIMH reads CBUFSIZE bytes a line: a longer one would split in two
MAY_RUN = ("SHOW", "EXAMINE", "DEPOSIT", "SET", "STEP", "CONT", "BREAK", "NOBREAK", "HELP")
MAY_RUN_TEXT = ("SHOW, EXAMINE, DEPOSIT, SET PLANT/CLK/LAB/CPU HISTORY, STEP, CONT, "
                "BREAK, NOBREAK, HELP, QUIT")
WHY_NOT = {
    "!": "runs a command in the host's shell",
    "ATTACH": "opens a host file or a listening socket",
    "DETACH": "would close the FORTH's disk or the lab's devices under them",
    "SAVE": "writes a host file", "DUMP": "writes a host file",
    "RESTORE": "reads a host file into the machine", "GET": "reads a host file into the machine",
    "LOAD": "reads a host file into the machine", "DO": "runs the commands of a host file",
    "RESET": "resets the machine under the FORTH", "RUN": "restarts the machine",
    "GO": "starts the machine elsewhere", "BOOT": "reboots the machine",
    "ASSIGN": "renames devices", "DEASSIGN": "renames devices",
    "IEXAMINE": "reads further input from the console",
    "IDEPOSIT": "reads further input from the console",
}
# SET's devices the page may set, with their modifier tables in SIMH's order
# (scp.c set_cmd matches the typed word as a prefix of each, first match wins), as
# `SHOW dev MODIFIERS` lists them (tests/lab/test_sim_commands.py compares).
CPU_MODIFIERS = (
    "11/03", "11/04", "11/05", "11/20", "11/23", "11/23+", "11/24", "11/34", "11/40",
    "11/44", "11/45", "11/53", "11/60", "11/70", "11/73", "11/73B", "11/83", "11/84",
    "11/93", "11/94", "Q22", "URH11", "URH70", "U18", "EIS", "NOEIS", "FIS", "NOFIS",
    "FPP", "NOFPP", "CIS", "NOCIS", "MMU", "NOMMU", "IDLE", "NOIDLE", "16K", "32K",
    "48K", "64K", "96K", "128K", "192K", "256K", "384K", "512K", "768K", "1024K",
    "2048K", "3072K", "4096K", "1M", "2M", "3M", "4M", "AUTOCONFIG", "NOAUTOCONFIG",
    "HISTORY")
SETTABLE = {   # device: (its modifiers in table order, those the page may set)
    "CPU": (CPU_MODIFIERS, {"HISTORY"}),
    "PLANT": (("X", "Y", "Z", "T", "KV", "TAU", "AMAX", "VMAX", "OFFSET", "PMIN", "PMAX",
               "WALK", "POS", "GRIPPER", "OBJECT", "PULLOUT", "OPENING", "PARTX", "PARTY",
               "PARTZ", "SEED", "SAMPLE", "POWER", "HINT"), None),     # None: all
    "CLK": (("RATE", "REALTIME", "NOREALTIME", "IDLESPEED", "TIMED", "NOTIMED"), None),
    "LAB": (("SPEED", "IOBREAK", "NOIOBREAK"), None),
}
# Devices whose units SIMH backs with host files (disks, tapes, paper tape, cards,
# printer) or sockets (DZ, VH, XQ, LOCKSTEP: the five machines' coordinator): a DEPOSIT into one writes that file. The others
# (CPU, the bus devices, the plant) hold registers only. tests/lab/test_sim_commands.py
# checks that every device of the lab's machine is in one list or the other.
FILE_DEVICES = ("PTR", "PTP", "CR", "LPT", "DZ", "VH", "RC", "RF", "RK", "RL", "HK",
                "RX", "RY", "RP", "RQ", "RQB", "RQC", "RQD", "TC", "TM", "TS", "TQ",
                "TU", "TA", "XQ", "XQB", "XU", "XUB", "DLI", "DLO", "DCI", "DCO", "LOCKSTEP")
REGISTER_DEVICES = ("CPU", "SYSTEM", "RHA", "RHB", "PCLK", "CLK", "TTI", "TTO", "KE", "KG", "DRV11",
                    "AAV11", "PLANT", "LAB", "CUE", "LINK0", "LINK1", "LINK2", "LINK3")


def words(text):
    """SIMH's glyphs: separated by blanks (get_glyph) and, in modifier lists, commas."""
    return [w for w in re.split(r"[\s,]+", text) if w]


def names_device(word, devices):
    """Whether `word` names one of `devices` or one of their units (find_unit: RL0)."""
    word = word.upper()
    return any(word == d or (word.startswith(d) and word[len(d):].isdigit()) for d in devices)


def refusal(line):
    """None when the page may run `line` at sim>, else why not (one line)."""
    if len(line) > MAX_LINE:
        return f"the line is longer than {MAX_LINE} characters"
    if any(not 32 <= ord(c) < 127 for c in line):
        return "only plain ASCII is typed to SIMH from the page"
    text = line.strip()
    if not text or text.startswith(";"):
        return None                               # SIMH ignores it
    command = simh_command(text)
    rest = text.split(None, 1)[1] if " " in text else ""
    if command is None:
        return f"{text.split()[0]} is not a SIMH command"
    if command in EXITS:
        return None                               # the lab's way out (FLUSH first)
    if command not in MAY_RUN:
        return f"{command} {WHY_NOT.get(command, 'is not one of the commands the page may run')}"
    if "@" in rest and command in ("SHOW", "EXAMINE"):
        return f"{command} @FILE writes its output to a host file"
    if ";" in rest and command in ("BREAK", "NOBREAK"):
        return f"{command} with ;ACTIONS would run SIMH commands unchecked"
    if command == "DEPOSIT" and any(names_device(w, FILE_DEVICES) for w in words(rest)):
        return "DEPOSIT into a disk, tape or line unit writes its host file"
    if command == "SET":
        return _set_refusal(rest)
    return None


def _set_refusal(rest):
    args = [w for w in rest.split() if not w.startswith("-")]      # switches first
    device = args[0].upper() if args else ""
    if device not in SETTABLE:
        return (f"SET {device or '(nothing)'}: the page may SET only "
                f"{', '.join(SETTABLE)} (SET CONSOLE, LOG, DEBUG, TELNET and the "
                "line and disk devices open host files or sockets)")
    table, allowed = SETTABLE[device]
    for modifier in words(" ".join(args[1:])):
        name = modifier.split("=", 1)[0].upper()
        match = next((m for m in table if m.startswith(name)), None)
        if match is None or (allowed is not None and match not in allowed):
            return (f"SET {device} {modifier}: the page may set only "
                    f"{', '.join(sorted(allowed or table))} on {device}")
    return None
