"""How often the server sends the page data: 30 a second at real pace and x10
(issue 11's smooth drawing), fewer at full speed (docs/lab.md, cost)."""
from harness.lab.server import frame_interval, news


def test_real_pace_and_x10_send_thirty_frames_a_second():
    assert frame_interval("real") == frame_interval("x10") == 1 / 30


def test_full_speed_sends_fewer_frames():
    assert frame_interval("full") > frame_interval("real")


def test_a_frame_goes_out_only_with_news():
    assert news([[0.1, 0, 0, 0, 0, 0, 0]], "same", "same")
    assert news([], "paused at 2.0 s", "running at 1.9 s")
    assert not news([], "paused at 2.0 s", "paused at 2.0 s")
