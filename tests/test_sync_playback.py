"""The assembly example's two robot programs, EXPORTED by the service in every format without
task sync and read back by the format's reader, played against each other by
`motion.programs.io_playback` with random interpreter steps and I/O delays of 0-100 ms over
many seeds: no robot passes a sync point before its partner reached it, neither deadlocks nor
faults (issue 27, part 3). The same programs with the old handshake race in the same model.
"""

from __future__ import annotations

import numpy as np
import pytest
from example_plans import planned

from workbench.motion.programs import SyncPoint, post, reader
from workbench.motion.programs.controller_program import SetOutput, WaitInput
from workbench.motion.programs.io_playback import play, sync_wires

pytestmark = pytest.mark.slow  # plans the assembly example (about 20 s, shared per session)

SEEDS = 100


def _exported(fmt: str) -> dict:
    """Return each robot's program as its post writes it (the export's files are exactly
    these: tests/test_example_exports.py) and its reader reads it back."""
    _, programs = planned("assembly_cell.json", "assembly")
    return {p.name: reader(fmt)(post(fmt)(p).files).instructions for p in programs}


@pytest.mark.parametrize("fmt", ["krl", "ls", "urscript", "nachi"])
def test_the_assembly_programs_never_race(fmt: str) -> None:
    programs = _exported(fmt)
    wires = sync_wires(programs)
    assert len(programs) == 2 and len(wires) == 2
    n_sync = {r: sum(isinstance(i, SyncPoint) for i in p) for r, p in programs.items()}
    assert len(set(n_sync.values())) == 1 and min(n_sync.values()) >= 2, n_sync
    for seed in range(SEEDS):
        pb = play(
            programs,
            wires,
            rng=np.random.default_rng(seed),
            pulse_blocks=fmt in ("urscript", "nachi"),
        )
        assert pb.overtaking() == [], (fmt, seed)
        assert pb.stuck() == [] and not pb.faults, (fmt, seed, pb.stuck(), pb.faults)
    # twin: the old handshake in the same model on the same programs
    bad = 0
    for seed in range(SEEDS):
        pb = play(
            programs,
            wires,
            rng=np.random.default_rng(seed),
            sync_actions=lambda s, lead: (
                SetOutput(s.output, True),
                WaitInput(s.input, True),
                SetOutput(s.output, False),
            ),
        )
        bad += bool(pb.overtaking() or pb.stuck())
    assert bad > 0
