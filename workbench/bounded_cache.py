"""An in-memory cache bounded by entry count and by bytes: the least recently used entry goes first.

Module-level caches (a process that stays up for days sees many projects) use this instead of
a plain dict, with their limits as named settings next to them.
"""

from __future__ import annotations

import threading
from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Generic, TypeVar

V = TypeVar("V")


class BoundedCache(Generic[V]):
    """`get`/`put` with at most `max_items` entries and `max_bytes` by `sizeof(value)`."""

    def __init__(self, max_items: int, max_bytes: int, sizeof: Callable[[V], int]) -> None:
        self.max_items, self.max_bytes, self.sizeof = int(max_items), int(max_bytes), sizeof
        self._data: OrderedDict[Hashable, tuple[V, int]] = OrderedDict()
        self._bytes = 0
        self._lock = threading.Lock()

    def __len__(self) -> int:
        return len(self._data)

    @property
    def nbytes(self) -> int:
        """Return the bytes the entries take (by `sizeof`)."""
        return self._bytes

    def get(self, key: Hashable) -> V | None:
        """Return the value of `key` (now the most recently used), or None."""
        with self._lock:
            hit = self._data.get(key)
            if hit is None:
                return None
            self._data.move_to_end(key)
            return hit[0]

    def put(self, key: Hashable, value: V) -> None:
        """Store `value`; evict the least recently used entries beyond the limits.

        A value larger than `max_bytes` alone is not kept.
        """
        size = int(self.sizeof(value))
        with self._lock:
            old = self._data.pop(key, None)
            if old is not None:
                self._bytes -= old[1]
            if size > self.max_bytes or self.max_items <= 0:
                return
            self._data[key] = (value, size)
            self._bytes += size
            while len(self._data) > self.max_items or self._bytes > self.max_bytes:
                _, (_, s) = self._data.popitem(last=False)
                self._bytes -= s

    def clear(self) -> None:
        """Remove every entry."""
        with self._lock:
            self._data.clear()
            self._bytes = 0
