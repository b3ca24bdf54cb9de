"""Highlighters: the TextMate grammar is generated from the registry (drift test), the Pygments
lexer reads the registry and lexes every example without Error tokens."""
import subprocess
import sys

import pytest
from pygments.lexers import get_lexer_by_name
from pygments.token import Comment, Error, Keyword, Name, Number, Operator, String

from aidl_lang import registry as R
from aidl_lang.editor.highlight import grammar_keywords, tmlanguage_json, vocabulary

from conftest import EXAMPLES, ROOT

TM = ROOT / "editors" / "vscode" / "syntaxes" / "aidl.tmLanguage.json"
ALL = EXAMPLES + sorted((ROOT / "examples" / "parts").glob("*.aidl")) + sorted(
    (ROOT / "stdlib").glob("*.aidl"))


def test_committed_textmate_grammar_is_fresh():
    assert TM.read_text(encoding="utf-8") == tmlanguage_json(), \
        "run `python editors/gen_grammar.py` and commit the result"
    r = subprocess.run([sys.executable, str(ROOT / "editors" / "gen_grammar.py"), "--check"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout


def test_vocabulary_covers_the_registry_and_grammar():
    v = vocabulary()
    words = {w for ws in v.values() for w in ws}
    assert set(R.ENTRIES) | set(R.SYNONYMS) | set(R.FUNCTIONS) | set(R.CONSTANTS) <= words
    assert set(grammar_keywords()) | set(R.KEYWORDS) <= words
    assert set(R.UNITS_LENGTH) | set(R.UNITS_ANGLE) <= set(v["units"])
    assert {"param", "def", "for", "in", "if", "else", "elif", "and", "or", "not",
            "import", "as"} <= set(grammar_keywords())
    assert "units" in R.KEYWORDS        # (a NAME the post-lexer retypes, as thickness)
    grammar = TM.read_text()
    for name in list(R.ENTRIES) + list(R.SYNONYMS):
        assert name in grammar


@pytest.fixture(scope="module")
def lexer():
    return get_lexer_by_name("aidl-cad")           # through the entry point


@pytest.mark.parametrize("path", ALL, ids=lambda p: p.name)
def test_pygments_lexes_examples_without_errors(lexer, path):
    src = path.read_text()
    toks = list(lexer.get_tokens(src))
    assert [(t, v) for t, v in toks if t in Error] == []
    assert "".join(v for _, v in toks) == (src if src.endswith("\n") else src + "\n")


def test_pygments_token_kinds(lexer):
    src = ('// header\nparam w = 10 mm  # width\nsolid plate {\n    c = Circle(center=(0, 0), '
           'radius=w // 2)\n    Coincident(c.center, self.bb.center)\n    t = f"{w:.1f} mm"\n'
           '    q = 3 // half of it\n}\n')
    toks = [(t, v) for t, v in lexer.get_tokens(src) if v.strip()]
    assert toks[0] == (Comment.Single, "// header")
    assert (Keyword.Declaration, "param") in toks and (Name.Constant, "w") in toks
    assert (Number.Float, "10") in toks and (Keyword.Type, "mm") in toks
    assert (Comment.Single, "# width") in toks
    assert (Keyword.Declaration, "solid") in toks and (Name.Class, "plate") in toks
    assert (Name.Class, "Circle") in toks and (Name.Builtin, "Coincident") in toks
    assert (Operator, "//") in toks and (Comment.Single, "// half of it") in toks
    assert (Name.Builtin.Pseudo, "self") in toks
    assert any(t in String.Interpol for t, _ in toks)
