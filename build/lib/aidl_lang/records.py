"""``@dataclass`` for the compiler's own record types, made for cold start.

The standard library's ``dataclasses.dataclass`` costs about 0.4-0.8 ms per class (several
``exec`` calls, ``inspect.signature`` for a docstring, ABC bookkeeping) and importing
``dataclasses`` pulls in ``inspect``; the ~75 record classes a cold ``aidl check`` defines cost
30-60 ms of its 0.2 s target (issue 12, measured by wrapping ``dataclasses.dataclass``).
:func:`dataclass` here makes the same methods without compiling anything for the usual
shapes: the ``__init__`` is a template from :mod:`aidl_lang.record_inits` (bytecode loaded
from its ``.pyc``) with its parameter and attribute names replaced by the fields'
(``CodeType.replace``), the same bytecode ``compile`` would give for that source; the other
methods are closures over the field names.  ``compile`` took ~0.35 ms per class (the ~69
record classes of a cold ``aidl check``: ~25 M instructions, 4% of it); a shape with no
template (more than :data:`MAX_TEMPLATE_FIELDS` fields, a frozen record with a factory, a
field name the templates use) is compiled as before.

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

import keyword
import operator
import threading
import types

from . import record_inits

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
    init = _from_template(cls.__qualname__, names, frozen, slots, ns)
    if init is None:
        init = _compiled_init(cls.__qualname__, names, frozen, slots, ns)

    # The methods go into the class: a slotted record is made anew with them in its namespace
    # (one class creation, no attribute assignments on the class, each of which re-derives
    # the type's slots), any other record gets them assigned.
    # Only __init__ is made from code (it is the hot one); the other methods are closures over
    # the field tuple, the same for every class (compiling them was half of a record's cost).
    methods, bind = _methods(field_names, eq, frozen)
    explicit_hash = cls.__dict__.get("__hash__", None) is not None
    methods["__init__"] = init
    qualname = cls.__qualname__
    extra: dict = {}
    for fn, f in methods.items():
        if fn in ("__init__", "__eq__", "__repr__") and fn in cls.__dict__:
            continue                           # written in the class body: kept
        if fn == "__hash__" and explicit_hash:
            continue
        f.__qualname__ = f"{qualname}.{fn}"
        extra[fn] = f
    if eq and not frozen and not explicit_hash:
        extra["__hash__"] = None
    extra["__record_fields__"] = field_names
    extra["__record_defaults__"] = {n: d for n, d in names.items() if d is not _MISSING}
    extra["__match_args__"] = field_names
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
        cls_dict.update(extra)
        if frozen:
            cls_dict["__getstate__"] = _frozen_getstate
            cls_dict["__setstate__"] = _frozen_setstate
        cls_dict["__qualname__"] = qualname
        cls = type(cls)(cls.__name__, cls.__bases__, cls_dict)
        if frozen:
            for i, n in enumerate(field_names):     # a frozen record's __init__ sets its slots
                ns[f"_s_{n}"] = ns[f"_s{i}"] = _slot_setter(cls, n)
    else:
        for k, v in extra.items():
            setattr(cls, k, v)
        for n, d in names.items():             # class attributes keep plain defaults only
            if isinstance(d, _Factory) and n in cls.__dict__:
                delattr(cls, n)
    bind(cls)
    return cls


def _compiled_init(qualname: str, names: dict, frozen: bool, slots: bool, ns: dict):
    """The ``__init__`` of a record with fields ``names`` (field -> default), compiled from
    source in ``ns`` (for the shapes :func:`_from_template` has no template for)."""
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
        if frozen and slots:                   # the slot's own setter (bound by _process)
            body.append(f"  _s_{name}(self, {value})")
        elif frozen:
            body.append(f"  _setattr(self, {name!r}, {value})")
        else:
            body.append(f"  self.{name} = {value}")
    src = [f"def __init__(self, {', '.join(params)}):"] + (body or ["  pass"])
    exec(compile("\n".join(src), f"<record {qualname}>", "exec"), ns)
    return ns["__init__"]


MAX_TEMPLATE_FIELDS = 12
# The template families (record_inits.py): how a field is set, with or without factories.
_FAMILIES = {
    "attr": "self.{a} = {v}",                  # not frozen: a plain attribute store
    "slot": "_s{i}(self, {v})",                # frozen and slotted: the slot's own setter
    "setattr": "_setattr(self, _n{i}, {v})",   # frozen, no slots: object.__setattr__
}


def _template_name(family: str, n: int, factory: bool) -> str:
    return f"{family}{n}" + ("_factory" if factory else "")


def template_source() -> str:
    """The text of :mod:`aidl_lang.record_inits` (``python -m aidl_lang.records`` prints it;
    a test checks that the file is this text)."""
    out = ['"""The ``__init__`` templates of :mod:`aidl_lang.records` (generated by',
           '``python -m aidl_lang.records > aidl_lang/record_inits.py``; do not edit).',
           "",
           "Field ``i`` is ``a{i}``; ``records`` renames the parameters and attributes to the",
           'fields\' names.  Never called as they are."""',
           "# flake8: noqa", ""]
    for family, store in _FAMILIES.items():
        for factory in (False, True):
            if factory and family != "attr":
                continue
            for n in range(MAX_TEMPLATE_FIELDS + 1):
                args = "".join(f", a{i}" for i in range(n))
                out.append(f"def {_template_name(family, n, factory)}(self{args}):")
                for i in range(n):
                    v = f"_f{i}() if a{i} is _MISSING else a{i}" if factory else f"a{i}"
                    out.append("    " + store.format(a=f"a{i}", i=i, v=v))
                if not n:
                    out.append("    pass")
                out.append("")
    return "\n".join(out)


_TEMPLATE_NAMES = frozenset({"self", "_MISSING", "_setattr"})


def _from_template(qualname: str, names: dict, frozen: bool, slots: bool, ns: dict):
    """The ``__init__`` of a record with fields ``names`` (field -> default) made from a
    template, or None when there is none for this shape (it is then compiled).  The function
    has the compiled one's parameters, defaults, bytecode and globals ``ns`` (factories as
    ``_f{i}``, slot setters as ``_s{i}``, field names as ``_n{i}``)."""
    fields_ = list(names)
    n = len(fields_)
    factory = any(isinstance(d, _Factory) for d in names.values())
    family = "slot" if frozen and slots else "setattr" if frozen else "attr"
    if n > MAX_TEMPLATE_FIELDS or (factory and family != "attr"):
        return None
    defaults, seen_default = [], False
    for f, d in names.items():
        if (not isinstance(f, str) or not f.isidentifier() or keyword.iskeyword(f)
                or f in _TEMPLATE_NAMES or f.startswith(("_f", "_s", "_n", "_d"))):
            return None                        # compile says what is wrong with it, if anything
        if d is _MISSING:
            if seen_default:
                return None                    # a required field after a default: ditto
        else:
            seen_default = True
            defaults.append(_MISSING if isinstance(d, _Factory) else d)
    template = getattr(record_inits, _template_name(family, n, factory)).__code__
    rename = {f"a{i}": f for i, f in enumerate(fields_)}
    for i, (f, d) in enumerate(names.items()):
        if isinstance(d, _Factory):
            ns[f"_f{i}"] = d.factory
        ns[f"_n{i}"] = f
    code = template.replace(
        co_varnames=tuple(rename.get(v, v) for v in template.co_varnames),
        co_names=tuple(rename.get(v, v) for v in template.co_names),
        co_filename=f"<record {qualname}>", co_name="__init__",
        co_qualname=f"{qualname}.__init__", co_firstlineno=1)
    return types.FunctionType(code, ns, "__init__", tuple(defaults) or None)


def _methods(field_names: tuple, eq: bool, frozen: bool) -> tuple[dict, object]:
    """``__repr__`` and, per the options, ``__eq__``, ``__hash__``, ``__setattr__`` and
    ``__delattr__`` of a record class, with the standard library's meaning; and ``bind``, to
    be called with the class once it is made (the frozen methods refer to it)."""
    cls = None

    def bind(c) -> None:
        nonlocal cls
        cls = c
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
    return out, bind


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


if __name__ == "__main__":
    print(template_source(), end="")
