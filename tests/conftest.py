import pathlib
import pytest

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXAMPLES = sorted((ROOT / "examples").glob("*.aidl"))


@pytest.fixture
def compile_text(tmp_path):
    from aidl_lang.pipeline import compile_source

    def run(src: str, name: str = "t.aidl", **kw):
        p = tmp_path / name
        p.write_text(src)
        return compile_source(src, str(p), **kw)
    return run
