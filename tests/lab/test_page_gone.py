"""A page that closes while the lab writes to it: no traceback, the others still served.

The lab queues its frames to each page; a page that goes away between the queueing
and the write made aiohttp raise inside a task nobody awaited, and asyncio printed
that task's traceback on the lab's terminal (seen once in CI, in the malformed-
messages test)."""
import asyncio

from aiohttp.client_exceptions import ClientConnectionResetError

from harness.lab.server import Lab


class ClosingSocket:
    """A socket that still looks open but whose transport is already closing."""
    closed = False

    async def send_str(self, text):
        raise ClientConnectionResetError("Cannot write to closing transport")


class Socket:
    closed = False

    def __init__(self):
        self.sent = []

    async def send_str(self, text):
        self.sent.append(text)


def test_a_frame_to_a_page_that_is_closing_is_dropped_quietly():
    lab = Lab.__new__(Lab)                # only the page list and the queued frames are needed
    gone, open_page = ClosingSocket(), Socket()
    lab.pages, lab.sending = {gone: "page 1", open_page: "page 2"}, set()
    errors = []

    async def go():
        asyncio.get_running_loop().set_exception_handler(lambda loop, ctx: errors.append(ctx))
        lab.broadcast({"t": "note"})
        lab.tell(gone, {"t": "error", "why": "x"})
        for _ in range(3):
            await asyncio.sleep(0)
    asyncio.run(go())
    assert errors == []
    assert open_page.sent == ['{"t": "note"}']
