"""KUKA KRL reader: a module's `.src` with its `.dat` back into a `ReadProgram`.

`read_krl(files)` reads what `write_krl` writes and the common hand-written forms:

- targets declared in the `.dat` (`DECL [GLOBAL] E6POS|POS|FRAME|E6AXIS|AXIS name={...}`;
  KUKA's inline forms store point P1 as `XP1`, so a declared point's leading "X" is dropped
  from the name the reader returns), assigned in the `.src` (`name = {...}`), or inline
  aggregates in the move (`PTP {A1 0, A2 -90, ...}`, `LIN {E6POS: X .., ..., S 6, T 27}`,
  `LIN {X .., Y .., ...}`); `S`/`T` as decimal or binary ('B110') numbers. A partial
  E6AXIS/AXIS aggregate keeps the previous joint target's other axes, as the controller does.
- `PTP`, `LIN`, `CIRC aux, end` with `C_PTP`/`C_DIS` (`C_VEL`/`C_ORI` noted), speeds from
  `$VEL_AXIS[i]` [%] and `$VEL.CP` [m/s], zones from `$APO.CDIS` [mm] (a PTP zone given only
  by `$APO.CPTP`, a % of the machine datum $APO_DIS_PTP, has no distance: an exact stop, noted);
- `$TOOL`/`$BASE`/`$LOAD` = `TOOL_DATA[n]`/`BASE_DATA[n]`/`LOAD_DATA[n]` (their values from
  `TOOL_DATA[n] = {...}` lines; a trailing "; tool NAME" / "; base NAME" comment names
  them), `{FRAME: ...}`/`{X ...}` literals, declared FRAME variables or `$NULLFRAME`;
- `$OUT[n] = TRUE/FALSE`, `PULSE($OUT[n], TRUE, t)`, `WAIT SEC t`, `WAIT FOR [NOT] $IN[n]`
  (also `$IN[n] == TRUE`), and the timer pattern `write_krl` uses for a timeout
  (`$TIMER[k] = -ms`, `WAIT FOR ... OR $TIMER_FLAG[k]`, `IF $TIMER_FLAG[k] THEN HALT` and
  the re-wait `WAIT FOR ...` `ENDIF`);
- the `; sync point NAME: robots A, B` four-phase handshake back into a `SyncPoint` (its
  `lead` from the file: `sync_handshake.match_handshake`); comments, folds
  (`;FOLD`/`;ENDFOLD` are comments) and `&` header lines are skipped, and the motion settings
  `write_krl` states explicitly ($ADVANCE, $IPO_MODE = #BASE, $ORI_TYPE, $CIRC_TYPE,
  $ACC_AXIS, $ACC/$VEL.ORI*, $APO.CORI/CVEL) are understood and have no effect here.

Cartesian targets come back with their `ArmConfiguration` from Status (bit 0 set: overhead,
not front; bit 1: elbow up; bit 2: A5 < 0, wrist flip) and controller joint ranges from Turn
(bit i set: axis i+1 in [-360, 0) deg, else [-1e-6 deg, 360): the post counts an axis within
1e-6 deg of 0 as 0; half-open, an axis at 0 is not also taken at 360, where its range allows both); see `krl.py` for the definitions and
sources. Every other line (BAS/ILF calls, other declarations, relative moves, subroutines)
is listed in `unknown` as (line, text), lines of the `.dat` as (line, "name.dat: text").
A `.src` that uses a target its `.dat` would declare, without that `.dat`, is an InputError
naming the missing file and the first undefined target with its line.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

import numpy as np

from workbench.errors import InputError
from workbench.geometry.transforms import make_transform, rpy_to_matrix
from workbench.kinematics.arm_configuration import ArmConfiguration
from workbench.motion.programs.controller_program import (
    PulseOutput,
    ReadMove,
    ReadProgram,
    ReadTarget,
    SetOutput,
    Signal,
    SyncPoint,
    ToolData,
    WaitInput,
    WaitTime,
    WorkObject,
)
from workbench.motion.programs.krl import ZERO_TOL
from workbench.motion.programs.program_text import split_comment, split_top
from workbench.motion.programs.sync_handshake import match_handshake

_I = re.IGNORECASE
_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_NAME = r"[A-Za-z_$][A-Za-z0-9_$]*"
_DEF = re.compile(rf"^(?:GLOBAL\s+)?DEF\s+({_NAME})\s*\(.*\)\s*$", _I)
_DECL = re.compile(rf"^DECL\s+(?:GLOBAL\s+)?({_NAME})\s+({_NAME})\s*(?:=\s*(\{{.*\}}))?\s*$", _I)
_ASSIGN_AGG = re.compile(rf"^({_NAME})\s*=\s*(\{{.*\}})\s*$", _I)
_DATA_SET = re.compile(r"^(TOOL_DATA|BASE_DATA|LOAD_DATA)\[\s*(\d+)\s*\]\s*=\s*(\{.*\})\s*$", _I)
_SELECT = re.compile(r"^\$(TOOL|BASE|LOAD)\s*=\s*(.+?)\s*$", _I)
_DATA_REF = re.compile(r"^(TOOL_DATA|BASE_DATA|LOAD_DATA)\[\s*(\d+)\s*\]$", _I)
_VEL_AXIS = re.compile(rf"^\$VEL_AXIS\[\s*(\d+)\s*\]\s*=\s*({_NUM})\s*$", _I)
_SCALAR = re.compile(rf"^\$(VEL\.CP|APO\.CDIS|APO\.CPTP)\s*=\s*({_NUM})\s*$", _I)
_SETTING = re.compile(
    rf"^\$(?:ADVANCE\s*=\s*\d+|IPO_MODE\s*=\s*#BASE|ORI_TYPE\s*=\s*#(?:VAR|CONSTANT|JOINT)"
    rf"|CIRC_TYPE\s*=\s*#(?:BASE|PATH)|ACC_AXIS\[\s*\d+\s*\]\s*=\s*{_NUM}"
    rf"|(?:VEL|ACC)\.ORI[12]\s*=\s*(?:{_NUM}|\$(?:VEL|ACC)_MA\.ORI[12])"
    rf"|ACC\.CP\s*=\s*(?:{_NUM}|\$ACC_MA\.CP)|APO\.(?:CORI|CVEL)\s*=\s*{_NUM})\s*$",
    _I,
)
_MOVE = re.compile(r"^(PTP|LIN|CIRC)\s+(.+?)\s*$", _I)
_APPROX = re.compile(r"\s+(C_PTP|C_DIS|C_VEL|C_ORI)\s*$", _I)
_OUT = re.compile(r"^\$OUT\[\s*(\d+)\s*\]\s*=\s*(TRUE|FALSE)\s*$", _I)
_PULSE = re.compile(rf"^PULSE\s*\(\s*\$OUT\[\s*(\d+)\s*\]\s*,\s*TRUE\s*,\s*({_NUM})\s*\)\s*$", _I)
_WAIT_SEC = re.compile(rf"^WAIT\s+SEC\s+({_NUM})\s*$", _I)
_WAIT_FOR = re.compile(
    r"^WAIT\s+FOR\s+(NOT\s+)?\$IN\[\s*(\d+)\s*\]\s*(?:==\s*(TRUE|FALSE)\s*)?"
    r"(?:OR\s+\$TIMER_FLAG\[\s*(\d+)\s*\]\s*)?$",
    _I,
)
_TIMER = re.compile(r"^\$TIMER\[\s*(\d+)\s*\]\s*=\s*-\s*(\d+)\s*$", _I)
_TIMER_STOP = re.compile(r"^\$TIMER_STOP\[\s*(\d+)\s*\]\s*=\s*(TRUE|FALSE)\s*$", _I)
_IF_TIMER = re.compile(r"^IF\s+\$TIMER_FLAG\[\s*(\d+)\s*\]\s+THEN\s*$", _I)
_SYNC = re.compile(r"^sync point\s+(\S+?):\s*robots\s+(.*)$", _I)
_NAMED = re.compile(r"^(tool|base)\s+(\S+)\s*$", _I)

_POSE_TYPES = {"E6POS", "POS", "FRAME"}
_AXIS_TYPES = {"E6AXIS", "AXIS"}
_AXES = tuple(f"A{k}" for k in range(1, 7))
_FRAME_KEYS = ("X", "Y", "Z", "A", "B", "C")

# Turn bits give [-360, 0) or [0, 360) deg (select_solution takes the half-open ranges, so an
# axis at 0 on a +-360 deg joint is not also taken at 360)
_TURN = 2.0 * np.pi


def _split_comment(line: str) -> tuple[str, str]:
    """Return (code, comment) of one KRL line (';' outside a string starts the comment)."""
    code, comment = split_comment(line, ";")
    return code.strip(), (comment or "").strip()


def _split_top(text: str) -> list[str]:
    """Return the components of an aggregate's inside: split at commas outside braces."""
    return [p for p in split_top(text, ",", "{}", strict=False) if p]


def _value(text: str, where: str) -> object:
    t = text.strip()
    if t.startswith("{"):
        return _aggregate(t, where)[1]
    m = re.fullmatch(r"'B([01]+)'|B'([01]+)'", t, _I)
    if m:
        return float(int(m.group(1) or m.group(2), 2))
    m = re.fullmatch(r"'H([0-9A-F]+)'", t, _I)
    if m:
        return float(int(m.group(1), 16))
    try:
        return float(t)
    except ValueError:
        return t


def _aggregate(text: str, where: str) -> tuple[str | None, dict[str, object]]:
    """Return (type prefix or None, {COMPONENT: value}) of a KRL aggregate '{[TYPE:] K v, ...}'."""
    t = text.strip()
    if not (t.startswith("{") and t.endswith("}")):
        raise InputError(f"expected an aggregate {{...}}, got {text!r}", field=where)
    inner = t[1:-1].strip()
    kind = None
    m = re.match(rf"^({_NAME})\s*:\s*", inner)
    if m:
        kind, inner = m.group(1).upper(), inner[m.end() :]
    out: dict[str, object] = {}
    for part in _split_top(inner):
        m = re.match(rf"^({_NAME})\s+(.+)$", part, re.S)
        if not m:
            raise InputError(
                f"cannot read the aggregate component {part!r}; write it as NAME value", field=where
            )
        out[m.group(1).upper()] = _value(m.group(2), where)
    return kind, out


def _float(agg: dict[str, object], key: str, where: str) -> float:
    v = agg.get(key)
    if not isinstance(v, float) or not np.isfinite(v):
        raise InputError(f"component {key} must be a finite number, got {v!r}", field=where)
    return v


def _frame(agg: dict[str, object], where: str) -> np.ndarray:
    """Return the 4x4 [m] of a FRAME/POS aggregate (mm; A, B, C deg: R = Rz(A) Ry(B) Rx(C))."""
    missing = [k for k in _FRAME_KEYS if k not in agg]
    if missing:
        raise InputError(
            f"the frame lacks {', '.join(missing)}; give X, Y, Z, A, B, C", field=where
        )
    x, y, z, a, b, c = (_float(agg, k, where) for k in _FRAME_KEYS)
    R = rpy_to_matrix(np.radians([c, b, a]))
    return make_transform(R, np.array([x, y, z]) / 1000.0)


@dataclass
class _Var:
    name: str  # as declared
    kind: str | None  # declared type (upper) or None
    value: dict[str, object] | None
    line: int
    where: str


@dataclass
class _State:
    tool: str | None = None
    base: str | None = None
    vel_axis: dict[int, float] = field(default_factory=dict)
    vel_cp: float | None = None
    cdis: float | None = None
    cptp: float | None = None
    last_joints: np.ndarray | None = None
    timer: tuple[int, float, int, str] | None = None  # (k, seconds, line, text)
    in_timeout_if: int | None = None


class _Reader:
    def __init__(self, files: dict[str, str]) -> None:
        srcs = [n for n in files if n.lower().endswith(".src")]
        if len(srcs) != 1:
            raise InputError(
                f"KRL: give one module's .src (and its .dat); got {len(srcs)} .src files"
                f" among {sorted(files)}"
            )
        self.src_name = srcs[0]
        self.stem = self.src_name[: -len(".src")]
        dats = [n for n in files if n.lower() == (self.stem + ".dat").lower()]
        self.dat_name = dats[0] if dats else None
        self.files = files
        self.vars: dict[str, _Var] = {}
        self.unknown: list[tuple[int, str]] = []
        self.notes: list[str] = []
        self.tool_frames: dict[str, np.ndarray] = {}
        self.tool_loads: dict[str, tuple[float, np.ndarray]] = {}
        self.base_frames: dict[str, np.ndarray] = {}
        self.data: dict[tuple[str, int], tuple[object, str | None]] = {}
        self.instructions: list = []
        self.syncs: list[tuple[int, str, tuple[str, ...], int]] = []
        for other in files:
            if other not in (self.src_name, self.dat_name):
                self.notes.append(f"{other}: not part of module {self.stem}; not read")

    # -- .dat ------------------------------------------------------------------------
    def read_dat(self) -> None:
        if self.dat_name is None:
            return
        fname = self.dat_name
        started = ended = False
        for n, raw in enumerate(self.files[fname].splitlines(), 1):
            code, _ = _split_comment(raw)
            if not code or code.startswith("&"):
                continue
            where = f"{fname} line {n}"
            if not started:
                if re.match(rf"^DEFDAT\s+{_NAME}(\s+PUBLIC)?\s*$", code, _I):
                    started = True
                    continue
                self.unknown.append((n, f"{fname}: {raw.strip()}"))
                continue
            if ended:
                self.unknown.append((n, f"{fname}: {raw.strip()}"))
                continue
            if re.match(r"^ENDDAT\s*$", code, _I):
                ended = True
                continue
            m = _DECL.match(code)
            if m and (m.group(1).upper() in _POSE_TYPES | _AXIS_TYPES) and m.group(3):
                self._declare(m.group(2), m.group(1).upper(), m.group(3), n, where)
                continue
            self.unknown.append((n, f"{fname}: {raw.strip()}"))
        if not started:
            raise InputError(
                f"{fname}: no DEFDAT line; a KRL data list starts with DEFDAT {self.stem}"
            )

    def _declare(
        self, name: str, kind: str | None, agg_text: str | None, line: int, where: str
    ) -> None:
        value = None
        if agg_text is not None:
            typ, value = _aggregate(agg_text, where)
            kind = kind or typ
        self.vars[name.lower()] = _Var(name, kind, value, line, where)

    # -- .src ------------------------------------------------------------------------
    def read_src(self) -> str:
        fname = self.src_name
        prog = None
        done = False
        st = _State()
        for n, raw in enumerate(self.files[fname].splitlines(), 1):
            code, comment = _split_comment(raw)
            text = raw.strip()
            if not code:
                if prog is not None and not done:
                    self._comment(comment, n)
                continue
            if code.startswith("&"):
                continue
            if prog is None:
                m = _DEF.match(code)
                if m:
                    prog = m.group(1)
                else:
                    self.unknown.append((n, text))
                continue
            if done:
                self.unknown.append((n, text))
                continue
            if re.fullmatch(r"END", code, _I):
                done = True
                continue
            if not self._statement(code, comment, n, text, st):
                self.unknown.append((n, text))
        if prog is None:
            raise InputError(f"{fname}: no DEF line; a KRL program starts with DEF {self.stem}()")
        if not done:
            raise InputError(f"{fname}: DEF {prog}() has no END")
        if st.timer is not None:
            self.unknown.append((st.timer[2], st.timer[3]))
        return prog

    def _comment(self, comment: str, n: int) -> None:
        m = _SYNC.match(comment)
        if m:
            robots = tuple(r.strip() for r in m.group(2).split(",") if r.strip())
            self.syncs.append((len(self.instructions), m.group(1), robots, n))

    def _statement(self, code: str, comment: str, n: int, text: str, st: _State) -> bool:  # noqa: C901, PLR0911, PLR0912
        where = f"{self.src_name} line {n}"
        if st.in_timeout_if is not None:
            if re.fullmatch(r"ENDIF", code, _I):
                st.in_timeout_if = None
                return True
            # HALT, then the post's re-wait for the same input (no timer): part of the timed wait
            w = _WAIT_FOR.match(code)
            return bool(re.fullmatch(r"HALT", code, _I) or (w and w.group(4) is None))
        if _SETTING.match(code):
            return True
        m = _VEL_AXIS.match(code)
        if m:
            st.vel_axis[int(m.group(1))] = float(m.group(2))
            return True
        m = _SCALAR.match(code)
        if m:
            key, v = m.group(1).upper(), float(m.group(2))
            if key == "VEL.CP":
                st.vel_cp = v
            elif key == "APO.CDIS":
                st.cdis = v
            else:
                st.cptp = v
            return True
        m = _DATA_SET.match(code)
        if m:
            self._data_set(m.group(1).upper(), int(m.group(2)), m.group(3), comment, where)
            return True
        m = _SELECT.match(code)
        if m:
            return self._select(m.group(1).upper(), m.group(2), n, where, st)
        m = _MOVE.match(code)
        if m:
            return self._move(m.group(1).upper(), m.group(2), n, where, st)
        m = _OUT.match(code)
        if m:
            self.instructions.append(
                SetOutput(self._signal("out", m.group(1), comment), m.group(2).upper() == "TRUE")
            )
            return True
        m = _PULSE.match(code)
        if m:
            self.instructions.append(
                PulseOutput(self._signal("out", m.group(1), comment), float(m.group(2)))
            )
            return True
        m = _WAIT_SEC.match(code)
        if m:
            self.instructions.append(WaitTime(float(m.group(1))))
            return True
        m = _WAIT_FOR.match(code)
        if m:
            return self._wait(m, comment, n, text, st)
        m = _TIMER.match(code)
        if m:
            if st.timer is not None:
                self.unknown.append((st.timer[2], st.timer[3]))
            st.timer = (int(m.group(1)), int(m.group(2)) / 1000.0, n, text)
            return True
        if _TIMER_STOP.match(code):
            return True
        m = _IF_TIMER.match(code)
        if m:
            st.in_timeout_if = n
            return True
        m = _DECL.match(code)
        if m and m.group(1).upper() in _POSE_TYPES | _AXIS_TYPES:
            self._declare(m.group(2), m.group(1).upper(), m.group(3), n, where)
            return True
        m = _ASSIGN_AGG.match(code)
        if m and not m.group(1).startswith("$"):
            var = self.vars.get(m.group(1).lower())
            self._declare(m.group(1), var.kind if var else None, m.group(2), n, where)
            return True
        return False

    def _signal(self, kind: str, number: str, comment: str) -> Signal:
        k = int(number)
        name = comment.split()[0] if comment.split() else f"{'do' if kind == 'out' else 'di'}_{k}"
        return Signal(name, k)

    def _wait(self, m: re.Match, comment: str, n: int, text: str, st: _State) -> bool:
        value = m.group(1) is None
        if m.group(3) is not None:
            value = value == (m.group(3).upper() == "TRUE")
        timeout = None
        if m.group(4) is not None:
            k = int(m.group(4))
            if st.timer is None or st.timer[0] != k:
                return False
            timeout = st.timer[1]
            st.timer = None
        self.instructions.append(WaitInput(self._signal("in", m.group(2), comment), value, timeout))
        return True

    def _data_set(self, table: str, k: int, agg_text: str, comment: str, where: str) -> None:
        _, agg = _aggregate(agg_text, where)
        m = _NAMED.match(comment)
        name = m.group(2) if m else None
        if table == "LOAD_DATA":
            mass = _float(agg, "M", where)
            cm = agg.get("CM", {})
            cog = np.zeros(3)
            if isinstance(cm, dict):
                cog = np.array([float(cm.get(c, 0.0)) for c in "XYZ"]) / 1000.0  # type: ignore[arg-type]
            self.data[(table, k)] = ((mass, cog), name)
        else:
            self.data[(table, k)] = (_frame(agg, where), name)

    def _select(self, what: str, rhs: str, n: int, where: str, st: _State) -> bool:
        if what == "LOAD":
            m = _DATA_REF.match(rhs)
            if m and m.group(1).upper() == "LOAD_DATA":
                load = self.data.get(("LOAD_DATA", int(m.group(2))))
                if load is None:
                    self.notes.append(
                        f"{where}: LOAD_DATA[{m.group(2)}] is not set in these files; the tool's mass is unknown"
                    )
                elif st.tool is not None:
                    self.tool_loads[st.tool] = load[0]  # type: ignore[assignment]
                return True
            if rhs.startswith("{"):
                _, agg = _aggregate(rhs, where)
                cm = agg.get("CM", {})
                cog = (
                    np.array([float(cm.get(c, 0.0)) for c in "XYZ"]) / 1000.0
                    if isinstance(cm, dict)
                    else np.zeros(3)
                )  # type: ignore[arg-type]
                if st.tool is not None:
                    self.tool_loads[st.tool] = (_float(agg, "M", where), cog)
                return True
            return False
        table = "TOOL_DATA" if what == "TOOL" else "BASE_DATA"
        frames = self.tool_frames if what == "TOOL" else self.base_frames
        m = _DATA_REF.match(rhs)
        if m:
            if m.group(1).upper() != table:
                return False
            k = int(m.group(2))
            got = self.data.get((table, k))
            if got is None:
                name, T = f"{table}[{k}]", np.eye(4)
                self.notes.append(
                    f"{where}: {table}[{k}] is not set in these files (it lives in the controller's"
                    " $config.dat); read as the null frame"
                )
            else:
                T, name = got[0], got[1] or f"{table}[{k}]"  # type: ignore[assignment]
        elif re.fullmatch(r"\$NULLFRAME", rhs, _I):
            name, T = "$NULLFRAME", np.eye(4)
        elif rhs.startswith("{"):
            _, agg = _aggregate(rhs, where)
            name, T = f"{what.lower()}_line{n}", _frame(agg, where)
        elif (
            re.fullmatch(_NAME, rhs)
            and rhs.lower() in self.vars
            and self.vars[rhs.lower()].value is not None
        ):
            var = self.vars[rhs.lower()]
            name, T = var.name, _frame(var.value, var.where)  # type: ignore[arg-type]
        else:
            return False
        frames[name] = T  # type: ignore[assignment]
        if what == "TOOL":
            st.tool = name
        else:
            st.base = name
        return True

    # -- moves -----------------------------------------------------------------------
    def _target(self, expr: str, n: int, where: str, st: _State, *, joint_ok: bool) -> ReadTarget:
        expr = expr.strip()
        if expr.startswith("{"):
            kind, agg = _aggregate(expr, where)
            return self._make_target(f"line{n}", kind, agg, where, st, joint_ok)
        if not re.fullmatch(_NAME, expr):
            raise InputError(f"cannot read the move's target {expr!r}", field=where)
        var = self.vars.get(expr.lower())
        if var is None or var.value is None:
            if self.dat_name is None:
                raise InputError(
                    f"{self.src_name} line {n}: the target {expr!r} is not defined: the module's"
                    f" data list {self.stem}.dat is missing; read {self.stem}.src together with"
                    f" {self.stem}.dat"
                )
            raise InputError(
                f"{self.src_name} line {n}: the target {expr!r} is declared with a value neither in"
                f" {self.dat_name} nor in {self.src_name}"
            )
        name = var.name
        kind = var.kind
        if kind in _POSE_TYPES | _AXIS_TYPES and len(name) > 1 and name[0] in "xX":
            name = name[1:]
        return self._make_target(name, kind, var.value, var.where, st, joint_ok)

    def _make_target(self, name, kind, agg, where, st, joint_ok) -> ReadTarget:  # noqa: ANN001
        is_axis = kind in _AXIS_TYPES or (kind is None and any(a in agg for a in _AXES))
        if is_axis:
            if not joint_ok:
                raise InputError(
                    "a LIN/CIRC target must be a pose (X, Y, Z, A, B, C), not axes", field=where
                )
            vals = []
            for k, a in enumerate(_AXES):
                if a in agg:
                    vals.append(np.radians(_float(agg, a, where)))
                elif st.last_joints is not None:
                    vals.append(float(st.last_joints[k]))
                else:
                    raise InputError(
                        f"the joint target lacks {a} and no earlier joint target gives it",
                        field=where,
                    )
            q = np.array(vals)
            st.last_joints = q
            return ReadTarget(name, joints=q)
        T = _frame(agg, where)
        cfg, ranges = None, None
        if "S" in agg:
            s = int(_float(agg, "S", where))
            cfg = ArmConfiguration(front=not (s & 1), elbow_up=bool(s & 2), wrist_flip=bool(s & 4))
        else:
            self.notes.append(
                f"{where}: target {name!r} has no Status S; a PTP to it leaves the arm configuration"
                " to the controller"
            )
        if "T" in agg:
            t = int(_float(agg, "T", where))
            # the post counts an axis within ZERO_TOL (1e-6 deg) of 0 as >= 0
            ranges = np.array(
                [[-_TURN, 0.0] if t & (1 << i) else [-ZERO_TOL, _TURN] for i in range(6)],
                float,
            )
            if cfg is not None and bool(t & 16) != cfg.wrist_flip:
                self.notes.append(
                    f"{where}: target {name!r}: Status bit 2 and Turn bit 4 (A5 < 0) disagree"
                )
        return ReadTarget(name, T_wobj_tcp=T, configuration=cfg, controller_ranges=ranges)

    def _move(self, kind: str, rest: str, n: int, where: str, st: _State) -> bool:
        approx = None
        m = _APPROX.search(rest)
        if m:
            approx, rest = m.group(1).upper(), rest[: m.start()]
        if re.search(r",\s*CA\s", rest, _I):
            return False
        via = None
        if kind == "CIRC":
            parts = _split_top(rest)
            if len(parts) != 2:
                raise InputError(
                    "CIRC needs an auxiliary point and an end point: CIRC aux, end", field=where
                )
            via = self._target(parts[0], n, where, st, joint_ok=False)
            target = self._target(parts[1], n, where, st, joint_ok=False)
        else:
            target = self._target(rest, n, where, st, joint_ok=kind == "PTP")
            if target.joints is None:
                st.last_joints = None
        zone = 0.0
        if approx is not None:
            if approx in ("C_VEL", "C_ORI"):
                self.notes.append(
                    f"{where}: {approx} approximation read with $APO.CDIS as the zone"
                )
            if st.cdis is not None:
                zone = st.cdis / 1000.0
            elif approx == "C_PTP" and st.cptp is not None:
                self.notes.append(
                    f"{where}: PTP zone given only as $APO.CPTP {st.cptp:g} % (of the machine"
                    " datum $APO_DIS_PTP, not a distance); read as an exact stop"
                )
            else:
                self.notes.append(f"{where}: {approx} without $APO.CDIS; read as an exact stop")
        if kind == "PTP":
            speed = None
            if st.vel_axis:
                vals = sorted(set(st.vel_axis.values()))
                speed = max(vals) / 100.0
                if len(vals) > 1 or len(st.vel_axis) < 6:
                    self.notes.append(
                        f"{where}: $VEL_AXIS differs between axes; read as {max(vals):g} %"
                    )
            else:
                self.notes.append(f"{where}: no $VEL_AXIS before this PTP; its speed is unknown")
        else:
            speed = st.vel_cp
            if speed is None:
                self.notes.append(f"{where}: no $VEL.CP before this {kind}; its speed is unknown")
        if st.tool is None or st.base is None:
            for what, cur, frames in (
                ("TOOL", st.tool, self.tool_frames),
                ("BASE", st.base, self.base_frames),
            ):
                if cur is None:
                    frames.setdefault(f"${what}", np.eye(4))
                    self.notes.append(
                        f"{where}: no ${what} set before the first move; read as the null frame"
                    )
            st.tool = st.tool or "$TOOL"
            st.base = st.base or "$BASE"
        mk = {"PTP": "joint", "LIN": "linear", "CIRC": "circular"}[kind]
        self.instructions.append(ReadMove(mk, target, speed, zone, st.tool, st.base, None, via, n))  # type: ignore[arg-type]
        return True

    # -- result ----------------------------------------------------------------------
    def result(self, prog: str) -> ReadProgram:
        ins = self.instructions
        for idx, name, robots, line in reversed(self.syncs):
            found = match_handshake(ins[idx : idx + 4])
            if found:
                lead, out, inp = found
                ins[idx : idx + 4] = [SyncPoint(name, robots, out, inp, lead)]
            else:
                self.notes.append(
                    f"{self.src_name} line {line}: sync point {name} is not followed by the"
                    " four-phase handshake (WAIT FOR [NOT] $IN, $OUT = TRUE, WAIT FOR [NOT] $IN,"
                    " $OUT = FALSE); read as plain I/O"
                )
        tools = tuple(
            ToolData(nm, T, *(self.tool_loads[nm] if nm in self.tool_loads else (None, None)))
            for nm, T in self.tool_frames.items()
        )
        bases = tuple(WorkObject(nm, T) for nm, T in self.base_frames.items())
        return ReadProgram(
            prog, tools, bases, tuple(ins), tuple(sorted(self.unknown)), tuple(self.notes)
        )


def read_krl(files: dict[str, str]) -> ReadProgram:
    """Return the program of one KRL module: `files` maps "<name>.src" (and "<name>.dat",
    names compared case-insensitively) to their text. See the module docstring for what is
    read; lines it does not understand are in `unknown`, never dropped. Raises InputError
    naming the file and line on malformed input, and on a target whose .dat is missing."""
    r = _Reader(files)
    r.read_dat()
    prog = r.read_src()
    return r.result(prog)
