"""The lab's HTTP server on asyncio's streams: h11 reads the requests (keep-alive
as browsers use it), wsproto speaks the websocket; both are pure Python, small,
and pinned in requirements.txt. The lab imported aiohttp for this: its client,
imported with it whether used or not, builds two SSL contexts from the system's
CA certificates, and the whole import was 0.25-0.3 CPU seconds of every lab's
start, about half of what a lab server costs from its start to its exit.

    Server(handle)              handle(request) -> a Response, or raises a Refused;
                                start(host, port), port, stop()
    request.websocket()         the handshake: a WebSocket (send_str, close, async for)
"""
import asyncio
import sys
import traceback
from collections import namedtuple
from http import HTTPStatus
from pathlib import Path
from urllib.parse import parse_qs, unquote, urlsplit

import h11
from wsproto import ConnectionType, WSConnection
from wsproto.connection import ConnectionState
from wsproto.events import (AcceptConnection, BytesMessage, CloseConnection, Ping, Pong,
                            Request as WsRequest, TextMessage)
from wsproto.utilities import RemoteProtocolError

READ_CHUNK = 1 << 16
MAX_MESSAGE = 4 << 20          # a websocket message, as aiohttp's default: larger ones close it
HEARTBEAT_S = 20               # a ping this often; no pong within half of it closes the socket
CLOSE_WAIT_S = 2.0             # close(): at most this for the page's own close
TYPES = {".html": "text/html", ".js": "text/javascript", ".css": "text/css"}
TEXT, BINARY = "text", "binary"
Message = namedtuple("Message", "type data")


class Refused(Exception):
    """An HTTP error answer: its text and status."""
    status = 400

    def __init__(self, text, status=None):
        super().__init__(text)
        self.text, self.status = text, status or self.status


class Forbidden(Refused):
    status = 403


class NotFound(Refused):
    status = 404


class Response:
    def __init__(self, body, content_type="text/plain", status=200, headers=()):
        self.body = body.encode() if isinstance(body, str) else body
        self.status = status
        self.headers = [("Content-Type", f"{content_type}; charset=utf-8"), *headers]

    @classmethod
    def file(cls, path, headers=()):
        path = Path(path)
        return cls(path.read_bytes(), TYPES.get(path.suffix, "application/octet-stream"),
                   headers=headers)


class Request:
    """What a handler reads of a request: path, query, headers (lower-case names)."""

    def __init__(self, event, connection):
        target = urlsplit(event.target.decode("latin-1"))
        self.path = unquote(target.path)
        self.query = {k: v[0] for k, v in parse_qs(target.query).items()}
        self.method = event.method.decode("latin-1")
        self.headers = {name.decode("latin-1"): value.decode("latin-1")
                        for name, value in event.headers}
        self.host = self.headers.get("host")
        self._event, self._connection = event, connection
        self.upgraded = None

    async def websocket(self):
        """Accept the websocket the request asks for; its WebSocket."""
        self.upgraded = await self._connection.upgrade(self._event)
        return self.upgraded


class WebSocket:
    """One page's websocket: send_str(text), close(), and `async for` over its
    Messages (TEXT or BINARY); the iteration ends when the page closes it."""

    def __init__(self, ws, reader, writer, data):
        self.ws, self.reader, self.writer = ws, reader, writer
        self.closed = False
        self._pending = data                    # bytes read past the handshake
        self._ended = asyncio.Event()
        self._pong = None
        self._beat = asyncio.get_running_loop().call_later(HEARTBEAT_S, self._ping)

    async def send_str(self, text):
        if self.closed or self.writer.is_closing() or self.ws.state is not ConnectionState.OPEN:
            raise ConnectionResetError("the page's websocket is closing")
        self.writer.write(self.ws.send(TextMessage(data=text)))
        await self.writer.drain()

    async def close(self, code=1000):
        """Close it, and wait (at most CLOSE_WAIT_S) for the page's answer."""
        self._send_close(code)
        try:
            await asyncio.wait_for(self._ended.wait(), CLOSE_WAIT_S)
        except asyncio.TimeoutError:
            pass
        self._end()

    def _send_close(self, code):
        self.closed = True
        if self.ws.state in (ConnectionState.OPEN, ConnectionState.REMOTE_CLOSING):
            self.writer.write(self.ws.send(CloseConnection(code=code)))

    def _ping(self):
        if self.ws.state is ConnectionState.OPEN:
            self.writer.write(self.ws.send(Ping()))
            loop = asyncio.get_running_loop()
            self._pong = loop.call_later(HEARTBEAT_S / 2, self._end)   # a page gone silent

    def _end(self):
        self.closed = True
        self._beat.cancel()
        if self._pong:
            self._pong.cancel()
        self.writer.close()
        self._ended.set()

    async def __aiter__(self):
        parts, size = [], 0
        try:
            while not self._ended.is_set():
                data, self._pending = self._pending or await self.reader.read(READ_CHUNK), b""
                self.ws.receive_data(data or None)
                for event in self.ws.events():
                    if isinstance(event, (TextMessage, BytesMessage)):
                        parts.append(event.data)
                        size += len(event.data)
                        if size > MAX_MESSAGE:
                            self._send_close(1009)      # too big, as aiohttp says it
                            return
                        if event.message_finished:
                            kind = TEXT if isinstance(event, TextMessage) else BINARY
                            yield Message(kind, parts[0][:0].join(parts))
                            parts, size = [], 0
                    elif isinstance(event, Ping):
                        self.writer.write(self.ws.send(event.response()))
                    elif isinstance(event, Pong):
                        if self._pong:
                            self._pong.cancel()
                        self._beat.cancel()
                        self._beat = asyncio.get_running_loop().call_later(HEARTBEAT_S,
                                                                           self._ping)
                    elif isinstance(event, CloseConnection):
                        self._send_close(event.code if self.ws.state is not
                                         ConnectionState.CLOSED else 1000)
                        return
        except ConnectionError:
            pass
        finally:
            self._end()


class _Connection:
    """One client's connection: requests in turn (keep-alive), or one websocket."""

    def __init__(self, handle, reader, writer):
        self.handle, self.reader, self.writer = handle, reader, writer
        self.http = h11.Connection(h11.SERVER)

    async def _next(self):
        while True:
            event = self.http.next_event()
            if event is not h11.NEED_DATA:
                return event
            self.http.receive_data(await self.reader.read(READ_CHUNK))

    async def run(self):
        try:
            while True:
                event = await self._next()
                if not isinstance(event, h11.Request):
                    return                           # closed
                if not await self._body_read():
                    return
                request = Request(event, self)
                await self._answer(request)
                if request.upgraded or self.http.our_state is not h11.DONE:
                    return
                self.http.start_next_cycle()
        except h11.RemoteProtocolError as err:
            if self.http.our_state in (h11.IDLE, h11.SEND_RESPONSE):
                self._send(Response(f"lab: {err}\n", status=400))
        except ConnectionError:
            pass
        finally:
            self.writer.close()

    async def _body_read(self):
        """Past the request's body (no page sends one); False if the client left."""
        while True:
            event = await self._next()
            if isinstance(event, h11.EndOfMessage):
                return True
            if isinstance(event, h11.ConnectionClosed):
                return False

    async def _answer(self, request):
        try:
            response = await self.handle(request)
        except Refused as refused:
            response = Response(refused.text, status=refused.status)
        except Exception:                            # a bug: said, and this request ends
            traceback.print_exc(file=sys.stderr)
            response = Response("lab: internal error\n", status=500)
        if request.upgraded is None:
            self._send(response, head=request.method == "HEAD")
            await self.writer.drain()

    def _send(self, response, head=False):
        headers = response.headers + [("Content-Length", str(len(response.body)))]
        data = self.http.send(h11.Response(status_code=response.status, headers=headers,
                                           reason=HTTPStatus(response.status).phrase))
        if not head:
            data += self.http.send(h11.Data(data=response.body))
        self.writer.write(data + self.http.send(h11.EndOfMessage()))

    async def upgrade(self, event):
        ws = WSConnection(ConnectionType.SERVER)
        try:
            ws.initiate_upgrade_connection(event.headers, event.target)
        except RemoteProtocolError as err:
            raise Refused(f"lab: not a websocket request: {err}\n") from err
        if not any(isinstance(e, WsRequest) for e in ws.events()):
            raise Refused("lab: not a websocket request\n")
        self.writer.write(ws.send(AcceptConnection()))
        return WebSocket(ws, self.reader, self.writer, self.http.trailing_data[0])


class Server:
    """The server: every connection's requests go to handle(request)."""

    def __init__(self, handle):
        self.handle, self.server = handle, None
        self.connections = set()                 # their writers

    async def start(self, host, port):
        self.server = await asyncio.start_server(self._connected, host, port)

    @property
    def port(self):
        return self.server.sockets[0].getsockname()[1]

    async def _connected(self, reader, writer):
        self.connections.add(writer)
        try:
            await _Connection(self.handle, reader, writer).run()
        finally:
            self.connections.discard(writer)

    async def stop(self):
        """Listen no more and close the connections left (a page's idle keep-alive)."""
        self.server.close()
        for writer in list(self.connections):
            writer.close()
        await self.server.wait_closed()
