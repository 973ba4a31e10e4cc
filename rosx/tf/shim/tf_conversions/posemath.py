"""``tf_conversions.posemath``: PyKDL's frames to and from messages, which rosx cannot offer."""

from tf_conversions import WITHOUT_PYKDL  # type: ignore[import-not-found]

raise ImportError(f"tf_conversions.posemath {WITHOUT_PYKDL}")
