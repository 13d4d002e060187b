"""env_value: unset gives the default, a number parses, anything else names the variable."""

from __future__ import annotations

import pytest

from workbench.env_setting import env_value
from workbench.errors import InputError


def test_unset_gives_the_default_and_numbers_parse(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("WORKBENCH_TEST_LIMIT", raising=False)
    assert env_value("WORKBENCH_TEST_LIMIT", 7, int, "a whole number") == 7
    monkeypatch.setenv("WORKBENCH_TEST_LIMIT", "12")
    assert env_value("WORKBENCH_TEST_LIMIT", 7, int, "a whole number") == 12
    monkeypatch.setenv("WORKBENCH_TEST_LIMIT", "2.5")
    assert env_value("WORKBENCH_TEST_LIMIT", 1.0, float, "a number of seconds") == 2.5


@pytest.mark.parametrize(("raw", "parse"), [("2.5", int), ("ten", float), ("", int)])
def test_what_does_not_parse_is_refused_naming_the_variable(
    monkeypatch: pytest.MonkeyPatch, raw: str, parse: type
) -> None:
    monkeypatch.setenv("WORKBENCH_TEST_LIMIT", raw)
    with pytest.raises(InputError, match=rf"WORKBENCH_TEST_LIMIT: {raw!r} is not a number"):
        env_value("WORKBENCH_TEST_LIMIT", parse(1), parse, "a number of bytes")
