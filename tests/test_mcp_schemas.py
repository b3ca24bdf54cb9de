"""The input schemas `tools/list` sends are made short (issue 86: `tools/list` 13,663 tokens
-> about 3,400) without changing what they accept: :func:`aidl_lang.mcp.server.slim` takes
out titles, `default: null` and `anyOf [X, null]`; a hypothesis law checks, for the schema of
every argument type the tools use, that the full and the slim schema accept the same JSON
values.  And the output schemas' outline (:func:`~aidl_lang.mcp.server.outline_schema`)
accepts every result the full schema accepts (real results: tests/test_mcp_agents.py)."""
import json

import pytest

pytest.importorskip("mcp")
jsonschema = pytest.importorskip("jsonschema")
from hypothesis import given, settings, strategies as st  # noqa: E402
from pydantic import TypeAdapter  # noqa: E402

from aidl_lang.mcp import server as S  # noqa: E402
from aidl_lang.mcp import schemas  # noqa: E402

ARGUMENTS = [v for k, v in vars(S).items() if k[:1].isupper() and hasattr(v, "__metadata__")]
FULL = [TypeAdapter(a).json_schema() for a in ARGUMENTS]

JSON = st.recursive(
    st.none() | st.booleans() | st.integers(-10, 10_000) | st.sampled_from([0, 0.5, 4.0, 4.5])
    | st.floats(allow_nan=False, allow_infinity=False) | st.text(max_size=5)
    | st.sampled_from(["sheet", "preview", "laser", "mm", "in", "x" * 41, "y" * 101]),
    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=3), inner,
                                                                max_size=3),
    max_leaves=6)


def _ok(schema: dict, value) -> bool:
    return jsonschema.Draft202012Validator(schema).is_valid(value)


def test_every_argument_type_is_seen_and_made_shorter():
    assert len(ARGUMENTS) >= 30
    slim = [S.slim(f) for f in FULL]
    assert all("title" not in json.dumps(s) for s in slim)
    assert all('{"type": "null"}' not in json.dumps(s) and '"default": null' not in
               json.dumps(s) for s in slim)
    assert all(len(json.dumps(s)) <= len(json.dumps(f)) for s, f in zip(slim, FULL))


@settings(max_examples=150, deadline=None)
@given(k=st.integers(0, len(FULL) - 1), value=JSON)
def test_the_slim_schema_accepts_what_the_full_one_does(k, value):
    full = FULL[k]
    assert _ok(S.slim(full), value) == _ok(full, value), (full, value)


def test_an_optional_argument_still_accepts_null():
    source = S.slim(TypeAdapter(S.Source).json_schema())
    assert source["type"] == ["string", "null"] and _ok(source, None)
    layout = S.slim(TypeAdapter(S.LayoutKind).json_schema())
    assert layout["enum"] == ["sheet", None] and not _ok(layout, "sheets")


@settings(max_examples=60, deadline=None)
@given(ok=st.booleans(), extra=st.dictionaries(st.sampled_from(
    ["size", "parts", "written", "job", "fit", "image", "layout", "other"]), JSON, max_size=4))
def test_the_outline_accepts_what_the_full_output_schema_accepts(ok, extra):
    full = TypeAdapter(schemas.RenderResult).json_schema()
    outline = S.outline_schema(full, "aidl://schemas/render.json")
    doc = {"ok": ok, "units": "mm", **extra}
    if _ok(full, doc):
        assert _ok(outline, doc)
    assert outline["properties"]["job"]["description"].startswith("{path_mm, passes, cut_mm")
