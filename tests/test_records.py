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
