"""CAD readers run in a child process with a wall-time and a memory limit.

Open CASCADE's STEP reader can crash the process that calls it (a deeply nested list overflows
its parser's stack: a segmentation fault), hang or swell for hours on a hostile or merely huge
file, and a DXF can ask ezdxf for millions of entities. So every STEP and DXF file is read by a
worker process (`python -m workbench.cad.isolation`, started with fork + exec by `subprocess`:
no fork of a threaded server) that

- limits its own address space to `WORKBENCH_CAD_MEMORY_BYTES` (``resource.setrlimit
  (RLIMIT_AS)``, default `DEFAULT_MEMORY_BYTES`): a reader that swells gets ``MemoryError``
  (or dies) instead of taking the machine's memory;
- is killed by the parent when a read takes longer than `WORKBENCH_CAD_SECONDS` (default
  `DEFAULT_SECONDS`), and kills itself a little later (``alarm``) should the parent be gone.

The parent gets plain data back (numpy arrays, the readers' frozen dataclasses), unpickled
with an allow-list of classes, and turns every way a read can end into a result or a
`WorkbenchError` naming the file and what happened: the worker's own error as raised there
(same class, message and field), a crash (the signal), the time limit, the memory limit.

Start-up costs a new Python with numpy and ezdxf (2.7-4 s for the first read here; OCP loads
on the first STEP read, 3 s, as it did in process); later reads cost what they did in process
(docs/security.md). A worker is therefore kept and reused: `MAX_IDLE_WORKERS` wait between reads, one more is started for
each read that finds none idle; a worker that crashed, was killed or grew past half its
memory limit is replaced at the next read.
"""

from __future__ import annotations

import atexit
import dataclasses
import importlib
import io
import os
import pickle
import select
import signal
import struct
import subprocess
import sys
import threading
import time
from pathlib import Path
from typing import Any

from workbench import errors
from workbench.env_setting import env_value
from workbench.errors import InputError, MeshError, WorkbenchError

DEFAULT_SECONDS = 60.0
"""The longest one CAD file may take to read [s] (`WORKBENCH_CAD_SECONDS`)."""
DEFAULT_MEMORY_BYTES = 4 * 1024**3
"""The most address space a CAD reader may use [bytes] (`WORKBENCH_CAD_MEMORY_BYTES`); Open
CASCADE's libraries take some 550 MB of it once loaded."""
MIN_MEMORY_BYTES = 1024**3
"""The least `WORKBENCH_CAD_MEMORY_BYTES` accepted: below it OCP cannot even load."""
MAX_IDLE_WORKERS = 2
"""How many workers wait for the next read."""
ALLOWED_MODULES = ("workbench.cad.",)
"""Where the worker may find the function it runs (the parent names it: a trusted name)."""
SETTINGS = (
    "workbench.cad.brep_mesh.MAX_TRIANGLES",
    "workbench.cad.step_checks.MAX_STEP_ENTITIES",
    "workbench.cad.step_checks.MAX_STEP_NESTING",
    "workbench.cad.step_checks.MAX_COORDINATE_MM",
    "workbench.cad.dxf_checks.MAX_DXF_ENTITIES",
    "workbench.cad.dxf_checks.MAX_EXPANDED_ENTITIES",
    "workbench.cad.dxf_checks.MAX_SPLINE_DEGREE",
    "workbench.cad.dxf_checks.MAX_BEND_LINES",
)
"""The readers' bounds: the parent sends their values in this process with every read, so
the worker applies the same ones (a program or a test that changes one changes both)."""
_HEADER = struct.Struct("<Q")


def cad_seconds() -> float:
    """Return the time limit of one CAD read [s] (`WORKBENCH_CAD_SECONDS`, default 60)."""
    value = env_value("WORKBENCH_CAD_SECONDS", DEFAULT_SECONDS, float, "a number of seconds")
    if not 0 < value <= 86400:
        raise InputError(f"WORKBENCH_CAD_SECONDS: {value:g} must lie in (0, 86400] s")
    return value


def cad_memory_bytes() -> int:
    """Return the memory limit of a CAD reader [bytes] (`WORKBENCH_CAD_MEMORY_BYTES`)."""
    value = env_value("WORKBENCH_CAD_MEMORY_BYTES", DEFAULT_MEMORY_BYTES, int, "a whole number")
    if value < MIN_MEMORY_BYTES:
        raise InputError(
            f"WORKBENCH_CAD_MEMORY_BYTES: {value} is below {MIN_MEMORY_BYTES} (1 GiB), too little"
            " for Open CASCADE to load"
        )
    return value


class _Unpickler(pickle.Unpickler):
    """Unpickles only numpy arrays and the CAD readers' own dataclasses (workbench.cad.*): a
    worker that a hostile file took over cannot make the parent call a function."""

    def find_class(self, module: str, name: str) -> Any:
        numpy_ok = module.split(".")[0] == "numpy" and name in (
            "_reconstruct",
            "ndarray",
            "dtype",
            "scalar",
            "_frombuffer",
        )
        if numpy_ok:
            return super().find_class(module, name)
        if module.startswith(ALLOWED_MODULES):  # the readers' dataclasses, never a function
            found = super().find_class(module, name)
            if isinstance(found, type) and dataclasses.is_dataclass(found):
                return found
        raise pickle.UnpicklingError(f"a CAD worker's reply may not hold {module}.{name}")


def _send(fh: Any, obj: Any) -> None:
    body = pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL)
    fh.write(_HEADER.pack(len(body)) + body)
    fh.flush()


class _Worker:
    """One worker process and its pipes."""

    def __init__(self, memory: int) -> None:
        root = str(Path(__file__).resolve().parents[2])  # the tree this package was loaded from
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join(p for p in (root, env.get("PYTHONPATH")) if p)
        env["WORKBENCH_CAD_CHILD_MEMORY"] = str(memory)
        env["MALLOC_ARENA_MAX"] = "2"  # glibc's per-thread arenas would eat the address space
        self.memory = memory
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "workbench.cad.isolation"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            env=env,
            close_fds=True,
        )

    def kill(self) -> None:
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.wait()
        for fh in (self.proc.stdin, self.proc.stdout):
            if fh is not None:
                fh.close()

    def _read(self, n: int, deadline: float) -> bytes | None:
        """Return `n` bytes of the reply, or None at end of file; TimeoutError past `deadline`."""
        assert self.proc.stdout is not None
        fd, parts, got = self.proc.stdout.fileno(), [], 0
        while got < n:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([fd], [], [], left)[0]:
                raise TimeoutError
            chunk = os.read(fd, min(n - got, 1 << 20))
            if not chunk:
                return None
            parts.append(chunk)
            got += len(chunk)
        return b"".join(parts)

    def call(self, target: str, args: tuple[Any, ...], seconds: float) -> tuple[str, Any]:
        """Return the worker's reply to running `target(*args)`: ("ok", result), ("error", ..),
        or ("died", returncode) / ("timeout", None) after which the worker is gone."""
        deadline = time.monotonic() + seconds
        try:
            _send(self.proc.stdin, (target, args, seconds, _settings()))
        except (BrokenPipeError, OSError):
            self.kill()
            return "gone", None  # it ended while idle: the file is not to blame
        try:
            head = self._read(_HEADER.size, deadline)
            body = None if head is None else self._read(_HEADER.unpack(head)[0], deadline)
        except TimeoutError:
            self.kill()
            return "timeout", None
        except (BrokenPipeError, OSError):
            body = None
        if body is None:
            self.kill()
            return "died", self.proc.returncode
        reply = _Unpickler(io.BytesIO(body)).load()
        return reply[0], reply[1:]


def _settings() -> dict[str, Any]:
    out = {}
    for path in SETTINGS:
        module, _, attr = path.rpartition(".")
        out[path] = getattr(importlib.import_module(module), attr)
    return out


_idle: list[_Worker] = []
_lock = threading.Lock()


def _take(memory: int) -> tuple[_Worker, bool]:
    """Return a worker for a read and whether it was an idle one (which may have ended)."""
    with _lock:
        while _idle:
            worker = _idle.pop()
            if worker.proc.poll() is None and worker.memory == memory:
                return worker, True
            worker.kill()
    return _Worker(memory), False


def _give_back(worker: _Worker) -> None:
    with _lock:
        if worker.proc.poll() is None and len(_idle) < MAX_IDLE_WORKERS:
            _idle.append(worker)
            return
    worker.kill()


@atexit.register
def stop_workers() -> None:
    """End the idle workers (they also end when this process does: their input closes)."""
    with _lock:
        while _idle:
            _idle.pop().kill()


def _signal_name(code: int) -> str:
    try:
        return signal.Signals(-code).name
    except ValueError:
        return f"signal {-code}"


def run_isolated(
    target: str, args: tuple[Any, ...], *, name: str, field: str | None, fix: str = ""
) -> Any:
    """Return `target(*args)` run in a CAD worker (`target` is "module:function" in
    workbench.cad); `name` (the file) and `field` name the input in errors, `fix` (", or ...")
    adds to what a time or memory refusal tells the user to do.

    The worker's WorkbenchError comes back as raised; a crash, the time limit
    (`WORKBENCH_CAD_SECONDS`) and the memory limit (`WORKBENCH_CAD_MEMORY_BYTES`) become a
    MeshError naming the file and the setting; any other exception a MeshError naming it.
    """
    if not target.startswith(ALLOWED_MODULES):
        raise ValueError(f"not a CAD reader: {target}")
    seconds, memory = cad_seconds(), cad_memory_bytes()
    worker, was_idle = _take(memory)
    status, detail = worker.call(target, args, seconds)
    if status == "gone" or (status == "died" and was_idle):
        # an idle worker that ended (or was being killed) before the read reached it: the file
        # is blamed only when a fresh worker dies on it too
        worker = _Worker(memory)
        status, detail = worker.call(target, args, seconds)
    if status in ("ok", "error", "memory", "failed"):
        if detail[-1]:
            _give_back(worker)
        else:
            worker.kill()
    if status == "ok":
        return detail[0]
    if status == "error":
        raise _error_class(detail[0])(detail[1], field=detail[2])
    where = f"reading {name!r}"
    if status == "memory":
        raise MeshError(
            f"{where} took more than the {memory / 1024**3:g} GiB its reader may use"
            f" (WORKBENCH_CAD_MEMORY_BYTES); simplify the file{fix} or raise the setting",
            field=field,
        )
    if status == "timeout":
        raise MeshError(
            f"{where} took longer than {seconds:g} s (WORKBENCH_CAD_SECONDS) and was stopped;"
            f" simplify the file{fix} or raise the setting",
            field=field,
        )
    if status == "died":
        code = int(detail)
        how = f"with {_signal_name(code)}" if code < 0 else f"with exit status {code}"
        if code == -signal.SIGALRM:
            how = f"at its own time limit ({seconds:g} s, WORKBENCH_CAD_SECONDS)"
        raise MeshError(
            f"the reader crashed on {name!r} ({how}); the file is damaged or made to break"
            " readers: export it again from its CAD system",
            field=field,
        )
    if status == "gone":
        raise MeshError(f"cannot read {name!r}: the CAD worker does not start", field=field)
    raise MeshError(f"cannot read {name!r}: {detail[0]}: {detail[1]}", field=field)


def _error_class(name: str) -> type[WorkbenchError]:
    """Return the WorkbenchError subclass called `name` (workbench.errors' or the flat
    pattern's); MeshError for any other name."""
    from workbench.cad.flat_pattern import FlatPatternError

    found = FlatPatternError if name == "FlatPatternError" else getattr(errors, name, None)
    ok = isinstance(found, type) and issubclass(found, WorkbenchError)
    return found if ok else MeshError  # type: ignore[return-value]


# -- the worker ------------------------------------------------------------------------------------
def _child_reply(target: str, args: tuple[Any, ...], settings: dict[str, Any]) -> tuple[Any, ...]:
    """Run `target(*args)` under the parent's `settings`; return the reply (its last item:
    whether the worker may go on)."""
    try:
        for path, value in settings.items():
            owner, _, attr = path.rpartition(".")
            setattr(importlib.import_module(owner), attr, value)
        module, _, func = target.partition(":")
        result = getattr(importlib.import_module(module), func)(*args)
        return ("ok", result, True)
    except WorkbenchError as exc:
        return ("error", type(exc).__name__, exc.detail, exc.field, True)
    except MemoryError:
        return ("memory", False)
    except RecursionError as exc:
        return ("failed", "RecursionError", str(exc)[:300], False)
    except Exception as exc:  # a library's own exception: named by the parent
        return ("failed", type(exc).__name__, str(exc)[:300], True)


def _child_main() -> None:
    import resource

    memory = int(os.environ["WORKBENCH_CAD_CHILD_MEMORY"])
    resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))  # a crash leaves no core file behind
    # The protocol gets its own descriptors: OCP prints on stdout, which goes nowhere.
    inp = os.fdopen(os.dup(0), "rb")
    out = os.fdopen(os.dup(1), "wb")
    null = os.open(os.devnull, os.O_RDWR)
    os.dup2(null, 0)
    os.dup2(null, 1)
    while True:
        head = inp.read(_HEADER.size)
        if len(head) < _HEADER.size:
            return  # the parent is gone or done
        target, args, seconds, settings = pickle.loads(inp.read(_HEADER.unpack(head)[0]))
        signal.alarm(int(seconds) + 5)  # should the parent be gone: end, never hang
        reply = _child_reply(target, args, settings)
        signal.alarm(0)
        if reply[-1] and _resident() > memory // 2:
            reply = (*reply[:-1], False)  # grown: the next read gets a fresh worker
        try:
            _send(out, reply)
        except MemoryError:
            _send(out, ("memory", False))
            return
        if not reply[-1]:
            return


def _resident() -> int:
    """Return this process's resident memory [bytes]."""
    with open("/proc/self/statm") as fh:
        return int(fh.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


if __name__ == "__main__":
    _child_main()
