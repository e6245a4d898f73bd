"""Who may use the lab server (pure logic): the page drives SIMH, which can write
files, so only a page on this machine that was given the session's URL may.

- The server listens on 127.0.0.1 only (server.py).
- The websocket (everything that acts on the machine) needs the random
  per-session token in its URL (?token=). The page takes it once from the URL
  that `make lab` printed, keeps it in the tab's sessionStorage (per origin, the
  port included, so a second lab's tab keeps its own) and removes it from the
  address bar. No cookie carries it: browsers send cookies to every port of a
  host, so any local server the browser visits would receive it.
- The page and its assets hold no secret and are served without the token.
- The Host header must name the server (127.0.0.1:PORT or localhost:PORT): a
  page from elsewhere cannot reach it by making a name resolve to 127.0.0.1.
- The websocket's Origin must be the server itself: another site's page in the
  same browser cannot open it.
"""
import hmac
import secrets


def new_token():
    return secrets.token_urlsafe(24)


def same_token(given, token):
    return bool(given) and hmac.compare_digest(given.encode(), token.encode())


def hosts(port):
    return {f"127.0.0.1:{port}", f"localhost:{port}"}


def refusal(host, query_token, token, port, origin=None, websocket=False):
    """None when the request may go on, else the reason it may not."""
    if host not in hosts(port):
        return f"this server answers only as 127.0.0.1:{port} (Host was {host!r})"
    if not websocket:
        return None
    if not same_token(query_token, token):
        return "missing or wrong token: open the URL that `make lab` printed"
    if origin not in {f"http://{h}" for h in hosts(port)}:
        return f"websocket from a foreign origin refused ({origin!r})"
    return None
