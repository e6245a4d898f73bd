"""The lab's page for the five machines of issue 21 (`make run CONTROLLERS=4 LAB=1`,
python -m harness controllers launch --lab): each machine's state and the tail
of its console, the amplifier rack's power (on or off: SET PLANT POWER at any
machine's sim>), and the servo table per axis (controllers_view.py), refreshed
twice a second from the lock-step's status file and the 11/03s' console logs.

It only reads: nothing here acts on the machines. The server listens on
127.0.0.1 only; the status needs the session's token (?token=, as the lab's
guard.py checks the Host header and the token); the page and its script hold
no secret. serve(status, directory) -> (url, stop): `status` the coordinator's
status file, `directory` where the consoles' logs (x.log ...) are."""
import json
import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from urllib.parse import parse_qs, urlparse

from harness.lab import guard
from harness.lab.controllers_view import MEMBERS, view

STATIC = Path(__file__).resolve().parent / "static"
FILES = {"/": ("controllers.html", "text/html"),
         "/controllers.js": ("controllers.js", "text/javascript")}


def read_view(status_path, directory):
    directory = Path(directory)
    try:
        status = json.loads(Path(status_path).read_text())
    except (OSError, ValueError):
        status = None
    logs = {}
    for m in MEMBERS:
        try:
            logs[m] = (directory / f"{m}.log").read_bytes()[-8192:].decode("latin-1")
        except OSError:
            pass
    return view(status, logs)


def serve(status_path, directory, port=0):
    token = guard.new_token()

    class Handler(BaseHTTPRequestHandler):
        def log_message(self, *args):
            pass

        def do_GET(self):
            url = urlparse(self.path)
            why = guard.refusal(self.headers.get("Host"), None, token, server.server_port)
            if why:
                return self.answer(403, why.encode(), "text/plain")
            if url.path == "/status":
                if not guard.same_token(parse_qs(url.query).get("token", [""])[0], token):
                    return self.answer(403, b"missing or wrong token", "text/plain")
                return self.answer(200, json.dumps(read_view(status_path, directory)).encode(),
                                   "application/json")
            if url.path in FILES:
                name, kind = FILES[url.path]
                return self.answer(200, (STATIC / name).read_bytes(), kind)
            self.answer(404, b"not found", "text/plain")

        def answer(self, code, body, kind):
            self.send_response(code)
            self.send_header("Content-Type", kind + "; charset=utf-8")
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)

    server = ThreadingHTTPServer(("127.0.0.1", port), Handler)
    # shutdown() waits for serve_forever's next look at its flag: 50 ms, not the default
    # 0.5 s, at every leave of a --lab session
    threading.Thread(target=server.serve_forever, kwargs={"poll_interval": 0.05},
                     name="controllers-page", daemon=True).start()

    def stop():
        server.shutdown()
        server.server_close()

    return f"http://127.0.0.1:{server.server_port}/?token={token}", stop
