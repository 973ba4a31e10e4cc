"""Which address servers bind and which host name they advertise in their URIs.

ROS 1 (rosgraph.network, roscpp's network.cpp) takes the advertised host from, in order, the
``__hostname:=`` / ``__ip:=`` remapping, ``ROS_HOSTNAME``, ``ROS_IP``, then the machine's host
name; it binds 127.0.0.1 when that override is a loopback name and 0.0.0.0 otherwise.

rosx keeps the overrides and their order, but without one it stays on the loopback interface:
it binds 127.0.0.1 and advertises ``localhost``, the host of ROS 1's default
``ROS_MASTER_URI``. ROS 1's choice, the host name, only works where that name resolves to an
address the server listens on; ``localhost`` always resolves to 127.0.0.1 on this machine, so
rospy and roscpp peers here reach rosx's servers, and nothing is exposed to the network until
``ROS_IP`` or ``ROS_HOSTNAME`` asks for it.

The environment is passed in (any mapping), never read from `os.environ` here.
"""

from __future__ import annotations

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Mapping

ROS_HOSTNAME = "ROS_HOSTNAME"
ROS_IP = "ROS_IP"

#: Advertised when neither ROS_HOSTNAME, ROS_IP nor a remapping names a host.
DEFAULT_HOST = "localhost"
#: Bound when no override says otherwise.
LOOPBACK_BIND = "127.0.0.1"


def address_override(environ: Mapping[str, str], remap: str | None = None) -> str | None:
    """The host a node must advertise, from `remap` (``__hostname:=``/``__ip:=``), ROS_HOSTNAME
    or ROS_IP, in that order; ``None`` when none is set (an empty value counts as unset)."""
    if remap:
        return remap
    if ROS_HOSTNAME in environ:
        return environ[ROS_HOSTNAME] or None
    return environ.get(ROS_IP) or None


def is_loopback_host(host: str) -> bool:
    """Whether `host` names this machine's loopback interface (``localhost``, 127/8, ``::1``)."""
    return host in ("localhost", "::1") or host.startswith("127.")


def advertised_host(environ: Mapping[str, str], remap: str | None = None) -> str:
    """The host to put in this process's URIs (see the module docstring)."""
    return address_override(environ, remap) or DEFAULT_HOST


def bind_host(environ: Mapping[str, str], remap: str | None = None) -> str:
    """The address servers listen on: loopback unless an override names another host."""
    override = address_override(environ, remap)
    if override is None or override == "localhost":
        return LOOPBACK_BIND
    if override.startswith("127.") or override == "::1":
        return override
    # Any other name may resolve to any interface of this machine, as in ROS 1.
    return "::" if ":" in override else "0.0.0.0"


def http_uri(host: str, port: int) -> str:
    """``http://host:port/``, with an IPv6 address in brackets."""
    if ":" in host and not host.startswith("["):
        host = f"[{host}]"
    return f"http://{host}:{port}/"


def uri_hostname(uri: str) -> str:
    """The host of a node's URI as ``urllib.parse`` reads it (lower case, IPv6 unbracketed).

    Empty when the URI names none or does not parse (``http://[::1/``): a node may register
    any string with the master.
    """
    from urllib.parse import urlsplit  # noqa: PLC0415 - only the tools that group by host

    try:
        return urlsplit(uri).hostname or ""
    except ValueError:
        return ""


def _is_url_scheme(text: str) -> bool:
    return (
        bool(text)
        and text[0].isascii()
        and text[0].isalpha()
        and all(c.isascii() and (c.isalnum() or c in "+-.") for c in text)
    )


def address_warnings(environ: Mapping[str, str]) -> list[str]:
    """ROS 1's warnings (rosgraph.network) for a malformed ROS_HOSTNAME or ROS_IP."""
    if ROS_HOSTNAME in environ:
        hostname = environ[ROS_HOSTNAME]
        if not hostname:
            return ["invalid ROS_HOSTNAME (an empty string)"]
        scheme, colon, rest = hostname.partition(":")
        if colon and _is_url_scheme(scheme):
            # As urllib splits it: "host:1" reads as scheme "host", no port.
            netloc = rest[2:].partition("/")[0] if rest.startswith("//") else ""
            with_port = "and port " if netloc.rpartition(":")[2].isdigit() else ""
            return [f"invalid ROS_HOSTNAME (protocol {with_port}should not be included)"]
        if ":" in hostname:
            return ["invalid ROS_HOSTNAME (port should not be included)"]
        return []
    if ROS_IP in environ:
        ip = environ[ROS_IP]
        if not ip:
            return ["invalid ROS_IP (an empty string)"]
        if "://" in ip:
            return ["invalid ROS_IP (protocol should not be included)"]
        if "." in ip and ip.rfind(":") > ip.rfind("."):
            return ["invalid ROS_IP (port should not be included)"]
        if "." not in ip and ":" not in ip:
            return ["invalid ROS_IP (must be a valid IPv4 or IPv6 address)"]
    return []


def is_local_host(host: str) -> bool:
    """Whether `host` resolves to this machine (a loopback address, or one of the host name's).

    ROS 1 (rosgraph.network.is_local_address) asks the same; used to warn when
    ``ROS_MASTER_URI`` names another machine. Looks the name up, so it may block briefly.
    """
    import socket  # noqa: PLC0415 - the other helpers are string work; keep them import-cheap

    if is_loopback_host(host):
        return True
    try:
        addresses = {info[4][0] for info in socket.getaddrinfo(host, 0, proto=socket.SOL_TCP)}
    except OSError:
        return False
    if any(is_loopback_host(str(address)) for address in addresses):
        return True
    try:
        own = {info[4][0] for info in socket.getaddrinfo(socket.gethostname(), 0)}
    except OSError:
        return False
    return bool(addresses & own)


def foreign_address_warning(environ: Mapping[str, str], remap: str | None = None) -> str | None:
    """A warning when the address this process would advertise is not one of this machine's.

    ROS 1 advertises such an address without a word, and peers then fail to connect with
    nothing to say why. Only a literal IPv4 or IPv6 address is checked (by binding a socket to
    it: no traffic, no name look-up); a host name is left to the resolver.
    """
    import ipaddress  # noqa: PLC0415 - the other helpers are string work; keep them import-cheap
    import socket  # noqa: PLC0415 - socket is not needed at start-up

    override = address_override(environ, remap)
    if override is None:
        return None
    try:
        address = ipaddress.ip_address(override.strip("[]"))
    except ValueError:
        return None
    family = socket.AF_INET6 if address.version == 6 else socket.AF_INET
    try:
        with socket.socket(family, socket.SOCK_STREAM) as probe:
            probe.bind((str(address), 0))
    except OSError:
        source = (
            "__ip/__hostname" if remap else (ROS_HOSTNAME if environ.get(ROS_HOSTNAME) else ROS_IP)
        )
        return (
            f"{source} is {override}, which is not an address of this machine: other nodes "
            f"cannot connect to this one (set {source} to one of this machine's addresses)"
        )
    return None
