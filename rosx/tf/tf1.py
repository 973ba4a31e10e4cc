"""The old ``tf`` API, over tf2 as ROS 1's Noetic ``tf`` is: ``Transformer``, ``TransformerROS``,
``TransformListener`` and ``TransformBroadcaster``.

Most course material still writes ``listener.lookupTransform('/turtle2', '/turtle1',
rospy.Time())`` (a leading slash is dropped, as tf2 wants none), ``waitForTransform``,
``transformPoint``… and ``br.sendTransform((x, y, 0), q, rospy.Time.now(), child, parent)``.
Lookups return ``([x, y, z], [x, y, z, w])``; matrices come from `rosx.tf.transformations`
(numpy, loaded on first use); failures are tf2's exceptions, ``tf.Exception`` being
``TransformException``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.tf.buffer import Buffer
from rosx.tf.exceptions import TransformException

if TYPE_CHECKING:
    from rosx.node import Node

_NO_THREAD = (
    "cannot wait for transform without a dedicated thread that listens to incoming TF messages"
)


def strip_leading_slash(s: str) -> str:
    """``s`` without its leading ``/`` (tf's frame names had one; tf2's have none)."""
    return s[1:] if s.startswith("/") else s


def _message(name: str) -> Any:
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

    return get_message_class(name)


def _numpy() -> Any:
    import numpy  # numpy only on this path

    return numpy


def _transformations() -> Any:
    from rosx.tf import transformations  # noqa: PLC0415 - numpy loads with it

    return transformations


class Transformer:
    """tf's ``Transformer(interpolate=True, cache_time=None)``: a buffer without a listener."""

    def __init__(self, interpolate: bool = True, cache_time: Any = None, node: Node | None = None):
        self._buffer = Buffer(cache_time, debug=False, node=node)
        self._using_dedicated_thread = False

    def allFramesAsDot(self, current_time: Any = None) -> str:  # noqa: N802 - tf's names
        """The tree in Graphviz's language."""
        if current_time:
            return self._buffer._allFramesAsDot(current_time)
        return self._buffer._allFramesAsDot()

    def allFramesAsString(self) -> str:  # noqa: N802
        """``Frame X exists with parent Y.`` per frame."""
        return self._buffer.all_frames_as_string()

    def setTransform(self, transform: Any, authority: str = "default_authority") -> None:  # noqa: N802
        """Store a ``geometry_msgs/TransformStamped``."""
        self._buffer.set_transform(transform, authority)

    def canTransform(self, target_frame: str, source_frame: str, time: Any) -> Any:  # noqa: N802
        """1 when the transform is available at ``time``, else 0."""
        return self._buffer.can_transform(
            strip_leading_slash(target_frame), strip_leading_slash(source_frame), time
        )

    def canTransformFull(  # noqa: N802
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> Any:
        """`canTransform` between two times, through ``fixed_frame``."""
        return self._buffer.can_transform_full(
            strip_leading_slash(target_frame),
            target_time,
            strip_leading_slash(source_frame),
            source_time,
            strip_leading_slash(fixed_frame),
        )

    def waitForTransform(  # noqa: N802
        self,
        target_frame: str,
        source_frame: str,
        time: Any,
        timeout: Any,
        polling_sleep_duration: Any = None,
    ) -> None:
        """Wait up to ``timeout`` for the transform.

        Raises:
            TransformException: it did not come (tf2's reason), or nothing listens.
        """
        if not self._using_dedicated_thread:
            raise TransformException(_NO_THREAD)
        ok, error = self._buffer.can_transform(
            strip_leading_slash(target_frame),
            strip_leading_slash(source_frame),
            time,
            timeout,
            return_debug_tuple=True,
        )
        if not ok:
            raise TransformException(
                error or f'no such transformation: "{source_frame}" -> "{target_frame}"'
            )

    def waitForTransformFull(  # noqa: N802
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Any,
        polling_sleep_duration: Any = None,
    ) -> None:
        """`waitForTransform` between two times, through ``fixed_frame``."""
        if not self._using_dedicated_thread:
            raise TransformException(_NO_THREAD)
        ok, error = self._buffer.can_transform_full(
            strip_leading_slash(target_frame),
            target_time,
            strip_leading_slash(source_frame),
            source_time,
            strip_leading_slash(fixed_frame),
            timeout,
            return_debug_tuple=True,
        )
        if not ok:
            raise TransformException(
                error or f'no such transformation: "{source_frame}" -> "{target_frame}"'
            )

    def chain(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> list[str]:
        """The frames between the two, through ``fixed_frame``."""
        buffer = self._buffer
        return buffer._chain(target_frame, target_time, source_frame, source_time, fixed_frame)

    def clear(self) -> None:
        """Forget the moving frames' transforms."""
        self._buffer.clear()

    def frameExists(self, frame_id: str) -> bool:  # noqa: N802
        """Whether ``frame_id`` has transforms (not a recommended API, as in tf)."""
        return frame_id in self.getFrameStrings()

    def getFrameStrings(self) -> list[str]:  # noqa: N802
        """The frames that have transforms."""
        return [frame.name for frame in self._buffer.frames() if frame.parent]

    def getLatestCommonTime(self, source_frame: str, dest_frame: str) -> Any:  # noqa: N802
        """The latest time both frames have data for."""
        return self._buffer.get_latest_common_time(
            strip_leading_slash(source_frame), strip_leading_slash(dest_frame)
        )

    def lookupTransform(  # noqa: N802
        self, target_frame: str, source_frame: str, time: Any
    ) -> tuple[list[float], list[float]]:
        """``([x, y, z], [x, y, z, w])`` from ``source_frame`` to ``target_frame``."""
        msg = self._buffer.lookup_transform(
            strip_leading_slash(target_frame), strip_leading_slash(source_frame), time
        )
        t = msg.transform.translation
        r = msg.transform.rotation
        return [t.x, t.y, t.z], [r.x, r.y, r.z, r.w]

    def lookupTransformFull(  # noqa: N802
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> tuple[list[float], list[float]]:
        """`lookupTransform` between two times, through ``fixed_frame``."""
        msg = self._buffer.lookup_transform_full(
            strip_leading_slash(target_frame),
            target_time,
            strip_leading_slash(source_frame),
            source_time,
            strip_leading_slash(fixed_frame),
        )
        t = msg.transform.translation
        r = msg.transform.rotation
        return [t.x, t.y, t.z], [r.x, r.y, r.z, r.w]

    def lookupTwist(  # noqa: N802
        self, tracking_frame: str, observation_frame: str, time: Any, averaging_interval: Any
    ) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """The velocity of ``tracking_frame`` seen from ``observation_frame``."""
        return self.lookupTwistFull(
            tracking_frame,
            observation_frame,
            observation_frame,
            (0, 0, 0),
            tracking_frame,
            time,
            averaging_interval,
        )

    def lookupTwistFull(  # noqa: N802
        self,
        tracking_frame: str,
        observation_frame: str,
        reference_frame: str,
        ref_point: Any,
        reference_point_frame: str,
        time: Any,
        averaging_interval: Any,
    ) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """`lookupTwist` expressed in ``reference_frame`` at ``ref_point``."""
        from rosx.client.timing import Duration, Time  # noqa: PLC0415 - the rospy API loads only when used

        np = _numpy()
        tf = _transformations()
        latest = self.getLatestCommonTime(observation_frame, tracking_frame)
        target_time = time or latest
        end = min(target_time + Duration.from_sec(0.5 * averaging_interval.to_sec()), latest)
        start = max(Time.from_sec(0.0001) + averaging_interval, end) - averaging_interval
        delta_t = (end - start).to_sec()
        start_tr, start_rt = self.lookupTransform(observation_frame, tracking_frame, start)
        end_tr, end_rt = self.lookupTransform(observation_frame, tracking_frame, end)
        d_r = np.dot(np.linalg.inv(tf.quaternion_matrix(start_rt)), tf.quaternion_matrix(end_rt))
        angle, axis, _ = tf.rotation_from_matrix(d_r)
        vel0 = tuple((end_tr[i] - start_tr[i]) / delta_t for i in range(3))
        rot0 = tuple(axis[i] * angle / delta_t for i in range(3))
        inverse_tr, inverse_rt = self.lookupTransform(reference_frame, tracking_frame, target_time)
        i_r = tf.quaternion_matrix(inverse_rt)[:3, :3]
        rot = np.dot(i_r, rot0)
        vel = np.dot(i_r, vel0) + np.cross(inverse_tr, rot)
        origin = np.array((inverse_tr[0], inverse_tr[1], inverse_tr[2], 1))
        rp_tr, rp_rt = self.lookupTransform(reference_frame, reference_point_frame, target_time)
        t = np.dot(tf.translation_matrix(rp_tr), tf.quaternion_matrix(rp_rt))
        desired = np.dot(t, (origin[0], origin[1], origin[2], 1))
        vel += np.dot(rot, (desired - origin)[:3])
        return (vel[0], vel[1], vel[2]), (rot[0], rot[1], rot[2])

    def setUsingDedicatedThread(self, value: bool) -> None:  # noqa: N802
        """Whether something fills this transformer (a listener does)."""
        self._using_dedicated_thread = value

    def getTFPrefix(self) -> str:  # noqa: N802
        """tf2 has no tf_prefix: the empty prefix."""
        return ""


class TransformerROS(Transformer):
    """A `Transformer` that transforms ROS messages and gives matrices."""

    def asMatrix(self, target_frame: str, hdr: Any) -> Any:  # noqa: N802
        """The 4x4 transform from ``hdr``'s frame (at its stamp) to ``target_frame``."""
        translation, rotation = self.lookupTransform(target_frame, hdr.frame_id, hdr.stamp)
        return self.fromTranslationRotation(translation, rotation)

    def fromTranslationRotation(self, translation: Any, rotation: Any) -> Any:  # noqa: N802
        """The 4x4 matrix of a translation and a quaternion."""
        tf = _transformations()
        return _numpy().dot(tf.translation_matrix(translation), tf.quaternion_matrix(rotation))

    def _points(self, mat44: Any, xyz: Any) -> tuple[float, float, float]:
        np = _numpy()
        moved = np.dot(mat44, np.array([xyz[0], xyz[1], xyz[2], 1.0]))
        return (moved[0], moved[1], moved[2])

    def transformPoint(self, target_frame: str, ps: Any) -> Any:  # noqa: N802
        """A ``PointStamped`` in ``target_frame``."""
        mat44 = self.asMatrix(target_frame, ps.header)
        r = _message("geometry_msgs/PointStamped")()
        r.header.stamp = ps.header.stamp
        r.header.frame_id = target_frame
        r.point = _message("geometry_msgs/Point")(
            *self._points(mat44, (ps.point.x, ps.point.y, ps.point.z))
        )
        return r

    def transformVector3(self, target_frame: str, v3s: Any) -> Any:  # noqa: N802
        """A ``Vector3Stamped`` in ``target_frame`` (rotated only)."""
        mat44 = self.asMatrix(target_frame, v3s.header)
        mat44[0, 3] = mat44[1, 3] = mat44[2, 3] = 0.0
        r = _message("geometry_msgs/Vector3Stamped")()
        r.header.stamp = v3s.header.stamp
        r.header.frame_id = target_frame
        v = v3s.vector
        r.vector = _message("geometry_msgs/Vector3")(*self._points(mat44, (v.x, v.y, v.z)))
        return r

    def transformQuaternion(self, target_frame: str, ps: Any) -> Any:  # noqa: N802
        """A ``QuaternionStamped`` in ``target_frame``."""
        tf = _transformations()
        mat44 = self.asMatrix(target_frame, ps.header)
        q = ps.quaternion
        pose44 = tf.quaternion_matrix((q.x, q.y, q.z, q.w))
        quat = tuple(tf.quaternion_from_matrix(_numpy().dot(mat44, pose44)))
        r = _message("geometry_msgs/QuaternionStamped")()
        r.header.stamp = ps.header.stamp
        r.header.frame_id = target_frame
        r.quaternion = _message("geometry_msgs/Quaternion")(*quat)
        return r

    def transformPose(self, target_frame: str, ps: Any) -> Any:  # noqa: N802
        """A ``PoseStamped`` in ``target_frame``."""
        np = _numpy()
        tf = _transformations()
        mat44 = self.asMatrix(target_frame, ps.header)
        p = ps.pose.position
        o = ps.pose.orientation
        pose44 = np.dot(
            tf.translation_matrix((p.x, p.y, p.z)), tf.quaternion_matrix((o.x, o.y, o.z, o.w))
        )
        moved = np.dot(mat44, pose44)
        xyz = tuple(tf.translation_from_matrix(moved))[:3]
        quat = tuple(tf.quaternion_from_matrix(moved))
        r = _message("geometry_msgs/PoseStamped")()
        r.header.stamp = ps.header.stamp
        r.header.frame_id = target_frame
        r.pose = _message("geometry_msgs/Pose")(
            _message("geometry_msgs/Point")(*xyz), _message("geometry_msgs/Quaternion")(*quat)
        )
        return r

    def transformPointCloud(self, target_frame: str, point_cloud: Any) -> Any:  # noqa: N802
        """A ``sensor_msgs/PointCloud`` in ``target_frame``."""
        r = _message("sensor_msgs/PointCloud")()
        r.header.stamp = point_cloud.header.stamp
        r.header.frame_id = target_frame
        r.channels = point_cloud.channels
        mat44 = self.asMatrix(target_frame, point_cloud.header)
        point = _message("geometry_msgs/Point32")
        r.points = [point(*self._points(mat44, (p.x, p.y, p.z))) for p in point_cloud.points]
        return r


class TransformListener(TransformerROS):
    """A `TransformerROS` filled from ``/tf`` and ``/tf_static``."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        from rosx.tf.listener import TransformListener as Listener  # noqa: PLC0415 - tf code loads only when used

        TransformerROS.__init__(self, *args, **kwargs)
        self._listener = Listener(self._buffer, node=kwargs.get("node"))
        self.setUsingDedicatedThread(True)


class TransformBroadcaster:
    """tf's broadcaster: ``sendTransform(translation, rotation, time, child, parent)``."""

    def __init__(self, queue_size: int = 100, node: Node | None = None) -> None:
        from rosx.tf.broadcaster import TransformBroadcaster as Broadcaster  # noqa: PLC0415 - tf code loads only when used

        self.tf2_broadcaster = Broadcaster(node=node)

    def sendTransform(  # noqa: N802
        self, translation: Any, rotation: Any, time: Any, child: str, parent: str
    ) -> None:
        """Send the transform from ``child`` to ``parent`` at ``time`` on ``/tf``."""
        t = _message("geometry_msgs/TransformStamped")()
        t.header.frame_id = parent
        t.header.stamp = time
        t.child_frame_id = child
        v = t.transform.translation
        v.x, v.y, v.z = translation[0], translation[1], translation[2]
        q = t.transform.rotation
        q.x, q.y, q.z, q.w = rotation[0], rotation[1], rotation[2], rotation[3]
        self.sendTransformMessage(t)

    def sendTransformMessage(self, transform: Any) -> None:  # noqa: N802
        """Send a ``geometry_msgs/TransformStamped`` on ``/tf``."""
        self.tf2_broadcaster.sendTransform([transform])


__all__ = [
    "TransformBroadcaster",
    "TransformListener",
    "Transformer",
    "TransformerROS",
    "strip_leading_slash",
]
