"""The I/O handshake that makes a two-robot sync point on controllers without task
synchronisation (KRL, FANUC LS, URScript, NACHI; RAPID writes `WaitSyncTask`).

Each robot has one output wired to the partner's input (`SyncPoint.output`, `.input`). Of
the two robots of `SyncPoint.robots` the one whose name sorts first leads at every sync point,
whatever order a sync point names them in (`SyncPoint.lead` overrides, as a reader finds it in
a file): the roles must stay fixed, since the lead's last transition of one sync point is
answered only by the follower's first of the next. Both outputs are off when the programs
start. At every sync point:

    lead:    wait in OFF,  out ON,  wait in ON,   out OFF
    follow:  wait in ON,   out ON,  wait in OFF,  out OFF

This is the four-phase (return-to-zero) request/acknowledge handshake of asynchronous
circuits, lead = request, follow = acknowledge: the wires change strictly in the order
lead ON, follow ON, lead OFF, follow OFF, lead ON, ... Correct under any I/O delay and any
interpreter timing, because:

- Each wait waits for the partner's *next* transition, and the partner makes no further
  transition until it has seen this robot's answer to it. So a level a robot waits for stays
  on the wire until that robot has read it (no transient can be missed by a controller that
  samples its inputs), and at most one transition is in flight per wire (delays cannot
  reorder them).
- No overtaking: the lead passes sync k after it saw the follower's ON, which the follower
  sets after it reached sync k; the follower passes after it saw the lead's ON of sync k
  (the lead sets it after it reached sync k; the lead's ON of sync k-1 was taken back before
  the follower left sync k-1, since it waited for that OFF).
- No deadlock: by induction over the transitions, each robot's wait is answered by the
  partner's next transition once the partner reaches the same sync point, and a robot between
  sync points only moves, sets outputs and waits on other signals.

The old form (out ON, wait in ON, out OFF; the same for both) fails: a robot passing two sync
points in a row can find its partner's ON of the first still on the wire at the second
(overtaking), and a partner's short ON can come and go between two samples (deadlock).
`motion.programs.io_playback` plays both forms against each other with random I/O delays.

The symmetric four-phase form (out ON, wait ON, out OFF, wait OFF, the same for both) is not
used: a robot takes its ON back as soon as it sees the partner's, which the partner may not
have sampled yet (deadlock).
"""

from __future__ import annotations

from collections.abc import Sequence

from workbench.errors import InputError
from workbench.motion.programs.controller_program import (
    Action,
    SetOutput,
    Signal,
    SyncPoint,
    WaitInput,
)


def leads(sync: SyncPoint, program: str) -> bool:
    """Return whether the program called `program` leads the handshake of `sync`
    (`sync.lead` where set, else whether its name sorts first of `sync.robots`)."""
    if sync.lead is not None:
        return sync.lead
    return bool(sync.robots) and min(sync.robots) == program


def handshake(sync: SyncPoint, lead: bool) -> tuple[Action, ...]:
    """Return the four I/O actions of `sync` for the leading (`lead`) or following robot
    (see the module docstring); InputError when the sync point has no output or input, or
    joins more than two robots (one output and one input join two)."""
    out, inp = sync.output, sync.input
    if out is None or inp is None:
        raise InputError(
            f"sync point {sync.name!r}: this controller has no task sync; its I/O handshake"
            " needs an output and an input signal (the project's io.sync)"
        )
    if len(sync.robots) > 2:
        raise InputError(
            f"sync point {sync.name!r} joins {len(sync.robots)} robots {list(sync.robots)};"
            " an I/O handshake of one output and one input joins two"
        )
    if lead:
        return (
            WaitInput(inp, False),
            SetOutput(out, True),
            WaitInput(inp, True),
            SetOutput(out, False),
        )
    return (
        WaitInput(inp, True),
        SetOutput(out, True),
        WaitInput(inp, False),
        SetOutput(out, False),
    )


def match_handshake(seq: Sequence[object]) -> tuple[bool, Signal, Signal] | None:
    """Return (lead, output, input) when the first four of `seq` are a handshake as
    `handshake` writes it (untimed waits on one input, sets of one output; signals compared by
    number), else None."""
    if len(seq) < 4:
        return None
    w0, s1, w2, s3 = seq[:4]
    if not (
        isinstance(w0, WaitInput)
        and isinstance(w2, WaitInput)
        and isinstance(s1, SetOutput)
        and isinstance(s3, SetOutput)
    ):
        return None
    same = w0.signal.number == w2.signal.number and s1.signal.number == s3.signal.number
    if not same or w0.timeout is not None or w2.timeout is not None:
        return None
    if not (s1.value and not s3.value and w0.value != w2.value):
        return None
    return (not w0.value, s1.signal, w0.signal)
