"""`env_value`: a named setting read from the environment (the size, time and memory limits)."""

from __future__ import annotations

import os
from typing import TypeVar

from workbench.errors import InputError

N = TypeVar("N", int, float)


def env_value(env: str, default: N, parse: type[N], what: str) -> N:
    """Return the value of environment variable `env` parsed by `parse` (int or float), or
    `default` when it is unset; InputError naming `env` when it does not parse ("is not
    `what`", e.g. "a whole number of bytes"). Callers check the value's range themselves."""
    raw = os.environ.get(env)
    if raw is None:
        return default
    try:
        return parse(raw)
    except ValueError:
        raise InputError(f"{env}: {raw!r} is not {what}") from None
