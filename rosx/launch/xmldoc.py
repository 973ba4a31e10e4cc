"""Launch XML read into small elements that remember their line.

roslaunch reads files with ``xml.dom.minidom``, which forgets where a tag is; rosx needs the line
for its errors, so files are read with expat directly. What is kept is what roslaunch looks at:
each element's tag, attributes (in document order), element children, and its own text (text
and CDATA directly inside it, concatenated). Comments and processing instructions are dropped.

As roslaunch, the ``<launch>`` element is found anywhere in the document, and there must be
exactly one.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from xml.parsers import expat


@dataclass
class Element:
    """One XML element.

    Attributes:
        tag: The tag name as written.
        attrs: Attribute name -> value, in document order.
        line: The 1-based line of the start tag.
        children: The element children, in order.
        text: The text and CDATA directly inside, concatenated.
    """

    tag: str
    attrs: dict[str, str]
    line: int
    children: list[Element] = field(default_factory=list)
    text: str = ""


class XmlSyntaxError(ValueError):
    """The file is not XML, or has no single ``<launch>``; ``str()`` is roslaunch's wording."""

    def __init__(self, message: str, line: int = 0) -> None:
        super().__init__(message)
        self.line = line


def parse_launch(data: bytes) -> Element:
    """The ``<launch>`` element of a document.

    Raises:
        XmlSyntaxError: ``Invalid roslaunch XML syntax: …`` (expat's description of the first
            error, or ``no root <launch> tag`` when there is none or more than one).
    """
    stack: list[Element] = []
    launches: list[Element] = []
    parser = expat.ParserCreate()
    parser.buffer_text = True

    def start(tag: str, attrs: dict[str, str]) -> None:
        element = Element(tag, dict(attrs), parser.CurrentLineNumber)
        if stack:
            stack[-1].children.append(element)
        if tag == "launch":
            launches.append(element)
        stack.append(element)

    def end(_tag: str) -> None:
        stack.pop()

    def text(data: str) -> None:
        if stack:
            stack[-1].text += data

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = text
    try:
        parser.Parse(data, True)
    except expat.ExpatError as error:
        raise XmlSyntaxError(f"Invalid roslaunch XML syntax: {error}", error.lineno) from None
    if len(launches) != 1:
        line = launches[1].line if len(launches) > 1 else 0
        raise XmlSyntaxError("Invalid roslaunch XML syntax: no root <launch> tag", line)
    return launches[0]


__all__ = ["Element", "XmlSyntaxError", "parse_launch"]
