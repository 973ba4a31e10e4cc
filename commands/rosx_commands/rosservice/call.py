"""``rosservice call``: fill a request from YAML arguments (or stdin), call, print the response.

As ROS 1's: the service's type comes from a probe; each argument is one YAML document
(`rosx.msg.text.yamlargs`), an empty one the empty string; with no argument and a request that has
fields, YAML documents separated by ``---`` lines are read from stdin (unless it is a terminal)
and the service is called once per document. ``-v`` prints the request and a ``---`` line
first. ``--wait`` waits for the service to be advertised. Beyond ROS 1: ``--timeout SECS`` bounds
the wait and the call, and ``--nostr``/``--noarr`` shorten strings and arrays in what is printed,
as ``rostopic echo`` does.
"""

from __future__ import annotations

import io
import os
import time

from rosx.names.anonymous import anonymous_node_name
from rosx.terminal import is_terminal
from rosx_commands.cli import ToolParser
from rosx_commands.context import CommandError, Environment, ExitStatus
from rosx_commands.rosservice.services import SERVICE_ERROR, Services
from rosx_commands.yamltext import one_line

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

    from rosx.msg.codec.message import Message, ServiceDefinition

#: How often rospy's ``wait_for_service`` looks for the service, in seconds.
WAIT_PERIOD = 0.3


def _parser(env: Environment) -> ToolParser:
    parser = ToolParser(env, "rosservice", "usage: %prog call /service [args...]")
    parser.add_option(
        "-v", dest="verbose", default=False, action="store_true", help="print verbose output"
    )
    parser.add_option(
        "--wait",
        dest="wait",
        default=False,
        action="store_true",
        help="wait for service to be advertised",
    )
    parser.add_option(
        "--timeout",
        dest="timeout",
        default=None,
        type="float",
        metavar="SECS",
        help="give up when the service is not advertised (--wait) or has not answered after "
        "SECS seconds (rosx)",
    )
    parser.add_option(
        "--nostr",
        dest="nostr",
        default=False,
        action="store_true",
        help="exclude string fields from the output (rosx)",
    )
    parser.add_option(
        "--noarr",
        dest="noarr",
        default=False,
        action="store_true",
        help="exclude arrays from the output (rosx)",
    )
    return parser


def call_command(argv: list[str], env: Environment) -> int:
    """``rosservice call SERVICE [ARGS]``: call a service with YAML arguments, print the
    response."""
    parser = _parser(env)
    options, args = parser.parse(argv)
    if not args:
        parser.error("service must be specified")
    if options.timeout is not None and options.timeout <= 0:
        parser.error("--timeout must be a positive number of seconds")
    services = Services(env)
    name = services.resolve(args[0])
    if options.wait:
        services.master.check_online()
        _wait_for_service(services, name, options.timeout)
    service_class = services.service_class(name)
    caller = _Caller(services, name, service_class, options)
    service_args = _load_args(args[1:])
    if service_args or not service_class._request_class.__slots__:
        caller.call(service_args)
        return ExitStatus.OK
    if is_terminal(env.stdin):
        parser.error("Please specify service arguments")
    from rosx.msg.text.yamlload import load_stream  # noqa: PLC0415 - ruamel loads lazily

    def invalid(error: Exception) -> None:
        env.err(f"Invalid YAML: {one_line(str(error))}")

    for document in load_stream(env.stdin, invalid):
        if document:
            caller.call(document if type(document) is list else [document])
    return ExitStatus.OK


def _load_args(words: list[str]) -> list[Any]:
    from rosx.msg.text.yamlargs import load_args  # noqa: PLC0415 - ruamel loads lazily
    from rosx.msg.text.yamlload import YAMLLoadError  # noqa: PLC0415 - the text forms load on first use

    try:
        return load_args(words, empty_is_string=True)
    except YAMLLoadError as error:
        raise CommandError(f"ERROR: Invalid YAML in arguments: {one_line(str(error))}", 2) from None


def _wait_for_service(services: Services, name: str, timeout: float | None) -> None:
    """Block until ``name`` is advertised and answers a probe (rospy's ``wait_for_service``)."""
    from rosx.node.service_client import contact_service  # noqa: PLC0415 - call only

    deadline = None if timeout is None else time.monotonic() + timeout
    while not contact_service(services.master, name):
        if deadline is not None and time.monotonic() >= deadline:
            raise CommandError(
                f"ERROR: timeout exceeded while waiting for service {name}", SERVICE_ERROR
            )
        time.sleep(WAIT_PERIOD)


class _Caller:
    """Fills, sends and prints one request at a time."""

    def __init__(
        self,
        services: Services,
        name: str,
        service_class: type[ServiceDefinition],
        options: Any,
    ) -> None:
        self.services = services
        self.env = services.env
        self.name = name
        self.service_class = service_class
        self.options = options
        from rosx.node.service_client import ServiceClient  # noqa: PLC0415 - call only

        caller_id = "/" + anonymous_node_name("rosservice", pid=os.getpid())
        self.client = ServiceClient(services.master, name, service_class, caller_id=caller_id)

    def call(self, args: list[Any]) -> None:
        """Fill a request from ``args``, call the service, print the response.

        Raises:
            CommandError: the arguments do not fit or the call failed.
        """
        request = self._fill(args)
        payload = self._serialize(request)
        data = self.client.call_serialized(payload, timeout=self.options.timeout)
        response = self._deserialize(data)
        if self.options.verbose:
            self.env.out(self._format(request))
            self.env.out("---")
        self.env.out(self._format(response))
        self.env.stdout.flush()

    def _fill(self, args: list[Any]) -> Message:
        from rosx.msg.codec.message import MessageException  # noqa: PLC0415 - message classes load on first use
        from rosx.msg.text.yamlargs import call_error_text, fill_message_args  # noqa: PLC0415 - the text forms load on first use

        request = self.service_class._request_class()
        try:
            fill_message_args(request, args, store=self.services.store)
        except (MessageException, ValueError) as error:
            # ROS 1 lets the ValueError (a scalar where a message goes) escape as a traceback.
            text = call_error_text(error, args, request)
            raise CommandError(f"ERROR: {text}", SERVICE_ERROR) from None
        return request

    def _serialize(self, request: Message) -> bytes:
        from rosx.msg.codec.message import SerializationError  # noqa: PLC0415 - message classes load on first use
        from rosx.msg.describe import describe_srv  # noqa: PLC0415 - the message layer loads on first use

        buff = io.BytesIO()
        try:
            request.serialize(buff)
        except SerializationError as error:
            store = self.services.store
            srv_text = describe_srv(store.srv(self.service_class._type), store.msg)
            raise CommandError(
                "ERROR: Unable to send request. One of the fields has an incorrect type:\n"
                f"  {error}\n\nsrv file:\n{srv_text}",
                SERVICE_ERROR,
            ) from None
        return buff.getvalue()

    def _deserialize(self, data: bytes) -> Message:
        from rosx.msg.codec.message import DeserializationError  # noqa: PLC0415 - message classes load on first use

        try:
            return self.service_class._response_class().deserialize(data)
        except (DeserializationError, ValueError, IndexError) as error:
            raise CommandError(
                f"ERROR: transport error completing service call: {error}", SERVICE_ERROR
            ) from None

    def _format(self, msg: Message) -> str:
        from rosx.msg.text.echo import format_message  # noqa: PLC0415 - the text forms load on first use

        return format_message(msg, nostr=self.options.nostr, noarr=self.options.noarr)
