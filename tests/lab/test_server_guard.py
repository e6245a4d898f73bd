"""The running lab server refuses what it must (issues 11 and 23): other addresses,
websockets with a missing or wrong token or a foreign origin, foreign Host names;
and no cookie carries the token (browsers send cookies to every port of a host)."""
import asyncio
import http.client
import json
import socket

import aiohttp
import pytest


def get(server, path, host=None, cookie=None):
    conn = http.client.HTTPConnection("127.0.0.1", server.port, timeout=10)
    headers = {"Host": host or f"127.0.0.1:{server.port}"}
    if cookie:
        headers["Cookie"] = cookie
    conn.request("GET", path, headers=headers)
    response = conn.getresponse()
    return response.status, response.read().decode(), response.getheader("Set-Cookie")


def test_listens_on_127_0_0_1_only(lab_server):
    """A server on all interfaces would answer on every address of the machine,
    127.0.0.2 (another loopback address) included; this one refuses it."""
    socket.create_connection(("127.0.0.1", lab_server.port), timeout=5).close()
    with pytest.raises(ConnectionRefusedError):
        socket.create_connection(("127.0.0.2", lab_server.port), timeout=5)
    if socket.has_ipv6:
        with pytest.raises(OSError):                  # refused, or no IPv6 here at all
            socket.create_connection(("::1", lab_server.port), timeout=5)


def test_the_page_holds_no_secret_and_sets_no_cookie(lab_server):
    """The page and its assets are served without the token and set no cookie;
    the token is in none of them."""
    for path in ("/", f"/?token={lab_server.token}", "/assets/lab.js", "/assets/xterm.js"):
        status, body, cookie = get(lab_server, path)
        assert status == 200 and cookie is None, path
        assert lab_server.token not in body, path
    assert "<title>Lab bench" in get(lab_server, "/")[1]


def test_foreign_host_names_are_refused(lab_server):
    status, body, _ = get(lab_server, f"/?token={lab_server.token}",
                          host=f"attacker.example:{lab_server.port}")
    assert status == 403 and "Host" in body


def websocket(server, origin, token):
    async def connect():
        async with aiohttp.ClientSession() as session:
            async with session.ws_connect(
                    f"http://127.0.0.1:{server.port}/ws?token={token}",
                    headers={"Origin": origin} if origin else {}) as ws:
                return json.loads((await ws.receive(timeout=10)).data)["t"]
    return asyncio.run(connect())


def test_websocket_needs_token_and_own_origin(lab_server):
    own = f"http://127.0.0.1:{lab_server.port}"
    assert websocket(lab_server, own, lab_server.token) == "hello"
    for origin, token in ((own, "wrong"), ("http://attacker.example", lab_server.token),
                          (None, lab_server.token)):
        with pytest.raises(aiohttp.WSServerHandshakeError) as refused:
            websocket(lab_server, origin, token)
        assert refused.value.status == 403
