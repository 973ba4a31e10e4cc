"""The scope a launch tag is read in: namespace, remaps, private params, env, args.

Mirrors roslaunch's ``LoaderContext`` rules, which decide what a user observes:

* a child scope (``<group>``, ``<node>``, ``<include>``) gets its own namespace (a global
  ``ns`` replaces, a relative one joins), a copy of the ``<env>`` settings, a copy of the args
  and anon ids, and sees its parent's ``<remap>``s unless it remaps the same ``from`` itself;
* the ``~private`` params declared in a scope apply to every node declared after them in that
  scope and its children; the list is *shared* with the child scope when it is not empty at
  the time the child is made (so a ``~param`` inside an ``<include>`` reaches the nodes of the
  including file that follow), while ``<group>`` and ``<node>`` take copies;
* across an ``<include>``, the included file sees only the args the ``<include>`` passes
  (``<arg>`` children, or all of the includer's with ``pass_all_args``), and every passed arg
  must be declared by the included file.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rosx.launch.substitution import Scope
from rosx.names.resolution import canonicalize, make_global_ns, ns_join
from rosx.names.validation import is_legal_name

if TYPE_CHECKING:
    from rosx.launch.model import Source


class ContextError(ValueError):
    """A scope rule is broken; ``str()`` is roslaunch's text."""


@dataclass(frozen=True)
class LocalParam:
    """A ``~param`` (or a ``<param>`` inside a ``<node>``) waiting for the nodes it applies to."""

    key: str
    value: Any
    source: Source


class LoadContext:
    """One scope of a launch file (roslaunch's ``LoaderContext``)."""

    def __init__(
        self,
        ns: str,
        filename: str,
        *,
        parent: LoadContext | None = None,
        params: list[LocalParam] | None = None,
        env: list[tuple[str, str]] | None = None,
        subst: Scope | None = None,
        arg_names: list[str] | None = None,
        include_subst: Scope | None = None,
    ) -> None:
        self.parent = parent
        self.ns = make_global_ns(ns or "/")
        self.filename = filename
        self.remaps: list[tuple[str, str]] = []
        # An empty list is not shared: roslaunch tests the list for truth.
        self.params: list[LocalParam] = params if params else []
        self.env: list[tuple[str, str]] = env or []
        self.subst = subst or Scope()
        self.arg_names: list[str] = arg_names or []
        self.include_subst = include_subst
        self.args_passed: list[str] = []
        self.pass_all_args = False

    def child(self, ns: str | None) -> LoadContext:
        """The scope of a tag inside this one, in namespace ``ns`` (None or "": the same)."""
        if ns:
            child_ns = ns if ns.startswith("/") else "~" if ns == "~" else ns_join(self.ns, ns)
        else:
            child_ns = self.ns
        return LoadContext(
            child_ns,
            self.filename,
            parent=self,
            params=self.params,
            env=list(self.env),
            subst=self.subst.copy(),
            arg_names=list(self.arg_names),
            include_subst=self.include_subst,
        )

    def include_child(self, ns: str | None, filename: str) -> LoadContext:
        """The scope of an ``<include>``d file, before its args are passed."""
        context = self.child(ns)
        context.arg_names = []
        context.filename = filename
        context.include_subst = Scope()
        return context

    def add_param(self, param: LocalParam) -> None:
        """Declare a ``~param``: it replaces one of the same key."""
        self.params[:] = [p for p in self.params if p.key != param.key]
        self.params.append(param)

    def add_remap(self, source: str, target: str) -> None:
        """Declare a ``<remap>``; one with the same ``from`` is replaced."""
        source, target = canonicalize(source), canonicalize(target)
        if not source or not target:
            raise ContextError("remap from/to attributes cannot be empty")
        if not is_legal_name(source):
            raise ContextError(f"remap from [{source}] is not a valid ROS name")
        if not is_legal_name(target):
            raise ContextError(f"remap to [{target}] is not a valid ROS name")
        self.remaps = [r for r in self.remaps if r[0] != source]
        self.remaps.append((source, target))

    def remap_args(self) -> list[tuple[str, str]]:
        """The remaps in force: the parents' not overridden here, then this scope's."""
        if self.parent is None:
            return list(self.remaps)
        mine = {r[0] for r in self.remaps}
        return [r for r in self.parent.remap_args() if r[0] not in mine] + self.remaps

    def add_arg(
        self,
        name: str,
        *,
        default: str | None = None,
        value: str | None = None,
        doc: str | None = None,
    ) -> None:
        """Declare an ``<arg>`` (with a fixed ``value``, a ``default``, or neither)."""
        if name in self.arg_names:
            if not self.pass_all_args:
                raise ContextError(f"arg '{name}' has already been declared")
        else:
            self.arg_names.append(name)
        scope = self.subst if self.include_subst is None else self.include_subst
        if value is not None:
            if name in scope.args and not self.pass_all_args:
                raise ContextError(f"cannot override arg '{name}', which has already been set")
            scope.args[name] = value
        elif default is not None:
            scope.args.setdefault(name, default)
        if not value:
            scope.arg_doc[name] = (doc, default)

    def start_include(self) -> None:
        """Hand the args passed by an ``<include>`` to the included file."""
        assert self.include_subst is not None
        for name in self.arg_names:
            if name not in self.include_subst.args:
                raise ContextError("include args must have declared values")
        self.args_passed = list(self.include_subst.args)
        self.arg_names = []
        self.subst = self.include_subst
        self.include_subst = None

    def unused_args(self) -> list[str]:
        """Args an ``<include>`` passed that the included file does not declare."""
        return [name for name in self.args_passed if name not in self.arg_names]


__all__ = ["ContextError", "LoadContext", "LocalParam"]
