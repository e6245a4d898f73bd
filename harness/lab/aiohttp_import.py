"""aiohttp's server side, imported without reading the system's CA certificates.

Importing aiohttp imports its client too, which makes two SSL contexts at once
(aiohttp/connector.py), each loading every certificate of the system's bundle:
about 80 ms of CPU, a quarter of the lab server's start, which 19 lab servers in
a `make test` pay for nothing. The lab serves plain HTTP on 127.0.0.1 and makes
no request of its own, so it imports aiohttp with OpenSSL's SSL_CERT_FILE (the
bundle those contexts load, OpenSSL's documented variable) naming an empty file,
and puts the variable back as it was: every context made later, in this process
or its children, finds the certificates as usual. Only aiohttp's two defaults
stay without them: an HTTPS request through aiohttp's client with its default
`ssl` would fail to verify its server (refuse, not trust). Where aiohttp was
imported already (a test process), nothing changes.
"""
import os

_SAVED = os.environ.get("SSL_CERT_FILE")
os.environ["SSL_CERT_FILE"] = os.devnull
try:
    from aiohttp import WSMsgType, web
finally:
    if _SAVED is None:
        del os.environ["SSL_CERT_FILE"]
    else:
        os.environ["SSL_CERT_FILE"] = _SAVED

__all__ = ["WSMsgType", "web"]
