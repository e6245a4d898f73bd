"""Who may use the lab server (harness/lab/guard.py)."""
from harness.lab.guard import new_token, refusal

TOKEN, PORT = "s3cret-token", 8023


def test_tokens_are_random_and_long():
    assert new_token() != new_token() and len(new_token()) >= 32


def test_the_page_with_its_token_or_cookie_is_served():
    assert refusal("127.0.0.1:8023", TOKEN, None, TOKEN, PORT) is None
    assert refusal("localhost:8023", None, TOKEN, TOKEN, PORT) is None


def test_missing_or_wrong_tokens_are_refused():
    assert "token" in refusal("127.0.0.1:8023", None, None, TOKEN, PORT)
    assert "token" in refusal("127.0.0.1:8023", "guess", "other", TOKEN, PORT)
    assert "token" in refusal("127.0.0.1:8023", "", None, TOKEN, PORT)


def test_other_host_names_are_refused():
    assert "Host" in refusal("evil.example:8023", TOKEN, None, TOKEN, PORT)
    assert "Host" in refusal("127.0.0.1:9999", TOKEN, None, TOKEN, PORT)


def test_websockets_need_the_servers_own_origin():
    ok = dict(websocket=True)
    assert refusal("127.0.0.1:8023", TOKEN, None, TOKEN, PORT, "http://127.0.0.1:8023", **ok) is None
    assert "origin" in refusal("127.0.0.1:8023", TOKEN, None, TOKEN, PORT,
                               "http://evil.example", **ok)
    assert "origin" in refusal("127.0.0.1:8023", TOKEN, None, TOKEN, PORT, None, **ok)
