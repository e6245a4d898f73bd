"""The lab's page of the five machines (harness/lab/controllers_page.py and
controllers_view.py): the view decoded from the coordinator's status, and the
server's guard (127.0.0.1, the Host header, the token)."""
import http.client
import json
from urllib.parse import urlparse

from harness.lab.controllers_page import serve
from harness.lab.controllers_view import servo_row, view

MOVE, STATUS = 0o122401, 0o122404


def axis(to_11_03, to_11_23, letter="X", sent=None):
    return {"axis": letter, "pos": 1999.5, "vel": 0.0, "dac": 2049, "counter": 1999, "run": 1,
            "to_11_03": to_11_03, "to_11_23": to_11_23, "sent": sent or {}}


def test_the_servo_table_is_read_off_the_link_words():
    row = servo_row(axis([[10, MOVE], [10, 2000], [20, STATUS], [20, 0]],
                         [[12, MOVE], [22, 3]], sent={"1": 2000, "4": 0}))
    assert row["target"] == 2000
    assert row["executing"] is True and row["moving"] is True
    assert row["counter"] == 1999 and row["dac"] == 2049
    assert row["last_words"] == ["122401", "003720", "122404", "000000"]


def test_a_negative_target_and_no_status_yet():
    row = servo_row(axis([[10, MOVE], [10, 0o177776]], [], sent={"1": 0o177776}))
    assert row["target"] == -2 and row["executing"] is None


def test_the_target_stays_while_move_complete_polls_the_status():
    """Move.Complete?'s polls push the move out of the last eight words; the
    coordinator's "sent" keeps its value, and the table its target."""
    polls = [[20 + i, w] for i in range(4) for w in (STATUS, 2)]
    row = servo_row(axis(polls, [[21 + i, 2] for i in range(4)], sent={"1": 2000, "2": 300, "4": 2}))
    assert row["target"] == 2000 and row["max_vel"] == 300
    assert row["executing"] is False and row["moving"] is True


def test_the_view_names_each_machine_its_state_and_console_tail():
    status = {"quantum": 500, "time_s": 0.5, "power": 0, "axes": [axis([], [])],
              "members": {"x": "running", "y": "lost", "z": "running", "t": "running",
                          "main": "running"}}
    v = view(status, {"y": "banner\r\n" + "".join(f"line {i}\r\n" for i in range(10))})
    machines = {m["name"]: m for m in v["machines"]}
    assert machines["y"]["state"] == "lost"
    assert v["rack_on"] is False                     # the coordinator's plant: POWER=OFF
    assert machines["y"]["console"].endswith("line 9\n") and "banner" not in machines["y"]["console"]
    assert view(None, {}) == {"started": False}


def get(url, path, host=None):
    u = urlparse(url)
    conn = http.client.HTTPConnection(u.hostname, u.port, timeout=10)
    conn.request("GET", path, headers={"Host": host} if host else {})
    r = conn.getresponse()
    return r.status, r.read()


def test_the_server_answers_with_the_token_only(tmp_path):
    status = {"quantum": 100, "time_s": 0.1, "power": 1, "axes": [axis([], [])],
              "members": {m: "running" for m in ("x", "y", "z", "t", "main")}}
    (tmp_path / "status.json").write_text(json.dumps(status))
    (tmp_path / "x.log").write_text("11/03 servo on axis x, link at 167760 ok\r\n")
    url, stop = serve(tmp_path / "status.json", tmp_path)
    try:
        token = url.split("token=")[1]
        assert get(url, "/")[0] == 200
        assert get(url, "/controllers.js")[0] == 200
        assert get(url, "/status")[0] == 403
        assert get(url, "/status?token=wrong")[0] == 403
        assert get(url, f"/status?token={token}", host="evil.example:80")[0] == 403
        code, body = get(url, f"/status?token={token}")
        v = json.loads(body)
        assert code == 200 and v["time_s"] == 0.1
        assert "11/03 servo on axis x" in v["machines"][0]["console"]
    finally:
        stop()
