"""Who may use the lab server (pure logic): the page drives SIMH, which can write
files, so only a browser on this machine that was given the session's URL may.

- The server listens on 127.0.0.1 only (server.py).
- Every request carries the random per-session token, in the URL (?token=) or,
  after the page was opened with it, in a cookie the server set (as Jupyter does).
- The Host header must name the server (127.0.0.1:PORT or localhost:PORT): a
  page from elsewhere cannot reach it by making a name resolve to 127.0.0.1.
- The websocket's Origin must be the server itself: another site's page in the
  same browser cannot open it, even with the cookie.
"""
import hmac
import secrets

COOKIE = "lab-token"


def new_token():
    return secrets.token_urlsafe(24)


def same_token(given, token):
    return bool(given) and hmac.compare_digest(given.encode(), token.encode())


def hosts(port):
    return {f"127.0.0.1:{port}", f"localhost:{port}"}


def refusal(host, query_token, cookie_token, token, port, origin=None, websocket=False):
    """None when the request may go on, else the reason it may not."""
    if host not in hosts(port):
        return f"this server answers only as 127.0.0.1:{port} (Host was {host!r})"
    if not (same_token(query_token, token) or same_token(cookie_token, token)):
        return "missing or wrong token: open the URL that `make lab` printed"
    if websocket and origin not in {f"http://{h}" for h in hosts(port)}:
        return f"websocket from a foreign origin refused ({origin!r})"
    return None
