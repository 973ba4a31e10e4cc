"""Who may use the bridge: browser pages by their ``Origin``, clients by a token.

A web page the user visits could open a WebSocket to ``ws://localhost:9090`` and drive their
robot; browsers always send the page's ``Origin`` header, so the server refuses origins not on
its allow-list. By default only pages of this machine are allowed: served from it
(``localhost``, ``127.x.x.x``, ``[::1]``, any port), or opened from one of its files where the
browser says so (``file://``, Chromium with ``--allow-file-access-from-files``); programs that
send no ``Origin`` (roslibpy, node) are not browsers and pass. Browsers otherwise give a page
opened from a file the origin ``null``, which sandboxed frames of any web site have too, so
``null`` is refused unless ``--allow-origin null`` says otherwise (``*`` wildcards, ``*`` for
any); a refused page's line in the log names the option that lets it in.

With a token, a client proves it knows the token with rosbridge's ``auth`` op, either as the
``mac`` itself or as rosauth's MAC: ``sha512(token + client + dest + rand + t + level + end)``
in hex, ``t`` within `AUTH_WINDOW` seconds of the server's time, ``end`` not past.
"""

from __future__ import annotations

import fnmatch
import hashlib
import hmac
from collections.abc import Sequence
from typing import Any
from urllib.parse import urlsplit

_LOCAL_HOSTS = ("localhost", "::1")
#: How far (seconds) an ``auth`` request's time ``t`` may be from the server's.
AUTH_WINDOW = 300


#: The origin of a page opened from a file of this machine, where the browser tells it (Chromium
#: with ``--allow-file-access-from-files``); otherwise such a page's origin is ``null``.
FILE_ORIGIN = "file://"


def is_local_origin(origin: str) -> bool:
    """Whether ``origin`` is a page of this machine: served from it (http or https, any port),
    or opened from one of its files (`FILE_ORIGIN`)."""
    if origin == FILE_ORIGIN:
        return True
    try:
        parts = urlsplit(origin)
        host = parts.hostname or ""
    except ValueError:
        return False
    if parts.scheme not in ("http", "https"):
        return False
    return host in _LOCAL_HOSTS or host.startswith("127.") or host.endswith(".localhost")


def origin_allowed(origin: str | None, allow: Sequence[str] = ()) -> bool:
    """Whether a connection with header ``Origin: origin`` (None: none sent) is served."""
    if origin is None:
        return True
    if is_local_origin(origin):
        return True
    return any(fnmatch.fnmatchcase(origin.lower(), pattern.lower()) for pattern in allow)


def check_auth(token: str, request: dict[str, Any], now: int) -> bool:
    """Whether an ``auth`` request proves knowledge of ``token`` at server time ``now``."""
    mac = str(request.get("mac", ""))
    if hmac.compare_digest(mac.encode(), token.encode()):
        return True
    try:
        t, end = int(request.get("t", 0)), int(request.get("end", 0))
    except (TypeError, ValueError):
        return False
    if abs(now - t) > AUTH_WINDOW or (end and end < now):
        return False
    fields = [str(request.get(k, "")) for k in ("client", "dest", "rand")]
    text = token + "".join(fields) + str(t) + str(request.get("level", "")) + str(end)
    expected = hashlib.sha512(text.encode()).hexdigest()
    return hmac.compare_digest(mac.encode(), expected.encode())


def refusal(origin: str | None, kind: str = "") -> str:
    """The line a server logs when it refuses a page of ``origin``: what lets it in (``kind``:
    the protocol's name, ``"Foxglove"``, or nothing for rosbridge's)."""
    connection = f"{kind} connection" if kind else "connection"
    return (
        f"Refused a {connection} from a page of {origin}: not an allowed origin (--allow-origin "
        f"{origin}, or allow_origin:={origin} with roslaunch, lets its pages connect)"
    )


def refusal_answer(origin: str | None) -> str:
    """The body of the HTTP answer (403) refusing a page of ``origin``: what lets it in."""
    return (
        f"Origin {origin} is not allowed: start the bridge with --allow-origin {origin} "
        "to let its pages connect\n"
    )


__all__ = [
    "AUTH_WINDOW",
    "FILE_ORIGIN",
    "check_auth",
    "is_local_origin",
    "origin_allowed",
    "refusal",
    "refusal_answer",
]
