"""aidl_lang.records.dataclass against the standard library's dataclass: for generated class
shapes (fields with and without defaults and factories, a base class, eq / frozen / slots),
both make the same __init__, repr, equality, hashing, frozenness and slots."""
import dataclasses
import pickle

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from aidl_lang import records

_KINDS = st.sampled_from(["required", "default", "factory"])


def _make(dc, field_fn, name, spec, base=None, **opts):
    ns = {"__annotations__": {}}
    for fname, kind in spec:
        ns["__annotations__"][fname] = "int"
        if kind == "default":
            ns[fname] = 7
        elif kind == "factory":
            ns[fname] = field_fn(default_factory=list)
    cls = type(name, (base,) if base is not None else (), ns)
    cls.__qualname__ = name
    return dc(**opts)(cls)


@st.composite
def _shapes(draw):
    n_base = draw(st.integers(0, 3))
    n_own = draw(st.integers(0, 4))
    kinds = draw(st.lists(_KINDS, min_size=n_base + n_own, max_size=n_base + n_own))
    # required fields first (both implementations refuse a required field after a default)
    kinds.sort(key=lambda k: k != "required")
    names = [f"f{i}" for i in range(n_base + n_own)]
    spec = list(zip(names, kinds))
    opts = {"eq": draw(st.booleans()), "frozen": draw(st.booleans()), "slots": draw(st.booleans())}
    values = draw(st.lists(st.integers(-5, 5), min_size=len(spec), max_size=len(spec)))
    return spec[:n_base], spec[n_base:], opts, values


def _build(dc, field_fn, shape):
    base_spec, own_spec, opts, _ = shape
    base = _make(dc, field_fn, "Base", base_spec, eq=opts["eq"], frozen=opts["frozen"]) \
        if base_spec else None
    return _make(dc, field_fn, "Rec", own_spec, base, **opts)


@settings(max_examples=150, deadline=None)
@given(_shapes())
def test_records_behave_as_dataclasses(shape):
    base_spec, own_spec, opts, values = shape
    std = _build(dataclasses.dataclass, dataclasses.field, shape)
    ours = _build(records.dataclass, records.field, shape)
    spec = base_spec + own_spec
    required = [n for n, k in spec if k == "required"]
    kw = dict(zip(required, values))
    a_std, b_std = std(**kw), std(**kw)
    a, b = ours(**kw), ours(**kw)
    assert repr(a) == repr(a_std)
    assert (a == b) == (a_std == b_std)
    assert (a == a) and (a != object())
    assert records.fields(ours) == tuple(n for n, _ in spec)
    for n, k in spec:
        assert getattr(a, n) == getattr(a_std, n)
        if k == "factory":
            assert getattr(a, n) is not getattr(b, n)          # a new list each time
    assert (std.__hash__ is None) == (ours.__hash__ is None)
    if std.__hash__ is not None and opts["eq"] and all(k != "factory" for _, k in spec):
        assert (hash(a) == hash(b)) == (hash(a_std) == hash(b_std))
    assert ("__slots__" in std.__dict__) == ("__slots__" in ours.__dict__)
    if "__slots__" in std.__dict__:
        assert std.__slots__ == ours.__slots__
    if spec:
        n = spec[-1][0]
        if opts["frozen"]:
            with pytest.raises(dataclasses.FrozenInstanceError):
                setattr(a_std, n, 1)
            with pytest.raises(records.FrozenInstanceError):
                setattr(a, n, 1)
        else:
            setattr(a, n, 99)
            setattr(a_std, n, 99)
            assert getattr(a, n) == 99 and repr(a) == repr(a_std)
            assert (a == b) == (a_std == b_std)


def test_positional_and_keyword_arguments_and_pickling():
    @records.dataclass(frozen=True, slots=True)
    class P:
        x: float
        y: float = 0.0
    p = P(1.5, y=2.0)
    assert (p.x, p.y) == (1.5, 2.0) and repr(p) == "test_positional_and_keyword_arguments_" \
        "and_pickling.<locals>.P(x=1.5, y=2.0)"
    with pytest.raises(TypeError):
        P()                                   # x is required
    with pytest.raises(TypeError):
        P(1, 2, 3)


def test_recursive_repr_is_guarded():
    @records.dataclass(eq=False)
    class N:
        child: object = None
    n = N()
    n.child = n
    assert repr(n).endswith("N(child=...)")


def test_methods_written_in_the_class_body_are_kept():
    @records.dataclass
    class Q:
        x: int

        def __repr__(self):
            return "Q!"

        def __hash__(self):
            return 5
    assert repr(Q(1)) == "Q!" and hash(Q(2)) == 5 and Q(1) == Q(1)


# ------------------------------------------------------------------ the __init__ templates
def _call_outcomes(cls, spec, values):
    """What a set of calls gives: the fields' values, or the TypeError's text."""
    required = [n for n, k in spec if k == "required"]
    names = [n for n, _ in spec]
    calls = [((), dict(zip(required, values))),                      # by keyword
             (tuple(values[:len(required)]), {}),                    # by position
             (tuple(values), {}),                                    # every field by position
             (tuple(values) + (0,), {}),                             # one too many
             ((), {}),                                               # none
             ((), {**dict(zip(required, values)), "zz": 1}),         # an unknown keyword
             (tuple(values[:1]), dict(zip(names[:1], values[:1])))]  # one given twice
    out = []
    for args, kw in calls:
        try:
            obj = cls(*args, **kw)
            out.append(tuple(getattr(obj, n) for n in names))
        except TypeError as e:
            out.append(str(e).replace("Rec.__init__()", "__init__()"))
    return out


@settings(max_examples=150, deadline=None)
@given(_shapes())
def test_templates_equal_the_compiled_init(shape):
    """An __init__ made from a template takes and refuses the same calls, with the same
    messages, as the one compiled from source; same signature, same defaults."""
    import inspect
    base_spec, own_spec, opts, values = shape
    spec = base_spec + own_spec
    templated = _build(records.dataclass, records.field, shape)
    orig = records._from_template
    records._from_template = lambda *a: None
    try:
        compiled = _build(records.dataclass, records.field, shape)
    finally:
        records._from_template = orig
    assert templated.__init__.__code__ is not compiled.__init__.__code__
    if not (opts["frozen"] and any(k == "factory" for _, k in spec)):
        assert templated.__init__.__code__.co_firstlineno == 1 and \
            templated.__init__.__code__.co_filename == "<record Rec>"
        assert "a0" not in templated.__init__.__code__.co_varnames
    assert inspect.signature(templated.__init__) == inspect.signature(compiled.__init__)
    assert _call_outcomes(templated, spec, values) == _call_outcomes(compiled, spec, values)


def test_every_record_class_of_a_check_comes_from_a_template():
    """No record class of the compiler is compiled at import (a cold `aidl check` pays
    ~0.35 ms per compile): each one's __init__ is a renamed template."""
    import subprocess
    import sys
    code = ("import aidl_lang.records as R\n"
            "miss = []\n"
            "orig = R._from_template\n"
            "def f(q, *a):\n"
            "    r = orig(q, *a)\n"
            "    if r is None: miss.append(q)\n"
            "    return r\n"
            "R._from_template = f\n"
            "import aidl_lang.pipeline, aidl_lang.cli.main, aidl_lang.solver.diagnose\n"
            "print(miss)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_the_template_module_is_generated():
    from pathlib import Path
    text = (Path(records.__file__).parent / "record_inits.py").read_text()
    assert text == records.template_source(), \
        "regenerate: python -m aidl_lang.records > aidl_lang/record_inits.py"


def test_unusual_shapes_are_compiled():
    """Field names the templates use, more fields than the largest template, a required
    field after a default: compiled from source (the last one refused as before)."""
    ns = {"__annotations__": {f"f{i}": "int" for i in range(records.MAX_TEMPLATE_FIELDS + 1)}}
    big = records.dataclass(type("Big", (), ns))
    assert big.__init__.__code__.co_filename == "<record Big>"
    assert big(*range(records.MAX_TEMPLATE_FIELDS + 1)).f12 == 12

    @records.dataclass
    class Odd:
        _s0: int
        self_: int = 2
    assert (Odd(1)._s0, Odd(1).self_) == (1, 2)
    with pytest.raises(SyntaxError):
        records.dataclass(type("Bad", (), {"__annotations__": {"a": "int", "b": "int"},
                                           "a": 1}))
