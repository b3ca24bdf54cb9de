"""The bases of the plain records: value types written as classes with ``__slots__`` (a
tuple of their fields, in order) and an explicit ``__init__``, as the AST nodes are
(:mod:`aidl_lang.ast`).

They were dataclasses.  ``dataclass`` writes each record's methods as source text and runs
it through Python's parser and compiler when the module is imported
(``dataclasses._create_fn``, one ``exec`` per method on Python 3.11): 106 M instructions for
the 176 methods of the 55 records on the path of ``aidl check``, 12% of a cold check
(``benchmarks/compile/record_methods.py``; docs/dev/performance.md, "Dense drawings (issue 58)").
Written in their modules, the methods are in the ``.pyc``.  The fields are slots; every
record also keeps a ``__dict__``, as the dataclasses had, for what is set besides the fields
(an arc's ends and a part's mesh, kept once computed; the interpreter's marks on a
structure).  What the dataclass added beyond
``__init__`` comes from these bases, read from the class's slots (its bases' first; a
slot whose name starts with ``_``, ``__dict__`` among them, is not a field):

* :class:`Record` (a dataclass with ``eq=False``): ``__repr__`` as a dataclass's,
  ``Line(start=(0.0, 0.0), end=(1.0, 0.0))`` (``...`` for a record inside itself); compared
  by identity.
* :class:`Compared` (``eq=True``): also ``__eq__``, field by field as one tuple, between
  records of the same class only (``NotImplemented`` otherwise); unhashable, as a dataclass.
* :class:`Frozen` (``frozen=True``): also ``__hash__`` (of the fields' tuple), and setting or
  deleting a field raises :class:`dataclasses.FrozenInstanceError`; its ``__init__`` sets
  the fields with ``object.__setattr__``, as the dataclass's did, and ``copy`` and
  ``pickle`` call the class again with the fields in order.
"""
from __future__ import annotations

from dataclasses import FrozenInstanceError
from reprlib import recursive_repr


class Record:
    """Base of a record compared by identity: ``__repr__`` of its fields."""
    __slots__ = ("__dict__",)
    _fields: tuple[str, ...] = ()

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        cls._fields = cls._fields + tuple(n for n in cls.__dict__.get("__slots__", ())
                                          if n[0] != "_")

    @recursive_repr()
    def __repr__(self) -> str:
        """``Name(field=value, ...)``, the fields in order, as a dataclass's."""
        return (f"{type(self).__qualname__}("
                f"{', '.join(f'{n}={getattr(self, n)!r}' for n in self._fields)})")


class Compared(Record):
    """Base of a record equal to another of its class with equal fields (unhashable)."""
    __slots__ = ()

    def __eq__(self, other):
        if other.__class__ is self.__class__:
            return (tuple(getattr(self, n) for n in self._fields)
                    == tuple(getattr(other, n) for n in self._fields))
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]


class Frozen(Compared):
    """Base of an immutable record: equal by fields, hashable, its fields read-only."""
    __slots__ = ()

    def __hash__(self) -> int:
        return hash(tuple(getattr(self, n) for n in self._fields))

    def __setattr__(self, name, value):
        raise FrozenInstanceError(f"cannot assign to field {name!r}")

    def __delattr__(self, name):
        raise FrozenInstanceError(f"cannot delete field {name!r}")

    def __reduce__(self):
        """Copied and pickled as a call of the class with the fields in order (its
        ``__init__``'s arguments), since the fields cannot be set afterwards."""
        return type(self), tuple(getattr(self, n) for n in self._fields)


class kept:
    """A property computed on first read and kept in the instance's ``__dict__`` (later reads
    find it there, past this descriptor), as :func:`functools.cached_property` does but
    without its lock (Python 3.11 takes an ``RLock`` on every first read: a planetary gear's
    preview reads some 10,000 arcs' ends first, 3.3 µs each against 1.4 µs; issue 113).  For
    records that are never shared between threads while being built."""
    def __init__(self, func):
        self.func = func
        self.name = func.__name__
        self.__doc__ = func.__doc__

    def __set_name__(self, owner, name):
        self.name = name

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        value = obj.__dict__[self.name] = self.func(obj)
        return value
