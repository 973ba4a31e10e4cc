"""What a client's subscriptions to one topic ask for, and what several of them add up to."""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(slots=True)
class SubscriptionOptions:
    """One ``subscribe`` of a topic by this client (rosbridge keys them by ``id``)."""

    throttle_ms: float = 0.0
    queue_length: int = 0
    fragment_size: int | None = None
    compression: str = "none"


class TopicSubscriptions:
    """This client's subscriptions to one topic and what they add up to."""

    __slots__ = ("by_id", "last_sent", "options")

    def __init__(self) -> None:
        self.by_id: dict[object, SubscriptionOptions] = {}
        self.options = SubscriptionOptions()
        self.last_sent = -math.inf

    def combine(self, latest: SubscriptionOptions) -> None:
        """The lowest throttle and fragment size, the longest queue, the latest compression
        (rosbridge's rule for several subscriptions of one topic)."""
        subs = list(self.by_id.values())
        sizes = [s.fragment_size for s in subs if s.fragment_size]
        self.options = SubscriptionOptions(
            throttle_ms=min(s.throttle_ms for s in subs),
            queue_length=max(s.queue_length for s in subs),
            fragment_size=min(sizes) if sizes else None,
            compression=latest.compression,
        )


__all__ = ["SubscriptionOptions", "TopicSubscriptions"]
