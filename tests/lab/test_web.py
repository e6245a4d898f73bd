"""The lab's HTTP and websocket server (harness/lab/web.py), in this process on a free
port with a handler of the test's: answers and refusals, keep-alive, and a websocket
that echoes, refuses a message too large and closes as the page expects."""
import asyncio

import aiohttp

from harness.lab import web


async def echo(request):
    if request.path == "/ws":
        ws = await request.websocket()
        async for msg in ws:
            await ws.send_str(f"{msg.type}:{len(msg.data)}:{msg.data[:5]}")
        return None
    if request.path == "/forbidden":
        raise web.Forbidden("no\n")
    if request.path != "/":
        raise web.NotFound("none\n")
    return web.Response(f"hello {request.query.get('q')}", headers=[("X-Test", "1")])


def with_server(test):
    async def run():
        server = web.Server(echo)
        await server.start("127.0.0.1", 0)
        try:
            return await test(server.port)
        finally:
            await server.stop()
    return asyncio.run(run())


async def raw(port, data):
    reader, writer = await asyncio.open_connection("127.0.0.1", port)
    writer.write(data)
    answer = await reader.read()
    writer.close()
    return answer


def test_answers_refusals_and_keep_alive():
    async def test(port):
        host = f"Host: 127.0.0.1:{port}\r\n".encode()
        two = await raw(port, b"GET /?q=1 HTTP/1.1\r\n" + host + b"\r\n"
                        b"GET /nothing HTTP/1.1\r\n" + host + b"Connection: close\r\n\r\n")
        assert two.startswith(b"HTTP/1.1 200 OK\r\n") and b"x-test: 1" in two.lower()
        assert b"hello 1" in two and b"HTTP/1.1 404 Not Found" in two and two.endswith(b"none\n")
        close = b"Connection: close\r\n\r\n"
        refused = await raw(port, b"GET /forbidden HTTP/1.1\r\n" + host + close)
        assert refused.startswith(b"HTTP/1.1 403 ") and refused.endswith(b"no\n")
        assert (await raw(port, b"NONSENSE\r\n\r\n")).startswith(b"HTTP/1.1 400 ")
        not_ws = await raw(port, b"GET /ws HTTP/1.1\r\n" + host + close)
        assert not_ws.startswith(b"HTTP/1.1 400 ")
    with_server(test)


def test_websocket_echoes_refuses_too_large_and_closes():
    async def test(port):
        async with aiohttp.ClientSession() as session:
            async with session.ws_connect(f"http://127.0.0.1:{port}/ws") as ws:
                await ws.send_str("héllo" * 10000)          # many frames' worth, one message
                assert (await ws.receive(timeout=10)).data == "text:50000:héllo"
                await ws.send_bytes(b"\x00\x01")
                assert (await ws.receive(timeout=10)).data == "binary:2:b'\\x00\\x01'"
                await ws.send_str("y" * (web.MAX_MESSAGE + 1))
                closed = await ws.receive(timeout=10)
                assert closed.type == aiohttp.WSMsgType.CLOSE and closed.data == 1009
            async with session.ws_connect(f"http://127.0.0.1:{port}/ws") as ws:
                await ws.close()
                assert ws.close_code == 1000
    with_server(test)
