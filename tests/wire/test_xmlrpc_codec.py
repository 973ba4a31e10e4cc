"""XML-RPC documents: exact encoding, round trips of every type, stdlib compatibility, refusals."""

from __future__ import annotations

import datetime
import math
import xmlrpc.client
from typing import Any

import pytest

from rosx.wire.errors import ProtocolError
from rosx.wire.xmlrpc import (
    Fault,
    MethodCall,
    MethodResponse,
    decode_call,
    decode_response,
    encode_call,
    encode_fault,
    encode_response,
    encode_value,
)

PROLOG = b'<?xml version="1.0"?>'

VALUES: list[Any] = [
    0,
    1,
    -1,
    2**31 - 1,
    -(2**31),
    True,
    False,
    "",
    "plain",
    "caf\u00e9 \u2603 \U0001f422",
    "<tag> & 'quotes' \"double\" ]]>",
    "  spaced\n\tlines  ",
    0.0,
    -2.5,
    1e308,
    -1.7976931348623157e308,
    5e-324,
    0.1,
    b"",
    b"\x00\x01\xff binary",
    bytes(range(256)) * 3,
    [],
    {},
    [1, "two", 3.0, [4, [5, [6]]], {"seven": [8]}],
    {"a": {"b": {"c": []}}, "": "empty key", "x&y": [True, b"\x00"]},
    [[f"/topic_{i}", [f"/node_{i}", "/other"]] for i in range(5)],
    xmlrpc.client.DateTime("20240102T03:04:05"),
    {"when": [xmlrpc.client.DateTime("19980717T14:08:55")]},
]


def test_call_bytes_are_exact() -> None:
    assert encode_call("getPid", ["/rostopic"]) == (
        PROLOG + b"<methodCall><methodName>getPid</methodName><params><param><value>"
        b"<string>/rostopic</string></value></param></params></methodCall>"
    )
    assert encode_call("m", []) == (
        PROLOG + b"<methodCall><methodName>m</methodName><params></params></methodCall>"
    )


def test_response_and_fault_bytes_are_exact() -> None:
    assert encode_response([1, "", 42]) == (
        PROLOG + b"<methodResponse><params><param><value><array><data>"
        b"<value><int>1</int></value><value><string></string></value>"
        b"<value><int>42</int></value></data></array></value></param></params></methodResponse>"
    )
    assert encode_fault(-1, "a<b") == (
        PROLOG + b"<methodResponse><fault><value><struct>"
        b"<member><name>faultCode</name><value><int>-1</int></value></member>"
        b"<member><name>faultString</name><value><string>a&lt;b</string></value></member>"
        b"</struct></value></fault></methodResponse>"
    )


@pytest.mark.parametrize(
    ("value", "xml"),
    [
        (True, "<value><boolean>1</boolean></value>"),
        (False, "<value><boolean>0</boolean></value>"),
        (-7, "<value><int>-7</int></value>"),
        (1.5, "<value><double>1.5</double></value>"),
        (1e100, "<value><double>1e+100</double></value>"),
        (b"hi!", "<value><base64>aGkh</base64></value>"),
        ("a&b>c", "<value><string>a&amp;b&gt;c</string></value>"),
        ((), "<value><array><data></data></array></value>"),
        (
            {"k": 1},
            "<value><struct><member><name>k</name><value><int>1</int></value></member></struct></value>",
        ),
    ],
)
def test_value_bytes_are_exact(value: object, xml: str) -> None:
    assert encode_value(value) == xml


@pytest.mark.parametrize("value", VALUES, ids=range(len(VALUES)))
def test_round_trip(value: Any) -> None:
    assert decode_response(encode_response(value)) == MethodResponse(value)
    call = decode_call(encode_call("setParam", ["/caller", "/key", value]))
    assert call == MethodCall("setParam", ("/caller", "/key", value))


def test_date_times_keep_their_text_and_datetimes_are_written_as_python_writes_them() -> None:
    kept = xmlrpc.client.DateTime("2024-01-02T03:04:05 <odd> & more")
    decoded = decode_response(encode_response(kept))
    assert isinstance(decoded, MethodResponse) and isinstance(decoded.value, xmlrpc.client.DateTime)
    assert decoded.value.value == kept.value
    when = datetime.datetime(33, 1, 2, 3, 4, 5, 678)
    text = "00330102T03:04:05"
    assert f"<dateTime.iso8601>{text}</dateTime.iso8601>" in xmlrpc.client.dumps((when,))
    assert encode_value(when) == f"<value><dateTime.iso8601>{text}</dateTime.iso8601></value>"


def test_round_trip_keeps_types() -> None:
    decoded = decode_response(encode_response([True, 1, 1.0, "1", b"1", (2,)]))
    assert isinstance(decoded, MethodResponse)
    assert [type(v) for v in decoded.value] == [bool, int, float, str, bytes, list]
    assert decoded.value[5] == [2]


def test_special_doubles() -> None:
    decoded = decode_response(encode_response([math.inf, -math.inf, math.nan]))
    assert isinstance(decoded, MethodResponse)
    assert decoded.value[:2] == [math.inf, -math.inf]
    assert math.isnan(decoded.value[2])


def test_long_text_arrives_whole() -> None:
    text = ("x&<>\u00e9" * 40000) + "end"  # far beyond expat's buffer, with entities throughout
    assert decode_response(encode_response([text, text])) == MethodResponse([text, text])


@pytest.mark.parametrize("value", VALUES, ids=range(len(VALUES)))
def test_decodes_what_python_xmlrpc_writes(value: Any) -> None:
    stdlib_value = xmlrpc.client.Binary(value) if isinstance(value, bytes) else value
    call = xmlrpc.client.dumps(("/caller", stdlib_value), methodname="setParam").encode()
    assert decode_call(call) == MethodCall("setParam", ("/caller", value))
    response = xmlrpc.client.dumps((stdlib_value,), methodresponse=True).encode()
    assert decode_response(response) == MethodResponse(value)


@pytest.mark.parametrize("value", VALUES, ids=range(len(VALUES)))
def test_python_xmlrpc_reads_what_we_write(value: Any) -> None:
    params, method = xmlrpc.client.loads(encode_call("m", [value]), use_builtin_types=True)
    assert (method, params) == ("m", (_as_stdlib(value),))
    params, _ = xmlrpc.client.loads(encode_response(value), use_builtin_types=True)
    assert params == (_as_stdlib(value),)


def _as_stdlib(value: Any) -> Any:
    """How xmlrpc.client returns `value`: arrays as lists."""
    if isinstance(value, tuple | list):
        return [_as_stdlib(v) for v in value]
    if isinstance(value, dict):
        return {k: _as_stdlib(v) for k, v in value.items()}
    return value


def test_python_fault_and_ours() -> None:
    stdlib_fault = xmlrpc.client.dumps(xmlrpc.client.Fault(3, "bad & wrong"), methodresponse=True)
    assert decode_response(stdlib_fault.encode()) == Fault(3, "bad & wrong")
    with pytest.raises(xmlrpc.client.Fault) as info:
        xmlrpc.client.loads(encode_fault(3, "bad & wrong"))
    assert (info.value.faultCode, info.value.faultString) == (3, "bad & wrong")


@pytest.mark.parametrize(
    ("xml", "expected"),
    [
        ("<value>untyped</value>", "untyped"),
        ("<value></value>", ""),
        ("<value> <string> padded </string> </value>", " padded "),
        ("<value><string/></value>", ""),
        ("<value><i4>-4</i4></value>", -4),
        ("<value><i8>9007199254740993</i8></value>", 9007199254740993),
        ("<value><int> 12 </int></value>", 12),
        ("<value><boolean> 1 </boolean></value>", True),
        ("<value><double>-1.5E3</double></value>", -1500.0),
        ("<value><base64>aGVs\nbG8=\n</base64></value>", b"hello"),
        ("<value><nil/></value>", None),
        # Kept as text, as Python's xmlrpc.client (and so rosmaster) keeps it, whatever it says.
        (
            "<value><dateTime.iso8601>19980717T14:08:55</dateTime.iso8601></value>",
            xmlrpc.client.DateTime("19980717T14:08:55"),
        ),
        (
            "<value><dateTime.iso8601> 2024-01-02T03:04:05\n</dateTime.iso8601></value>",
            xmlrpc.client.DateTime("2024-01-02T03:04:05"),
        ),
        (
            "<value><dateTime.iso8601>whenever</dateTime.iso8601></value>",
            xmlrpc.client.DateTime("whenever"),
        ),
        ("<value><string>&#x2603;&#9731;&quot;&apos;</string></value>", "\u2603\u2603\"'"),
        ("<value><string><![CDATA[<raw>]]></string></value>", "<raw>"),
        # Spellings that the decoder's rewrite of common wrappers must not change:
        ("<value><string>x</string>\n</value>", "x"),
        ("<value>\n<string>x</string></value>", "x"),
        ("<value><array><data><value>1</value></data>\n</array></value>", ["1"]),
        ("<value><array>\n<data><value>1</value></data></array></value>", ["1"]),
        (
            "<value><string><![CDATA[<value><string>a</string></value>]]></string></value>",
            "<value><string>a</string></value>",
        ),
        (
            "<value><struct><member><name>a</name><value>1</value></member>"
            "<member><name>a</name><value>2</value></member></struct></value>",
            {"a": "2"},
        ),
    ],
)
def test_decoding_what_the_spec_allows(xml: str, expected: object) -> None:
    body = f"<?xml version='1.0' encoding='UTF-8'?>\n<methodResponse>\n<params><param>{xml}"
    body += "</param></params></methodResponse>\n"
    assert decode_response(body.encode()) == MethodResponse(expected)


def test_call_without_params() -> None:
    body = b"<methodCall><methodName>getPid</methodName></methodCall>"
    assert decode_call(body) == MethodCall("getPid", ())


@pytest.mark.parametrize(
    ("value", "message"),
    [
        (2**31, "int 2147483648 is outside XML-RPC's 32-bit range"),
        (-(2**31) - 1, "int -2147483649 is outside"),
        ([1, [2, 2**40]], "is outside XML-RPC's 32-bit range"),
        (None, "cannot carry None"),
        ({1: "x"}, "struct keys must be strings, not 1"),
        ({1.5}, "cannot carry a value of type set"),
        (object(), "cannot carry a value of type object"),
    ],
)
def test_encoding_refuses_what_xmlrpc_cannot_carry(value: object, message: str) -> None:
    with pytest.raises(ProtocolError, match=message):
        encode_response(value)


def test_subclasses_encode_as_their_base_types() -> None:
    import enum

    class Code(enum.IntEnum):
        OK = 1

    class Name(str):
        pass

    assert encode_value([Code.OK, Name("n")]) == encode_value([1, "n"])


def _response(inner: str) -> bytes:
    return f"<methodResponse><params><param>{inner}</param></params></methodResponse>".encode()


@pytest.mark.parametrize(
    ("body", "message"),
    [
        (b"not xml", "malformed XML-RPC document"),
        (b"<methodResponse><params>", "malformed XML-RPC document"),
        (b"\xff\xfe", "malformed XML-RPC document"),
        (b"<html/>", r"<html> is not allowed as the document element"),
        (_response("<value><int>1</int><int>2</int></value>"), "holds more than one value"),
        (_response("<value><bogus/></value>"), "<bogus> is not allowed inside <value>"),
        (_response("<value><int><int>1</int></int></value>"), "<int> is not allowed inside <int>"),
        (_response("<value><int>x</int></value>"), r"<int> holds 'x'"),
        (_response("<value><double>1,5</double></value>"), r"<double> holds '1,5'"),
        (_response("<value><boolean>2</boolean></value>"), r"<boolean> holds '2'"),
        (_response("<value><base64>\u00e9</base64></value>"), "<base64> holds"),
        (_response("<value><base64>abc</base64></value>"), "<base64> holds"),
        (
            _response("<value><struct><member><value>1</value></member></struct></value>"),
            "needs one <name> and one <value>",
        ),
        (
            _response(
                "<value><struct><member><value>1</value><name>a</name></member></struct></value>"
            ),
            "must start with its <name>",
        ),
        (_response(""), "a <param> needs exactly one <value>"),
        (_response("<value>1</value><value>2</value>"), "a <param> needs exactly one <value>"),
        (
            b"<methodResponse><params><param><value>1</value></param>"
            b"<param><value>2</value></param></params></methodResponse>",
            "holding one <param> or a <fault>",
        ),
        (b"<methodResponse><params></params></methodResponse>", "holding one <param>"),
        (
            b"<methodResponse><fault><value><int>1</int></value></fault></methodResponse>",
            "a <fault> must be a struct of faultCode and faultString",
        ),
        (
            b"<methodResponse><fault><value><struct><member><name>faultCode</name>"
            b"<value>1</value></member></struct></value></fault></methodResponse>",
            "a <fault> must be a struct of faultCode and faultString",
        ),
        (
            b"<methodCall><methodName>m</methodName></methodCall>",
            "expected a <methodResponse>",
        ),
        (
            b'<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol">]>'
            b"<methodResponse><params><param><value>&lol;</value></param></params>"
            b"</methodResponse>",
            "must not contain a DTD",
        ),
    ],
)
def test_malformed_responses_are_refused(body: bytes, message: str) -> None:
    with pytest.raises(ProtocolError, match=message):
        decode_response(body)


@pytest.mark.parametrize(
    ("body", "message"),
    [
        (b"<methodCall><params></params></methodCall>", "holding a <methodName>"),
        (
            b"<methodCall><params></params><methodName>m</methodName></methodCall>",
            "holding a <methodName>, then optional <params>",
        ),
        (
            b"<methodCall><methodName>a</methodName><methodName>b</methodName></methodCall>",
            "names more than one method",
        ),
        (b"<methodResponse><params></params></methodResponse>", "expected a <methodCall>"),
        (b"<methodCall><methodName>a<b/></methodName></methodCall>", "not allowed inside"),
    ],
)
def test_malformed_calls_are_refused(body: bytes, message: str) -> None:
    with pytest.raises(ProtocolError, match=message):
        decode_call(body)
