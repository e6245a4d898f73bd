"""The lab's console in the shell that started it, beside the page's terminal.

When `python -m harness lab` runs on a terminal, what the user types there goes to
the same simulator as the page's keys (the same LineWatcher, so BYE, ^D, ^C and
QUIT at sim> behave as in `make run`), and what the machine prints is shown there
too. The terminal is put in raw input mode, as `make run` does, so ^C reaches the
FORTH as a key; output processing stays on so the harness's own messages keep
their line ends. Without a terminal (tests, a log file) nothing changes: the page
alone types, and ^C (SIGINT) leaves.
"""
import os
import sys
import termios
import tty


def attach(loop, keys):
    """Join the shell's terminal to the lab; returns (echo, detach) or None when
    stdin and stdout are not both terminals. echo(bytes) shows machine output;
    detach() gives the terminal back as it was."""
    if not (sys.stdin.isatty() and sys.stdout.isatty()):
        return None
    fd_in, fd_out = sys.stdin.fileno(), sys.stdout.fileno()
    saved = termios.tcgetattr(fd_in)
    tty.setraw(fd_in, termios.TCSANOW)                # what was typed before is kept
    mode = termios.tcgetattr(fd_in)
    mode[1] |= termios.OPOST | termios.ONLCR          # oflag: "\n" still ends a line
    termios.tcsetattr(fd_in, termios.TCSANOW, mode)

    def readable():
        data = os.read(fd_in, 1024)
        if data:
            keys(data)
        else:
            loop.remove_reader(fd_in)

    def echo(data):
        try:
            os.write(fd_out, data)
        except OSError:
            pass                                      # a closed terminal: the page still shows it

    def detach():
        loop.remove_reader(fd_in)
        try:
            termios.tcsetattr(fd_in, termios.TCSADRAIN, saved)
        except termios.error:
            pass                                      # the terminal has gone away

    loop.add_reader(fd_in, readable)
    return echo, detach
