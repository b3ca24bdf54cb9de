"""The VS Code extension declares exactly the settings the language server reads.

``editors/vscode/package.json`` ``contributes.configuration`` must declare one boolean
``aidl.<name>.enabled`` per toggle in :data:`aidl_lang.editor.lsp.features.settings`, and the
nested form VS Code sends for them (``{"aidl": {"<name>": {"enabled": false}}}``, as
``server.js`` ``clientOptions`` builds it) must switch that toggle in :func:`features.configure`.
"""
import json
from pathlib import Path

import pytest

from aidl_lang.editor.lsp import features

PACKAGE = Path(__file__).resolve().parents[1] / "editors" / "vscode" / "package.json"
# settings the extension itself reads (finding and starting the server), not the server
CLIENT_SIDE = {"aidl.serverPath", "aidl.serverArgs"}


def _declared() -> dict:
    return json.loads(PACKAGE.read_text())["contributes"]["configuration"]["properties"]


def test_declared_settings_are_the_ones_the_server_reads():
    server_side = set(_declared()) - CLIENT_SIDE
    assert server_side == {f"aidl.{k}.enabled" for k in features.settings}


@pytest.mark.parametrize("name", sorted(features.settings))
def test_each_declared_toggle_switches_the_server(name, monkeypatch):
    prop = _declared()[f"aidl.{name}.enabled"]
    assert prop["type"] == "boolean" and prop["default"] is True
    assert len(prop.get("markdownDescription", prop.get("description", ""))) > 30
    monkeypatch.setattr(features, "settings", dict(features.settings))
    features.configure({"aidl": {name: {"enabled": False}}})
    assert features.settings[name] is False
    assert all(v is True for k, v in features.settings.items() if k != name)
    features.configure({"aidl": {name: {"enabled": True}}})
    assert features.settings[name] is True
