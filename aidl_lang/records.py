"""``@dataclass`` for the compiler's own record types, made for cold start.

The standard library's ``dataclasses.dataclass`` costs about 0.4-0.8 ms per class (several
``exec`` calls, ``inspect.signature`` for a docstring, ABC bookkeeping) and importing
``dataclasses`` pulls in ``inspect``; the ~75 record classes a cold ``aidl check`` defines cost
30-60 ms of its 0.2 s target (issue 12, measured by wrapping ``dataclasses.dataclass``).
:func:`dataclass` here makes the same methods with one small ``compile`` per class (the
``__init__``; the other methods are closures over the field names).

Supported, with the standard library's meaning: fields from the class's own annotations after
those of record base classes (a redeclared field keeps its place), class-attribute defaults,
``field(default_factory=...)``, and the options ``eq`` (``__eq__`` on the field tuple; an
``eq`` class that is not frozen is unhashable unless it defines ``__hash__``), ``frozen``
(assignment raises :class:`FrozenInstanceError`; ``__hash__`` on the field tuple) and ``slots``
(a new class with ``__slots__``).  ``__repr__`` is ``Name(field=value, ...)`` with the same
guard against recursion.  Not supported (not used here): ``InitVar``, ``ClassVar``,
``__post_init__``, ``kw_only``, ``order``, per-field options other than ``default_factory``,
and ``dataclasses.fields()`` on these classes (use :func:`fields`).
"""
from __future__ import annotations

import operator
import threading

__all__ = ["dataclass", "field", "fields", "FrozenInstanceError"]


class FrozenInstanceError(AttributeError):
    """Assignment to a field of a frozen record."""


class _Factory:
    __slots__ = ("factory",)

    def __init__(self, factory):
        self.factory = factory


def field(*, default_factory):
    """A field whose default is made by calling ``default_factory()`` for each instance."""
    return _Factory(default_factory)


def fields(cls) -> tuple:
    """The field names of a record class (or instance), in ``__init__`` order."""
    return cls.__record_fields__


_MISSING = object()
_repr_running = threading.local()


def _guard(repr_fn):
    """``reprlib.recursive_repr`` as ``dataclasses`` applies it: ``...`` for a record already
    being shown on this thread."""
    def __repr__(self):
        running = getattr(_repr_running, "ids", None)
        if running is None:
            running = _repr_running.ids = set()
        key = id(self)
        if key in running:
            return "..."
        running.add(key)
        try:
            return repr_fn(self)
        finally:
            running.discard(key)
    return __repr__


def dataclass(cls=None, /, *, eq: bool = True, frozen: bool = False, slots: bool = False):
    """Make ``cls`` a record class: ``__init__``, ``__repr__`` and, per the options, ``__eq__``,
    ``__hash__``, ``__setattr__`` / ``__delattr__`` and ``__slots__`` (see the module text)."""
    def wrap(c):
        return _process(c, eq, frozen, slots)
    return wrap if cls is None else wrap(cls)


def _process(cls, eq: bool, frozen: bool, slots: bool):
    names: dict[str, object] = {}          # field -> default (_MISSING, a value or a _Factory)
    for base in reversed(cls.__mro__[1:]):
        for name in base.__dict__.get("__record_fields__", ()):
            names[name] = base.__record_defaults__.get(name, _MISSING)
    own = cls.__dict__.get("__annotations__", {})
    for name in own:
        names[name] = cls.__dict__.get(name, _MISSING)
    field_names = tuple(names)
    ns: dict = {"_MISSING": _MISSING, "_setattr": object.__setattr__}
    params, body = [], []
    for name, default in names.items():
        if default is _MISSING:
            params.append(name)
            value = name
        elif isinstance(default, _Factory):
            ns[f"_f_{name}"] = default.factory
            params.append(f"{name}=_MISSING")
            value = f"_f_{name}() if {name} is _MISSING else {name}"
        else:
            ns[f"_d_{name}"] = default
            params.append(f"{name}=_d_{name}")
            value = name
        if frozen and slots:                   # the slot's own setter (bound below)
            body.append(f"  _s_{name}(self, {value})")
        elif frozen:
            body.append(f"  _setattr(self, {name!r}, {value})")
        else:
            body.append(f"  self.{name} = {value}")
    src = [f"def __init__(self, {', '.join(params)}):"] + (body or ["  pass"])
    exec(compile("\n".join(src), f"<record {cls.__qualname__}>", "exec"), ns)

    if slots:
        cls_dict = dict(cls.__dict__)
        inherited = set()
        for base in cls.__mro__[1:-1]:
            inherited.update(base.__dict__.get("__slots__", ()))
        cls_dict["__slots__"] = tuple(n for n in field_names if n not in inherited)
        for n in field_names:
            cls_dict.pop(n, None)
        cls_dict.pop("__dict__", None)
        cls_dict.pop("__weakref__", None)
        qualname = cls.__qualname__
        cls = type(cls)(cls.__name__, cls.__bases__, cls_dict)
        cls.__qualname__ = qualname
        if frozen:
            cls.__getstate__ = _frozen_getstate
            cls.__setstate__ = _frozen_setstate
            for n in field_names:              # a frozen record's __init__ sets its slots
                ns[f"_s_{n}"] = _slot_setter(cls, n)
    cls.__record_fields__ = field_names
    cls.__record_defaults__ = {n: d for n, d in names.items() if d is not _MISSING}
    cls.__match_args__ = field_names
    # Only __init__ is compiled (it is the hot one); the other methods are closures over the
    # field tuple, the same for every class (compiling them was half of a record's cost).
    methods = _methods(cls, field_names, eq, frozen)
    explicit_hash = cls.__dict__.get("__hash__", None) is not None
    methods["__init__"] = ns["__init__"]
    for fn, f in methods.items():
        if fn in ("__init__", "__eq__", "__repr__") and fn in cls.__dict__:
            continue                           # written in the class body: kept
        if fn == "__hash__" and explicit_hash:
            continue
        f.__qualname__ = f"{cls.__qualname__}.{fn}"
        setattr(cls, fn, f)
    if eq and not frozen and not explicit_hash:
        cls.__hash__ = None
    for n, d in names.items():                 # class attributes keep plain defaults only
        if isinstance(d, _Factory) and n in cls.__dict__ and not slots:
            delattr(cls, n)
    return cls


def _methods(cls, field_names: tuple, eq: bool, frozen: bool) -> dict:
    """``__repr__`` and, per the options, ``__eq__``, ``__hash__``, ``__setattr__`` and
    ``__delattr__`` of a record class, with the standard library's meaning."""
    if len(field_names) > 1:
        key = operator.attrgetter(*field_names)           # the field tuple
    elif field_names:
        one = operator.attrgetter(field_names[0])

        def key(obj):
            return (one(obj),)
    else:
        def key(obj):
            return ()
    getters = [(n, operator.attrgetter(n)) for n in field_names]

    def __repr__(self):
        inner = ", ".join(f"{n}={g(self)!r}" for n, g in getters)
        return f"{self.__class__.__qualname__}({inner})"
    out = {"__repr__": _guard(__repr__)}
    if eq:
        def __eq__(self, other):
            if other.__class__ is self.__class__:
                return key(self) == key(other)
            return NotImplemented
        out["__eq__"] = __eq__
    if frozen:
        names = frozenset(field_names)

        def __setattr__(self, name, value):
            if type(self) is cls or name in names:
                raise FrozenInstanceError(f"cannot assign to field {name!r}")
            super(cls, self).__setattr__(name, value)

        def __delattr__(self, name):
            if type(self) is cls or name in names:
                raise FrozenInstanceError(f"cannot delete field {name!r}")
            super(cls, self).__delattr__(name)
        out["__setattr__"], out["__delattr__"] = __setattr__, __delattr__
        if eq:
            def __hash__(self):
                return hash(key(self))
            out["__hash__"] = __hash__
    return out


def _slot_setter(cls, name: str):
    """The ``__set__`` of the slot descriptor for ``name`` (on ``cls`` or a base): setting it
    skips the frozen ``__setattr__`` (twice as fast as ``object.__setattr__``)."""
    for c in cls.__mro__:
        d = c.__dict__.get(name)
        if d is not None and hasattr(d, "__set__"):
            return d.__set__
    return lambda self, value, _n=name: object.__setattr__(self, _n, value)


def _frozen_getstate(self):
    return [getattr(self, n) for n in self.__record_fields__]


def _frozen_setstate(self, state):
    for n, v in zip(self.__record_fields__, state):
        object.__setattr__(self, n, v)
