"""Which SIMH 3.8.1 command a line typed at its sim> prompt runs.

SIMH (scp.c, find_cmd) upper-cases the first word and takes the first entry of its
command table that the word begins: "Q" is QUIT, "E" is EXAMINE, "EXI" is EXIT.
The console (harness/machine/console_watch.py) needs to know, before SIMH reads the line,
whether it lets the machine run again (then ^C is the FORTH's). Pure logic.
"""
# scp.c's cmd_table, in its order (the order decides abbreviations)
COMMANDS = ("RESET", "EXAMINE", "IEXAMINE", "DEPOSIT", "IDEPOSIT", "EVALUATE", "RUN", "GO",
            "STEP", "CONT", "BOOT", "BREAK", "NOBREAK", "ATTACH", "DETACH", "ASSIGN",
            "DEASSIGN", "SAVE", "RESTORE", "GET", "LOAD", "DUMP", "EXIT", "QUIT", "BYE",
            "SET", "SHOW", "DO", "ECHO", "ASSERT", "HELP", "!")
RUNS = frozenset({"RUN", "GO", "STEP", "CONT", "BOOT"})   # the machine runs again


def simh_command(line):
    """The full name of the command SIMH runs for `line`, or None (blank line,
    ';' comment, unknown command)."""
    words = line.split(None, 1)
    if not words or words[0].startswith(";"):
        return None
    word = words[0].upper()
    return next((name for name in COMMANDS if name.startswith(word)), None)
