"""The four 11/03s' consoles while the 11/23's is in front (the launcher's part):
each 11/03's pty is served on a Unix socket, `x.sock` ... in the session's
directory (mode 0700, so only this user reaches it), and a client must first
send the session's token (the file `token`, mode 0600, new at every launch):
`python -m harness controllers console x` joins the user's terminal to it.

ConsoleBridge(directory, token) serves; add(name, child) adds an 11/03 (a
pexpect child); type(name, line) types a line as if the user had (the boot
lines); poll() runs the bridge for a moment (the launcher calls it from its
thread until close()); wait_for(predicate, timeout), from another thread, waits
until what the polls saw makes predicate() true (a console said something, or
closed), and wake() has a poll waiting in select look again at once. What a
machine printed is kept (the last REPLAY bytes, also appended to `name.log`)
and replayed to a client when it joins; one client per console at a time (a
second is told and refused). Keys are queued and written when the pty takes
them: nothing typed is dropped. A client leaves with ^] (the machine runs on);
^E there gives that 11/03's sim> (and, as long as it stays there, holds all
five machines at their next boundary).
"""
import os
import select
import socket
import threading
from pathlib import Path

REPLAY = 1 << 16
DETACH = b"\x1d"                           # ^], as telnet's escape


class _Console:
    def __init__(self, name, child, directory, token):
        self.name, self.child, self.token = name, child, token
        self.listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        path = Path(directory) / f"{name}.sock"
        path.unlink(missing_ok=True)
        self.listener.bind(str(path))
        self.listener.listen(2)
        self.client, self.client_ok = None, False
        self.pending = b""                 # keys not yet taken by the pty
        self.shown = b""                   # the last REPLAY bytes printed
        self.log = open(Path(directory) / f"{name}.log", "ab")
        self.alive = True
        self.watchers = []                 # [pattern, output since, callback]: boot lines
        os.set_blocking(child.child_fd, False)

    def output(self, data):
        self.shown = (self.shown + data)[-REPLAY:]
        self.log.write(data)
        self.log.flush()
        if self.client and self.client_ok:
            try:
                self.client.sendall(data)
            except OSError:
                self.drop_client()
        for w in list(self.watchers):
            w[1] += data
            if w[0] in w[1]:
                self.watchers.remove(w)
                w[2]()

    def drop_client(self):
        if self.client:
            self.client.close()
        self.client, self.client_ok = None, False

    def accept(self):
        conn, _ = self.listener.accept()
        if self.client:
            conn.sendall(f"the console of {self.name} is in use by another client\r\n".encode())
            conn.close()
            return
        self.client, self.client_ok = conn, False

    def from_client(self):
        try:
            data = self.client.recv(4096)
        except OSError:
            data = b""
        if not data:
            self.drop_client()
            return
        if not self.client_ok:             # the first line is the token
            line, _, rest = data.partition(b"\n")
            if line.decode("latin-1").strip() != self.token:
                self.client.sendall(b"wrong session token\r\n")
                self.drop_client()
                return
            self.client_ok = True
            self.client.sendall(self.shown)
            data = rest
        self.pending += data

    def write_pending(self):
        try:
            n = os.write(self.child.child_fd, self.pending[:1024])
        except BlockingIOError:
            return
        except OSError:
            self.pending = b""
            return
        self.pending = self.pending[n:]


class ConsoleBridge:
    def __init__(self, directory, token):
        self.directory, self.token = Path(directory), token
        self.consoles = {}
        self.changed = threading.Condition()        # notified after a poll that read
        self._wake_r, self._wake_w = os.pipe()
        os.set_blocking(self._wake_r, False)
        os.set_blocking(self._wake_w, False)

    def add(self, name, child):
        self.consoles[name] = _Console(name, child, self.directory, self.token)

    def type(self, name, line):
        self.consoles[name].pending += line.encode() + b"\r"
        self.wake()

    def wake(self):
        try:
            os.write(self._wake_w, b".")
        except BlockingIOError:              # wakes enough are waiting already
            pass

    def wait_for(self, predicate, timeout):
        """predicate()'s last value, once it holds or `timeout` seconds have passed."""
        with self.changed:
            return self.changed.wait_for(predicate, timeout)

    def when_printed(self, name, pattern, callback):
        """Call `callback` once the console of `name` prints `pattern` (bytes) from now on."""
        self.consoles[name].watchers.append([pattern, b"", callback])

    def poll(self, timeout=0.05):
        reads, writes, who = [self._wake_r], [], {self._wake_r: (None, "wake")}
        for c in self.consoles.values():
            if c.alive:
                reads.append(c.child.child_fd); who[c.child.child_fd] = (c, "out")
                if c.pending:
                    writes.append(c.child.child_fd)
            reads.append(c.listener); who[c.listener] = (c, "accept")
            if c.client:
                reads.append(c.client); who[c.client] = (c, "client")
        ready, writable, _ = select.select(reads, writes, [], timeout)
        for r in ready:
            c, what = who[r]
            if what == "wake":
                os.read(self._wake_r, 4096)
            elif what == "out":
                try:
                    data = os.read(c.child.child_fd, 1 << 16)
                except BlockingIOError:
                    continue
                except OSError:
                    data = b""
                if data:
                    c.output(data)
                else:
                    c.alive = False
            elif what == "accept":
                c.accept()
            elif c.client:
                c.from_client()
        for w in writable:
            who[w][0].write_pending()
        if ready:
            with self.changed:
                self.changed.notify_all()

    def close(self):
        for c in self.consoles.values():
            c.drop_client()
            c.listener.close()
            c.log.close()
            (self.directory / f"{c.name}.sock").unlink(missing_ok=True)
        os.close(self._wake_r)
        os.close(self._wake_w)


def join(directory, name, stdin_fd=0, stdout_fd=1):
    """The user's terminal joined to the console `name` served in `directory`,
    until ^] or the session's end; a message saying which, or raises OSError
    (no session)."""
    token = (Path(directory) / "token").read_text().strip()
    conn = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    conn.connect(str(Path(directory) / f"{name}.sock"))
    conn.sendall(token.encode() + b"\n")
    while True:
        ready, _, _ = select.select([stdin_fd, conn], [], [])
        if conn in ready:
            data = conn.recv(1 << 16)
            if not data:
                return f"the console of {name} closed (the session is over)"
            os.write(stdout_fd, data)
        if stdin_fd in ready:
            data = os.read(stdin_fd, 4096)
            if not data or DETACH in data:
                conn.sendall(data.split(DETACH)[0])
                conn.close()
                return f"left the console of {name} (^]); it runs on"
            conn.sendall(data)
