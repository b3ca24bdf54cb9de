"""A minimal client for OpenAI-compatible chat-completions endpoints (standard library only).

Configuration comes from flags or, when a flag is not given, the environment:

* base URL: ``--base-url``, else ``AIDL_BASE_URL``, else ``OPENAI_BASE_URL``, else
  ``https://api.openai.com/v1`` (``/chat/completions`` is appended);
* model: ``--model``, else ``AIDL_MODEL``, else ``gpt-4o``;
* API key: ``--api-key``, else ``OPENAI_API_KEY`` (sent as ``Authorization: Bearer ...``;
  local servers such as llama.cpp, vLLM or Ollama usually need none).
"""
from __future__ import annotations

import json
import os
import urllib.error
import urllib.request
from dataclasses import dataclass

DEFAULT_BASE_URL = "https://api.openai.com/v1"
DEFAULT_MODEL = "gpt-4o"


class LLMError(Exception):
    """The endpoint could not be reached or gave no usable reply (message says which)."""


@dataclass
class ChatClient:
    base_url: str
    model: str
    api_key: str | None = None
    timeout: float = 300.0
    temperature: float | None = None

    @property
    def url(self) -> str:
        u = self.base_url.rstrip("/")
        return u if u.endswith("/chat/completions") else u + "/chat/completions"

    def complete(self, messages: list[dict]) -> str:
        """Send ``messages`` (``[{"role": ..., "content": ...}]``); return the reply text.

        Raises :class:`LLMError` for network errors, HTTP errors and malformed replies.
        """
        body: dict = {"model": self.model, "messages": messages}
        if self.temperature is not None:
            body["temperature"] = self.temperature
        req = urllib.request.Request(self.url, data=json.dumps(body).encode("utf-8"),
                                     headers={"Content-Type": "application/json"}, method="POST")
        if self.api_key:
            req.add_header("Authorization", f"Bearer {self.api_key}")
        try:
            with urllib.request.urlopen(req, timeout=self.timeout) as resp:
                raw = resp.read()
        except urllib.error.HTTPError as e:
            detail = e.read().decode("utf-8", "replace")[:300]
            raise LLMError(f"{self.url} answered HTTP {e.code}: {detail}") from None
        except (urllib.error.URLError, OSError) as e:
            reason = getattr(e, "reason", e)
            raise LLMError(f"cannot reach {self.url}: {reason}") from None
        try:
            doc = json.loads(raw)
            content = doc["choices"][0]["message"]["content"]
        except (ValueError, KeyError, IndexError, TypeError):
            raise LLMError(f"{self.url} gave a reply that is not a chat completion: "
                           f"{raw[:200]!r}") from None
        if not isinstance(content, str):
            raise LLMError(f"{self.url} gave an empty reply")
        return content


def client_from(base_url: str | None = None, model: str | None = None,
                api_key: str | None = None, temperature: float | None = None) -> ChatClient:
    """A :class:`ChatClient` from explicit values with the environment fallbacks above."""
    env = os.environ
    return ChatClient(
        base_url=base_url or env.get("AIDL_BASE_URL") or env.get("OPENAI_BASE_URL")
        or DEFAULT_BASE_URL,
        model=model or env.get("AIDL_MODEL") or DEFAULT_MODEL,
        api_key=api_key or env.get("OPENAI_API_KEY"),
        temperature=temperature)
