"""The value records written as plain classes (aidl_lang/base/records.py) behave as the dataclasses
they replaced: the same ``repr``, equality, hashing and immutability; and the modules of
``aidl check`` no longer have ``dataclasses`` compile methods at import (issue 58's cold start)."""
import copy
import dataclasses
import math
import pickle
import subprocess
import sys

import pytest

from aidl_lang.base.diagnostics import Diagnostic, Label, Span
from aidl_lang.geometry.shapes.curves import Arc, Circle, Line, Loop
from aidl_lang.base.limits import Budget
from aidl_lang.base.records import Compared, Frozen, Record


def _twin(cls, **options):
    """The dataclass ``cls`` was: the same fields and defaults, made by ``dataclasses``."""
    made = dataclasses.make_dataclass(cls.__name__, cls._fields, **options)
    made.__qualname__ = cls.__qualname__
    return made


@pytest.mark.parametrize("cls, args, options", [
    (Line, ((0.0, 1.5), (2.0, -1.0)), {"frozen": True}),
    (Arc, ((1.0, 2.0), 3.0, 0.25, -math.pi), {"frozen": True}),
    (Circle, ((0.0, 0.0), 2.5, False), {"frozen": True}),
    (Loop, ([Line((0.0, 0.0), (1.0, 0.0))],), {}),
    (Label, (Span("a.aidl", 1, 2, 1, 5), "here", False), {}),
])
def test_repr_equality_and_hash_as_the_dataclass(cls, args, options):
    twin = _twin(cls, **options)
    a, b, t = cls(*args), cls(*args), twin(*args)
    assert repr(a) == repr(t)
    assert a == b and not (a != b) and a is not b
    assert (a == t) is False                      # another class: never equal, as before
    if options.get("frozen"):
        assert hash(a) == hash(b) == hash(t)
        with pytest.raises(dataclasses.FrozenInstanceError):
            a.__setattr__(cls._fields[0], None)
        with pytest.raises(dataclasses.FrozenInstanceError):
            delattr(a, cls._fields[0])
    else:
        with pytest.raises(TypeError):            # eq=True without frozen: unhashable
            hash(a)


def test_defaults_fields_and_copies():
    d = Diagnostic("E0101", "unknown name `w`")
    assert d.span is None and d.severity == "error" and d.labels == [] and d.fix is None
    assert Diagnostic("E0101", "x").labels is not d.labels        # a fresh list each
    assert Diagnostic._fields == ("code", "message", "span", "severity", "hint", "labels",
                                  "suggestions", "fix")
    assert Budget().scaled(2).seconds == 30.0 and Budget() == Budget()
    assert Budget(steps=5) != Budget()
    c = Circle((1.0, 2.0), 3.0)
    assert c.ccw is True and c == pickle.loads(pickle.dumps(c))
    arc = Arc((0.0, 0.0), 2.0, 0.0, math.pi / 2)
    assert arc.end == pytest.approx((0.0, 2.0)) and arc.end is arc.end   # kept, as before
    assert arc == Arc((0.0, 0.0), 2.0, 0.0, math.pi / 2)
    assert copy.deepcopy(arc) == arc == pickle.loads(pickle.dumps(arc))
    assert pickle.loads(pickle.dumps(d)) == d and copy.copy(d) == d


def test_bases():
    class R(Record):
        __slots__ = ("a", "_hidden")

        def __init__(self, a):
            self.a = a
            self._hidden = 1

    class C(Compared):
        __slots__ = ("a",)

        def __init__(self, a):
            self.a = a

    r = R(1)
    r.a = r                                           # a record inside itself
    assert repr(r) == "test_bases.<locals>.R(a=...)" and R._fields == ("a",)
    assert r != R(1) and C(1) == C(1) and C(1) != C(2)
    assert C(1).__eq__(1) is NotImplemented
    assert issubclass(Frozen, Compared) and Frozen.__hash__ is not None


def test_check_imports_compile_no_record_methods():
    """``aidl check``'s imports: what ``dataclasses`` still compiles is the public API's two
    frozen records and the writers' ``Format`` (``dataclasses.replace`` is used on it), 18
    methods; the 55 records of before had 176 (106 M instructions of a cold check)."""
    code = """
import collections, dataclasses
made = dataclasses._create_fn
count = collections.Counter()
def spy(name, *a, **k):
    f = __import__("sys")._getframe(1)
    while f.f_code.co_name != "_process_class":
        f = f.f_back
    count[f.f_locals["cls"].__qualname__] += 1
    return made(name, *a, **k)
dataclasses._create_fn = spy
import aidl_lang.cli.main, aidl_lang.api, aidl_lang.pipeline, aidl_lang.solver.diagnosis.diagnose
import aidl_lang.solver.diagnosis.freedom, aidl_lang.solver.diagnosis.redundancy, aidl_lang.solver.diagnosis.sliding
import aidl_lang.output.checks
print(sorted(count.items()))
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, timeout=60).stdout
    assert out.strip() == "[('Format', 6), ('PartInfo', 6), ('Value', 6)]"
