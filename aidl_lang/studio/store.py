"""Where the studio keeps what outlives one request: the sessions' uploads and the per-client
rate-limit counters (issue 62; docs/studio.md, "More machines").

* Without ``--store``: :class:`~.sessions.Folders`, a folder per session under the server's
  data folder, and ``limits``' in-memory counters: one machine (its ``--processes`` share the
  folder; each process counts its own rate).
* ``--store redis://HOST:PORT/DB``: :class:`RedisFolders`.  A session's uploads live in Redis
  (two hashes per session, ``aidl:studio:SID:m`` name -> ``"SHA256:SIZE"`` and
  ``aidl:studio:SID:d`` name -> bytes, both expiring after
  :data:`~.sessions.IDLE_SECONDS` without a request), and the rate limit is ``limits``'
  moving window on Redis: every process of every machine sees the same uploads and counts the
  same rate, so a load balancer needs no sticky sessions.  The compilers still read a folder
  (the import sandbox is a folder): each process *mirrors* a session's files into its own
  data folder before a compile (:meth:`RedisFolders.folder`; only files whose digest changed
  are fetched), and drops mirrors idle for :data:`MIRROR_IDLE` seconds.

The limits (:data:`~.sessions.MAX_UPLOAD`, :data:`~.sessions.MAX_FILES`,
:data:`~.sessions.MAX_TOTAL`) are checked in Redis in one Lua script, so two processes
uploading to one session at once cannot pass them together.  Every Redis call has a 2 s
answer timeout (0.5 s to connect): a store that does not answer is :class:`StoreDown` (the
studio answers ``503`` with ``Retry-After``), never a hung request.  The calls are
synchronous (well under a millisecond on a LAN), made on the server's event loop like the
local folders' file calls.

Errors: :class:`~.sessions.Refused` (the visitor's mistake), :class:`StoreDown`.
"""
from __future__ import annotations

import hashlib
import json
import os
import secrets
import shutil
from urllib.parse import urlsplit

from .sessions import IDLE_SECONDS, MAX_FILES, MAX_TOTAL, MAX_UPLOAD, Folders, Refused, upload_name

MIRROR_IDLE = 600               # s: a process's copy of a session idle this long is removed
TIMEOUT = 2.0                   # s: every Redis answer
CONNECT_TIMEOUT = 0.5           # s: a connection to Redis (a LAN's take well under 1 ms)
SCHEMES = ("redis", "rediss", "unix")
_MANIFEST = ".manifest.json"    # a mirror's digests (a dot file: not an upload, not listed)


class StoreDown(Exception):
    """The store (Redis) did not answer; the message is for the visitor."""


def check_url(url: str) -> str:
    """``url`` checked as a ``--store`` value (``redis://HOST:PORT/DB``, ``rediss://`` with
    TLS, ``unix:///path/redis.sock``).  Raises ``ValueError`` with what is expected."""
    parts = urlsplit(url)
    if parts.scheme not in SCHEMES or not (parts.netloc or parts.path):
        raise ValueError(f"--store expects redis://HOST:PORT/DB (or rediss://, unix://), "
                         f"got `{url}`")
    return url


def down(e: BaseException) -> bool:
    """Whether ``e`` means the store cannot be reached (Redis' connection errors and
    time-outs, also when ``limits`` raised them)."""
    try:
        from redis.exceptions import ConnectionError, TimeoutError
    except ImportError:
        return False
    return isinstance(e, (ConnectionError, TimeoutError, StoreDown))


def digest(data: bytes) -> str:
    return f"{hashlib.sha256(data).hexdigest()}:{len(data)}"


# KEYS: manifest, data.  ARGV: name, digest, bytes, size, max files, max total, ttl.
# Returns "ok", "files" (one file too many) or "total" (too many bytes).
_UPLOAD = """
local have = redis.call('HGETALL', KEYS[1])
local count, total, old = 0, 0, nil
for i = 1, #have, 2 do
  count = count + 1
  local size = tonumber(string.match(have[i + 1], ':(%d+)$'))
  total = total + size
  if have[i] == ARGV[1] then old = size end
end
if old == nil and count >= tonumber(ARGV[5]) then return 'files' end
if total - (old or 0) + tonumber(ARGV[4]) > tonumber(ARGV[6]) then return 'total' end
redis.call('HSET', KEYS[1], ARGV[1], ARGV[2])
redis.call('HSET', KEYS[2], ARGV[1], ARGV[3])
redis.call('EXPIRE', KEYS[1], ARGV[7])
redis.call('EXPIRE', KEYS[2], ARGV[7])
return 'ok'
"""


def write_files(path: str, files: dict[str, bytes], keep: dict[str, str] | None = None) -> None:
    """Make the folder ``path`` hold exactly ``files`` ({upload name: bytes}): each written
    to a temporary name with ``O_EXCL | O_NOFOLLOW`` and renamed over the old one (nothing in
    it is ever a link), the others removed.  ``keep``: names already right (not rewritten)."""
    keep = keep or {}
    dfd = os.open(path, os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW)
    try:
        for e in os.listdir(dfd):
            if e not in files and e not in keep and not e.startswith("."):
                try:
                    os.unlink(e, dir_fd=dfd)
                except (FileNotFoundError, IsADirectoryError):
                    pass
        for name, data in files.items():
            name = upload_name(name)
            tmp = f".{name}.{secrets.token_hex(6)}"
            fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o600,
                         dir_fd=dfd)
            with os.fdopen(fd, "wb") as f:
                f.write(data)
            os.replace(tmp, name, src_dir_fd=dfd, dst_dir_fd=dfd)
    finally:
        os.close(dfd)


def read_files(path: str) -> dict[str, bytes]:
    """The uploads in the folder ``path`` ({name: bytes}; dot files and links left out)."""
    out = {}
    with os.scandir(path) as it:
        for e in it:
            if e.is_file(follow_symlinks=False) and not e.name.startswith("."):
                with open(e.path, "rb") as f:
                    out[e.name] = f.read()
    return out


class RedisFolders(Folders):
    """The sessions' uploads in Redis at ``url``, mirrored into folders under ``base`` for
    the compilers (the same methods as :class:`~.sessions.Folders`)."""

    PREFIX = "aidl:studio:"
    idle = MIRROR_IDLE

    def __init__(self, base: str | os.PathLike, url: str) -> None:
        import redis
        super().__init__(base)
        self.url = check_url(url)
        self.redis = redis.Redis.from_url(url, socket_timeout=TIMEOUT,
                                          socket_connect_timeout=CONNECT_TIMEOUT)
        self._upload = self.redis.register_script(_UPLOAD)

    def _keys(self, sid: str) -> tuple[str, str]:
        return f"{self.PREFIX}{sid}:m", f"{self.PREFIX}{sid}:d"

    def _call(self, fn, *args):
        try:
            return fn(*args)
        except Exception as e:
            if down(e):
                raise StoreDown("the studio's store (Redis) does not answer; your design is "
                                "kept in this page, try again in a few seconds") from None
            raise

    def ping(self) -> None:
        """Raises :class:`StoreDown` when Redis does not answer."""
        self._call(self.redis.ping)

    def limiter_storage(self):
        """``limits``' Redis storage on the same server (the rate-limit counters)."""
        from limits.storage import storage_from_string
        return storage_from_string(self.url, socket_timeout=TIMEOUT,
                                   socket_connect_timeout=CONNECT_TIMEOUT)

    def _manifest(self, sid: str) -> dict[str, str]:
        m, d = self._keys(sid)

        def get():
            with self.redis.pipeline(transaction=False) as p:
                p.hgetall(m).expire(m, IDLE_SECONDS).expire(d, IDLE_SECONDS)
                got = p.execute()[0]
            return {k.decode(): v.decode() for k, v in got.items()}
        return self._call(get)

    def folder(self, sid: str, create: bool = True) -> str:
        """The session's local mirror, brought up to date with Redis (made when missing)."""
        path = super().folder(sid, create)
        if not create:
            return path
        for _ in range(3):              # again when an upload changed it between two calls
            want = self._manifest(sid)
            try:
                with open(os.path.join(path, _MANIFEST)) as f:
                    have = json.load(f)
            except (OSError, ValueError):
                have = {}
            if want == have and sorted(want) == sorted(
                    n for n in os.listdir(path) if not n.startswith(".")):
                return path
            stale = [n for n in want if have.get(n) != want[n]
                     or not os.path.isfile(os.path.join(path, n))]
            got = self._call(self.redis.hmget, self._keys(sid)[1], stale) if stale else []
            data = dict(zip(stale, got))
            if any(v is None or digest(v) != want[n] for n, v in data.items()):
                continue
            write_files(path, data, keep={n: want[n] for n in want if n not in data})
            tmp = os.path.join(path, f".{secrets.token_hex(6)}")
            with open(tmp, "w") as f:
                json.dump(want, f)
            os.replace(tmp, os.path.join(path, _MANIFEST))
            return path
        raise StoreDown("the session's files keep changing; try again in a few seconds")

    def files(self, sid: str) -> list[dict]:
        super().folder(sid, create=False)           # the id's check
        return [{"name": n, "bytes": int(v.rsplit(":", 1)[1])}
                for n, v in sorted(self._manifest(sid).items())]

    def upload(self, sid: str, name: str, data: bytes) -> dict:
        name = upload_name(name)
        super().folder(sid, create=False)
        if len(data) > MAX_UPLOAD:
            raise Refused(f"`{name}` has {len(data):,} bytes; an upload has at most "
                          f"{MAX_UPLOAD:,}")
        said = self._call(self._upload, list(self._keys(sid)),
                          [name, digest(data), data, len(data), MAX_FILES, MAX_TOTAL,
                           IDLE_SECONDS])
        said = said.decode() if isinstance(said, bytes) else said
        if said == "files":
            raise Refused(f"a session holds at most {MAX_FILES} files; delete one first")
        if said == "total":
            raise Refused(f"a session holds at most {MAX_TOTAL:,} bytes of files")
        return {"name": name, "bytes": len(data)}

    def delete(self, sid: str, name: str) -> None:
        name = upload_name(name)
        super().folder(sid, create=False)
        m, d = self._keys(sid)

        def rm():
            with self.redis.pipeline() as p:
                p.hdel(m, name).hdel(d, name).execute()
        self._call(rm)

    def close(self, sid: str) -> None:
        path = super().folder(sid, create=False)
        self._call(self.redis.delete, *self._keys(sid))
        shutil.rmtree(path, ignore_errors=True)


def open_store(data: str, url: str | None) -> Folders:
    """The sessions' store: :class:`RedisFolders` at ``url``, or local folders under
    ``data`` (``url`` empty).  Raises ``ValueError`` for a bad URL, ``ImportError`` without
    the ``redis`` client (the ``studio`` extra)."""
    if not url:
        return Folders(data)
    return RedisFolders(data, url)


def limiter_storage(folders: Folders):
    """The rate limiter's counters: in Redis with :class:`RedisFolders`, else in memory."""
    if isinstance(folders, RedisFolders):
        return folders.limiter_storage()
    from limits.storage import MemoryStorage
    return MemoryStorage()
