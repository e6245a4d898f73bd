"""A page's websocket as the lab's tests and make fuzz drive it (aiohttp): messages checked
against harness/lab/protocol.py's TO_PAGE as they come, the console text kept."""
import asyncio
import json
import time

import aiohttp

from harness.lab import protocol


class Page:
    def __init__(self, session, ws):
        self.session, self.ws = session, ws
        self.screen, self.messages = "", []
        self.count = {}                                      # messages received, per kind
        self.inbox = asyncio.Queue()
        self.reader = asyncio.ensure_future(self._read())   # answers the server's pings

    async def _read(self):
        while True:
            msg = await self.ws.receive()
            await self.inbox.put(msg)
            if msg.type != aiohttp.WSMsgType.TEXT:
                return

    @classmethod
    async def open(cls, server):
        session = aiohttp.ClientSession()
        ws = await session.ws_connect(f"http://127.0.0.1:{server.port}/ws?token={server.token}",
                                      headers={"Origin": f"http://127.0.0.1:{server.port}"})
        page = cls(session, ws)
        await page.until(lambda m: m["t"] == "hello")
        return page

    async def send(self, message):
        await self.ws.send_str(message if isinstance(message, str) else json.dumps(message))

    async def until(self, done, timeout=60):
        """Read messages until done(message); that message."""
        deadline = time.monotonic() + timeout
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                raise AssertionError(f"timed out; the screen ends {self.screen[-300:]!r}")
            try:
                msg = await asyncio.wait_for(self.inbox.get(), left)
            except asyncio.TimeoutError:
                raise AssertionError(f"timed out; the screen ends {self.screen[-300:]!r}")
            if msg.type != aiohttp.WSMsgType.TEXT:
                raise AssertionError(f"the socket closed ({msg.type}); screen "
                                     f"{self.screen[-300:]!r}")
            message = json.loads(msg.data)
            protocol.check(message, protocol.TO_PAGE)       # the server speaks the protocol
            self.messages.append(message)
            self.count[message["t"]] = self.count.get(message["t"], 0) + 1
            if message["t"] == "con":
                self.screen += message["d"]
            if message["t"] == "hello":
                self.screen += message["con"]
            if done(message):
                return message

    async def type(self, text, answer=" ok", timeout=60):
        """Type text as the page does (pieces within the room the server gives);
        wait until the screen shows `answer` once more than before."""
        before, room = self.screen.count(answer), 4096
        while text:
            piece, text = text[:min(room, protocol.MAX_KEYS)], text[min(room, protocol.MAX_KEYS):]
            await self.send({"t": "key", "d": piece})
            reply = await self.until(lambda m: m["t"] in ("input", "error"))
            assert reply["t"] == "input", reply
            room = reply["room"]
            while room == 0:
                await asyncio.sleep(0.05)
                await self.send({"t": "key", "d": ""})
                room = (await self.until(lambda m: m["t"] == "input"))["room"]
        await self.see(answer, before, timeout)
        return self.screen

    async def see(self, answer, before=0, timeout=60):
        """Wait until the screen shows `answer` more than `before` times."""
        deadline = time.monotonic() + timeout
        while self.screen.count(answer) <= before:
            try:
                await self.until(lambda m: self.screen.count(answer) > before,
                                 max(0.1, deadline - time.monotonic()))
            except AssertionError:
                pass
            if self.screen.count(answer) <= before and time.monotonic() > deadline:
                raise AssertionError(f"no {answer!r}; the screen ends {self.screen[-300:]!r}")

    async def close(self):
        self.reader.cancel()
        await self.ws.close()
        await self.session.close()
