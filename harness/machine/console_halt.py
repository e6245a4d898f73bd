"""The console's word when the PDP-11 stops by itself (issue 8).

A trap reaches the FORTH's own handler and its prompt; what the hardware cannot
trap still stops the machine at SIMH's sim> prompt: a HALT instruction (a wild
jump after a raw store over the kernel's code, `1024 2000 0 FILL`), or SIMH's stop on a
trap whose push found no memory. SIMH prints one line and the prompt; the
console adds what happened and the ways on:

    watcher = HaltWatcher(kernel, entry)    # build/kernel.lda, ENTRY from its map
    out = watcher.feed(bytes_from_simh)     # the same bytes, a hint appended
"""
import re

# SIMH's stop line; ^E's own stop ("Simulation stopped") is the user's doing
STOP = re.compile(rb"\r?\n((?!Simulation stopped)[A-Z][^\r\n]*), PC: ([0-7]+)[^\r\n]*\r?\nsim> $")


class HaltWatcher:
    def __init__(self, kernel, entry):
        self.kernel, self.entry = kernel, entry
        self.tail = b""          # the last bytes seen: a stop line may come in pieces

    def hint(self, reason, pc):
        return (f"\r\n[console] The PDP-11 stopped by itself ({reason} at {pc}): the FORTH "
                "cannot go on from there (a raw store over the vectors or the kernel?).\r\n"
                f"[console] LOAD {self.kernel} then RUN {self.entry:o} restarts it cold "
                "(its dictionary is lost, the disk is kept; blocks UPDATEd but not FLUSHed "
                "are lost); BYE or ^D leaves.\r\nsim> ").encode()

    def feed(self, data):
        self.tail = (self.tail + data)[-300:]
        m = STOP.search(self.tail)
        if not m:
            return data
        self.tail = b""
        return data + self.hint(m.group(1).decode("latin-1"), m.group(2).decode())

