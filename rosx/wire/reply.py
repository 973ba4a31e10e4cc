"""ROS's XML-RPC reply convention (ROS wiki ROS/Master_API and ROS/Slave_API).

Every Master, Parameter and Slave API method answers with a 3-element array
``[code, statusMessage, value]``: code `SUCCESS` (1) with the value, `ERROR` (-1) when the caller
is wrong (bad arguments, unknown name), `FAILURE` (0) when the call was valid but did not work.
``value`` is meaningful only on success (callers conventionally ignore it otherwise).
"""

from __future__ import annotations

from rosx.record import Record
from rosx.wire.errors import ProtocolError

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

SUCCESS = 1
FAILURE = 0
ERROR = -1

_CODES = (SUCCESS, FAILURE, ERROR)


class RosReply(Record):
    """A decoded ``[code, statusMessage, value]`` reply."""

    __match_args__ = ("code", "status", "value")
    __slots__ = __match_args__
    code: int
    status: str
    value: Any

    def __init__(self, code: int, status: str, value: Any) -> None:
        super().__init__(code=code, status=status, value=value)

    @property
    def ok(self) -> bool:
        """Whether the call succeeded (code `SUCCESS`)."""
        return self.code == SUCCESS


def ros_reply(code: int, status: str, value: object = 0) -> list[object]:
    """The reply value to encode: ``[code, status, value]``."""
    if code not in _CODES:
        raise ProtocolError(f"ROS reply code must be 1, 0 or -1, not {code!r}")
    return [code, status, value]


def parse_ros_reply(value: object) -> RosReply:
    """Check that an XML-RPC response value follows the convention, and split it.

    Raises:
        ProtocolError: the value is not ``[int code, str status, value]``.
    """
    if not isinstance(value, list) or len(value) != 3:
        raise ProtocolError(
            f"a ROS reply must be [code, statusMessage, value], not {str(value)[:80]}"
        )
    code, status, result = value
    if type(code) is not int or not isinstance(status, str):
        raise ProtocolError(
            "a ROS reply must start with an int code and a string status message, not "
            f"{code!r}, {str(status)[:80]!r}"
        )
    return RosReply(code, status, result)
