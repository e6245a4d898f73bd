"""Who may use the lab server (harness/lab/guard.py)."""
from harness.lab.guard import new_token, refusal

TOKEN, PORT = "s3cret-token", 8023
OWN = "http://127.0.0.1:8023"


def test_tokens_are_random_and_long():
    assert new_token() != new_token() and len(new_token()) >= 32


def test_the_page_and_assets_need_no_token():
    """They hold no secret: the token lives in the tab, not in what is served."""
    assert refusal("127.0.0.1:8023", None, TOKEN, PORT) is None
    assert refusal("localhost:8023", None, TOKEN, PORT) is None


def test_websockets_need_the_token():
    for given in (None, "", "guess", TOKEN + "x"):
        assert "token" in refusal("127.0.0.1:8023", given, TOKEN, PORT, OWN, websocket=True)
    assert refusal("127.0.0.1:8023", TOKEN, TOKEN, PORT, OWN, websocket=True) is None


def test_other_host_names_are_refused():
    assert "Host" in refusal("evil.example:8023", None, TOKEN, PORT)
    assert "Host" in refusal("127.0.0.1:9999", TOKEN, TOKEN, PORT, OWN, websocket=True)


def test_websockets_need_the_servers_own_origin():
    assert "origin" in refusal("127.0.0.1:8023", TOKEN, TOKEN, PORT, "http://evil.example",
                               websocket=True)
    assert "origin" in refusal("127.0.0.1:8023", TOKEN, TOKEN, PORT, None, websocket=True)
