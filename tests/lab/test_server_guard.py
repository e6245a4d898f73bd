"""The running lab server refuses what it must (issue 11): other addresses, missing
or wrong tokens, foreign Host names and foreign websocket origins."""
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


def test_the_page_needs_its_token(lab_server):
    status, body, _ = get(lab_server, "/")
    assert status == 403 and "token" in body
    status, body, _ = get(lab_server, "/?token=wrong")
    assert status == 403
    status, _, _ = get(lab_server, "/assets/lab.js")
    assert status == 403
    status, body, cookie = get(lab_server, f"/?token={lab_server.token}")
    assert status == 200 and "<title>Lab bench" in body and "HttpOnly" in cookie
    status, body, _ = get(lab_server, "/assets/xterm.js", cookie=cookie.split(";")[0])
    assert status == 200 and "Terminal" in body


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
