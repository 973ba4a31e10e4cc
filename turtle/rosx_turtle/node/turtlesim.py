"""`TurtlesimNode`: turtlesim_node, the engine's `Simulation` behind ROS 1 interfaces.

What it offers (as Noetic's ``TurtleFrame``): the services ``clear``, ``reset``, ``spawn`` and
``kill`` in the node's namespace; per turtle the topics and services of `TurtleIo`; the private
parameters ``~background_r/g/b`` (set to 69/86/255 at start-up when missing, read only at
start-up, on ``clear`` and on ``reset``); the log lines of turtlesim word for word.

Threads: a `Ticker` runs every 16 ms. Each tick first runs the callbacks that arrived meanwhile
(the `Inbox`, turtlesim's ``spinOnce``), then, except on the very first tick, steps the
simulation with the fixed 0.016 s, logs the wall warnings and publishes every turtle's pose and
colour. Services are answered once their callback has run on that thread, as in roscpp.

A view observes the pond without being part of it: `snapshot` gives an immutable picture
(turtles, canvas copy, counters) from any thread, and `add_tick_listener` calls a function on
the tick thread after each tick with the tick's `TickReport` (keep it short: post a message).
"""

from __future__ import annotations

import re
import threading
import time
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_service_class
from rosx.names import validate
from rosx.names.validation import InvalidNameError
from rosx.node import DEBUG, ERROR, INFO, WARN
from rosx_turtle import roscpp
from rosx_turtle.console import Console, NodeLog
from rosx_turtle.engine import CENTRE, NameTakenError, Simulation
from rosx_turtle.engine.constants import DEFAULT_BACKGROUND, TICK_PERIOD, f32
from rosx_turtle.node.inbox import Inbox
from rosx_turtle.node.ticker import Ticker
from rosx_turtle.node.turtle_io import TurtleIo

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

    import numpy as np
    import numpy.typing as npt

    from rosx.msg.codec.message import Message
    from rosx.node import ServiceHandle
    from rosx_turtle.engine import TickReport, Turtles
    from rosx_turtle.roscpp import NodeArgs

#: The private parameters holding the background colour, in r, g, b order.
BACKGROUND_PARAMS = ("background_r", "background_g", "background_b")
_EXTERNAL = re.compile(r"external shutdown request from \[.*?\]: \[(.*)\]", re.DOTALL)


@dataclass(frozen=True, eq=False)
class PondSnapshot:
    """The pond at one moment, safe to keep: nothing in it changes afterwards.

    ``turtles`` is the engine's state (sorted by name; ``world_y``, ``theta``, ``sprite``,
    ``pen_*``); ``canvas`` an RGB copy (500, 500, 3) of the trails (None if not asked for);
    ``canvas_version`` changes whenever the trails do; ``ticks`` counts simulated steps.
    """

    ticks: int
    turtles: Turtles
    canvas: npt.NDArray[np.uint8] | None
    canvas_version: int


class TurtlesimNode:
    """turtlesim_node as a library object: `start`, observe, `shutdown`.

    Args:
        args: The node's name, namespace, remappings and private parameters.
        environ: The environment (``ROS_MASTER_URI``, ``ROS_IP``, ``ROSCONSOLE_FORMAT``...).
        console: Where log lines are printed (None: only ``/rosout``).
        seed: Seeds the sprites' choice (None: unpredictable).
        wall_clock: The wall clock (seconds) the command timeout is measured with.
    """

    def __init__(
        self,
        args: NodeArgs,
        *,
        environ: Mapping[str, str],
        console: Console | None = None,
        seed: int | None = None,
        wall_clock: Callable[[], float] = time.time,
    ) -> None:
        self.args = args
        self.node = args.make_node(environ)
        self._log = NodeLog(self.node, console)
        self._clock = wall_clock
        self.sim = Simulation(seed=seed)
        self.ticks = 0
        self._inbox: Inbox[Simulation] = Inbox()
        self._ios: dict[str, TurtleIo] = {}
        self._services: list[ServiceHandle] = []
        self._listeners: list[Callable[[TickReport], object]] = []
        self._lock = threading.Lock()
        self._first_tick = True
        self._ticker = Ticker(
            TICK_PERIOD,
            self._tick,
            name=f"rosx-turtlesim{self.node.name}",
            on_error=lambda exc: self.log(ERROR, f"turtlesim tick failed: {exc}"),
        )

    # -- lifecycle ----------------------------------------------------------------------------

    def start(self) -> TurtlesimNode:
        """Register with the master, set the parameters, spawn turtle1 and start ticking.

        Raises:
            TransportError: the master cannot be reached.
        """
        node = self.node
        node.start()
        node.on_shutdown(self._node_shut_down)
        try:
            self.args.set_private_params(node)
            for key, default in zip(BACKGROUND_PARAMS, DEFAULT_BACKGROUND, strict=True):
                if not node.params.has("~" + key):
                    node.params.set("~" + key, default)
            self.sim.clear(self._background())
            for name, kind, handler in (
                ("clear", "std_srvs/Empty", self._clear),
                ("reset", "std_srvs/Empty", self._reset),
                ("spawn", "turtlesim/Spawn", self._spawn),
                ("kill", "turtlesim/Kill", self._kill),
            ):
                self._services.append(
                    roscpp.advertise_service(node, name, get_service_class(kind), handler, self.log)
                )
            self.log(INFO, f"Starting turtlesim with node name {node.name}")
            self._add_turtle(self.sim, CENTRE, CENTRE, 0.0, "")
            self._ticker.start()
        except BaseException:
            self.shutdown("start-up failed")
            raise
        return self

    def shutdown(self, reason: str = "") -> None:
        """Stop ticking and leave the ROS graph."""
        self._ticker.stop()
        self._inbox.close()
        self.node.shutdown(reason)

    def is_shutdown(self) -> bool:
        """Whether the node has shut down."""
        return self.node.is_shutdown()

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        """Block until the node shuts down; False if ``timeout`` passed first."""
        return self.node.wait_for_shutdown(timeout)

    def _node_shut_down(self, reason: str) -> None:
        external = _EXTERNAL.fullmatch(reason)
        if external is not None:
            self.log(WARN, "Shutdown request received.")
            self.log(WARN, f"Reason given for shutdown: [{external.group(1)}]")
        self._ticker.stop()
        self._inbox.close()

    # -- for the turtles' callbacks and for views ---------------------------------------------

    def log(self, level: int, message: str) -> None:
        """Log a record to the console and ``/rosout``."""
        self._log(level, message)

    def post(self, action: Callable[[Simulation], object]) -> None:
        """Run ``action(simulation)`` on the tick thread before the next tick."""
        self._inbox.post(action)

    def call(self, action: Callable[[Simulation], object]) -> object:
        """As `post`, waiting for the result (not from the tick thread)."""
        return self._inbox.call(action)

    def snapshot(self, *, canvas: bool = True) -> PondSnapshot:
        """The pond now (see `PondSnapshot`); callable from any thread."""
        with self._lock:
            sim = self.sim
            return PondSnapshot(
                ticks=self.ticks,
                turtles=sim.turtles,
                canvas=sim.canvas.snapshot() if canvas else None,
                canvas_version=sim.canvas.version,
            )

    def add_tick_listener(self, listener: Callable[[TickReport], object]) -> Callable[[], None]:
        """Call ``listener(report)`` on the tick thread after every tick; returns a remover."""
        self._listeners = [*self._listeners, listener]

        def remove() -> None:
            self._listeners = [item for item in self._listeners if item is not listener]

        return remove

    # -- the tick -----------------------------------------------------------------------------

    def _tick(self) -> None:
        sim = self.sim
        self._inbox.drain(sim)
        if self._first_tick:  # turtlesim's first tick only starts its clock
            self._first_tick = False
            return
        with self._lock:
            report = sim.tick(self._clock())
            self.ticks += 1
        warnings = dict(zip(report.walls.rows.tolist(), report.walls.messages(), strict=True))
        debug = self._log.enabled(DEBUG)
        colours = report.colours.tolist()
        for row, name in enumerate(report.turtles.names):
            if row in warnings:
                self.log(WARN, warnings[row])
            io = self._ios.get(name)
            if io is None:
                continue
            io.publish(report.pose(row), tuple(colours[row]))
            if debug:
                x, y = report.turtles.x[row], report.turtles.y[row]
                theta = report.turtles.theta[row]
                self.log(DEBUG, f"[{io.namespace}]: pos_x: {x:f} pos_y: {y:f} theta: {theta:f}")
        for listener in self._listeners:
            listener(report)

    # -- the pond's services (their callbacks run on the tick thread) ------------------------

    def _background(self) -> list[int]:
        params = self.node.params
        return [
            roscpp.param_int(params.get("~" + key, default), default)
            for key, default in zip(BACKGROUND_PARAMS, DEFAULT_BACKGROUND, strict=True)
        ]

    def _add_turtle(self, sim: Simulation, x: float, y: float, theta: float, name: str) -> str:
        return self._attach(sim, sim.spawn(x, y, theta, name), x, y, theta)

    def _attach(self, sim: Simulation, name: str, x: float, y: float, theta: float) -> str:
        """Give the new turtle ``name`` its topics and services, and log its spawning."""
        try:
            self._ios[name] = TurtleIo(self, name, self._clock)
        except BaseException:
            sim.kill(name)
            raise
        x, y, theta = f32(x), f32(y), f32(theta)
        self.log(INFO, f"Spawning turtle [{name}] at x=[{x:f}], y=[{y:f}], theta=[{theta:f}]")
        return name

    def _spawn(self, request: Any) -> object:
        def spawn(sim: Simulation) -> Message | None:
            name = request.name
            if name and name in sim:
                self.log(ERROR, f"A turtled named [{name}] already exists")
                return None
            error = validate(name) if name else None
            if error is not None:
                raise InvalidNameError(error)
            try:
                real = self._add_turtle(sim, request.x, request.y, request.theta, name)
            except NameTakenError:
                return None
            response: Message = get_service_class("turtlesim/Spawn")._response_class(name=real)
            return response

        return self.call(spawn)

    def _kill(self, request: Any) -> object:
        def kill(sim: Simulation) -> object:
            name = request.name
            if not sim.kill(name):
                self.log(ERROR, f"Tried to kill turtle [{name}], which does not exist")
                return None
            io = self._ios.pop(name, None)
            if io is not None:
                io.close()
            return {}

        return self.call(kill)

    def _clear(self, request: Any) -> object:
        def clear(sim: Simulation) -> object:
            self.log(INFO, "Clearing turtlesim.")
            background = self._background()
            with self._lock:
                sim.clear(background)
            return {}

        return self.call(clear)

    def _reset(self, request: Any) -> object:
        def reset(sim: Simulation) -> object:
            self.log(INFO, "Resetting turtlesim.")
            for io in self._ios.values():
                io.close()
            self._ios.clear()
            background = self._background()
            with self._lock:
                name = sim.reset(background)
            self._attach(sim, name, CENTRE, CENTRE, 0.0)
            return {}

        return self.call(reset)
