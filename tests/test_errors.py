"""WorkbenchError keeps its field as data and builds its message; no code edits message text."""

from __future__ import annotations

import ast
import pickle
from pathlib import Path

import pytest

import workbench.errors as errors_module
from workbench.cad.flat_pattern import FlatPatternError
from workbench.errors import (
    InputError,
    MeshError,
    ProjectError,
    UnreachableError,
    WorkbenchError,
    join_field,
)

ROOT = Path(__file__).resolve().parents[1]

# -- the error's field ---------------------------------------------------------------------


def test_the_field_is_kept_and_the_message_built_from_it() -> None:
    exc = InputError("must be > 0 m, got -1", field="cell.objects[2].pose.xyz")
    assert exc.field == "cell.objects[2].pose.xyz"
    assert exc.detail == "must be > 0 m, got -1"
    assert str(exc) == "cell.objects[2].pose.xyz: must be > 0 m, got -1"
    assert exc.args == ("cell.objects[2].pose.xyz: must be > 0 m, got -1",)
    assert isinstance(exc, ValueError)  # InputError stays a ValueError (pydantic validators)


def test_without_a_field_the_message_is_the_detail() -> None:
    for exc in (InputError("bad"), InputError("bad", field=None), InputError("bad", field="")):
        assert exc.field is None and exc.detail == "bad" and str(exc) == "bad"
    assert str(WorkbenchError()) == ""


def test_within_re_roots_the_field_and_keeps_class_detail_and_cause() -> None:
    try:
        try:
            raise ValueError("numpy said no")
        except ValueError as low:
            raise MeshError("is 1000x off", field="units") from low
    except MeshError as exc:
        caught = exc
    out = caught.within("polishing")
    assert type(out) is MeshError
    assert (out.field, out.detail, str(out)) == (
        "polishing.units",
        "is 1000x off",
        "polishing.units: is 1000x off",
    )
    assert out.__cause__ is caught and isinstance(caught.__cause__, ValueError)
    assert (caught.field, str(caught)) == ("units", "units: is 1000x off")  # the original stays


def test_within_without_a_field_makes_the_prefix_the_field() -> None:
    out = InputError("no IK solution").within("move 3 (P1)")
    assert (out.field, str(out)) == ("move 3 (P1)", "move 3 (P1): no IK solution")


def test_nested_within_builds_the_whole_path() -> None:
    exc = UnreachableError("out of reach", field="xyz")
    out = exc.within("pose").within("[2]").within("cell.objects")
    assert out.field == "cell.objects[2].pose.xyz"
    assert str(out) == "cell.objects[2].pose.xyz: out of reach"
    # The slow obvious twin: paste the path together by hand.
    assert str(out) == "cell.objects" + "[2]" + ".pose" + ".xyz" + ": " + "out of reach"


@pytest.mark.parametrize(
    ("prefix", "field", "path"),
    [("a", None, "a"), ("a", "b", "a.b"), ("a", "[0]", "a[0]"), ("a.b", "c[1].d", "a.b.c[1].d")],
)
def test_join_field(prefix: str, field: str | None, path: str) -> None:
    assert join_field(prefix, field) == path


def test_raising_within_chains_to_the_original() -> None:
    def inner() -> None:
        raise InputError("must be > 0", field="step")

    with pytest.raises(InputError) as err:
        try:
            inner()
        except InputError as exc:
            raise exc.within("polishing") from exc
    assert str(err.value) == "polishing.step: must be > 0"
    cause = err.value.__cause__
    assert isinstance(cause, InputError) and str(cause) == "step: must be > 0"
    assert cause.__traceback__ is not None  # the original raise is still shown


def test_project_error_problems_take_the_field() -> None:
    exc = ProjectError("no flange 'F9'", field="base")
    assert exc.problems == [("base", "no flange 'F9'")]
    out = exc.within("bending.part_import")
    assert str(out) == "bending.part_import.base: no flange 'F9'"
    assert out.problems == [("bending.part_import.base", "no flange 'F9'")]
    assert exc.problems == [("base", "no flange 'F9'")]
    listed = ProjectError("2 problem(s)", [("(top level)", "x"), ("(file)", "y"), ("a[1]", "z")])
    assert listed.within("p").problems == [("p", "x"), ("(file)", "y"), ("p.a[1]", "z")]
    assert ProjectError("plain").problems == []


def test_project_error_of_keeps_field_and_detail() -> None:
    inner = InputError("no flange 'F9'", field="base").within("bending.part_import")
    out = ProjectError.of(inner)
    assert type(out) is ProjectError
    assert str(out) == "bending.part_import.base: no flange 'F9'"
    assert out.problems == [("bending.part_import.base", "no flange 'F9'")]


def test_flat_pattern_error_is_the_base_with_a_field() -> None:
    exc = FlatPatternError("bend 1: inner radius must be > 0", field="bending.part_file")
    assert str(exc) == "bending.part_file: bend 1: inner radius must be > 0"
    assert exc.within("x").field == "x.bending.part_file"
    assert isinstance(exc, InputError)


def test_errors_pickle_with_their_field() -> None:
    for exc in (
        InputError("bad", field="a.b"),
        ProjectError("bad", field="a"),
        FlatPatternError("bad", field="f"),
    ):
        back = pickle.loads(pickle.dumps(exc))
        assert type(back) is type(exc)
        assert (back.field, back.detail, str(back)) == (exc.field, exc.detail, str(exc))


# -- no message surgery --------------------------------------------------------------------

#: Left for the lead: another helper moves their code to the domain (issue 26, part 4); the
#: lead converts what remains after merging. A file here that no longer exists fails the test.
NOT_YET: set[str] = set()
#: Methods that edit or take apart a text.
_EDITS = {"replace", "removeprefix", "removesuffix", "split", "rsplit", "partition", "rpartition"}
_ERROR_TYPES = {
    n for n, v in vars(errors_module).items() if isinstance(v, type) and issubclass(v, Exception)
} | {"FlatPatternError", "Busy"}


def _error_names(node: ast.AST | None) -> set[str]:
    return (
        {n.id for n in ast.walk(node) if isinstance(n, ast.Name)} & _ERROR_TYPES if node else set()
    )


class _Scanner(ast.NodeVisitor):
    """Find code that edits or searches the text of a workbench error."""

    def __init__(self) -> None:
        self.found: list[tuple[int, str]] = []
        self.excs: list[set[str]] = [set()]  # names bound to a workbench error, per scope
        self.texts: list[set[str]] = [set()]  # names bound to such an error's text

    def _is_text(self, node: ast.AST) -> bool:
        """Return whether `node` is the text of a workbench error in scope."""
        excs, texts = self.excs[-1], self.texts[-1]
        if isinstance(node, ast.Name):
            return node.id in texts
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
            if node.func.id in ("str", "repr", "format"):
                return any(
                    {n.id for n in ast.walk(a) if isinstance(n, ast.Name)} & excs for a in node.args
                )
        if isinstance(node, ast.JoinedStr):
            return any(
                isinstance(v, ast.FormattedValue)
                and isinstance(v.value, ast.Name)
                and v.value.id in excs
                for v in node.values
            )
        if isinstance(node, ast.Attribute) and node.attr in ("detail", "args"):
            return isinstance(node.value, ast.Name) and node.value.id in excs
        if isinstance(node, ast.Subscript):
            return self._is_text(node.value)
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
            return node.func.attr in ("strip", "lower", "casefold") and self._is_text(
                node.func.value
            )
        return False

    def visit_FunctionDef(self, node: ast.FunctionDef | ast.AsyncFunctionDef) -> None:
        params = node.args.posonlyargs + node.args.args + node.args.kwonlyargs
        excs = {a.arg for a in params if _error_names(a.annotation)}
        self.excs.append(self.excs[-1] | excs)
        self.texts.append(set(self.texts[-1]))
        self.generic_visit(node)
        self.excs.pop()
        self.texts.pop()

    visit_AsyncFunctionDef = visit_FunctionDef  # type: ignore[assignment]

    def visit_ExceptHandler(self, node: ast.ExceptHandler) -> None:
        excs = self.excs[-1] - {node.name}  # the handler's name is its own error
        if node.name and _error_names(node.type):
            excs |= {node.name}
        self.excs.append(excs)
        self.generic_visit(node)
        self.excs.pop()

    def visit_Assign(self, node: ast.Assign) -> None:
        if self._is_text(node.value):
            for t in node.targets:
                self.texts[-1] |= {n.id for n in ast.walk(t) if isinstance(n, ast.Name)}
        self.generic_visit(node)

    def visit_Call(self, node: ast.Call) -> None:
        f = node.func
        if isinstance(f, ast.Attribute) and f.attr in _EDITS and self._is_text(f.value):
            self.found.append((node.lineno, f"edits an error's text with .{f.attr}()"))
        self.generic_visit(node)

    def visit_Compare(self, node: ast.Compare) -> None:
        for op, right in zip(node.ops, node.comparators, strict=True):
            if isinstance(op, ast.In | ast.NotIn) and self._is_text(right):
                self.found.append((node.lineno, "searches an error's text for words"))
        self.generic_visit(node)


def message_surgery(source: str) -> list[tuple[int, str]]:
    """Return (line, what) for each place in `source` that edits or searches an error's text."""
    scanner = _Scanner()
    scanner.visit(ast.parse(source))
    return scanner.found


def test_no_module_edits_or_searches_an_error_message() -> None:
    assert all((ROOT / p).is_file() for p in NOT_YET), (
        "a file left for the move is gone: update NOT_YET"
    )
    found = [
        f"{path.relative_to(ROOT)}:{line}: {what}"
        for path in sorted((ROOT / "workbench").rglob("*.py"))
        if str(path.relative_to(ROOT)) not in NOT_YET
        for line, what in message_surgery(path.read_text(encoding="utf-8"))
    ]
    assert found == [], (
        "set the field where the error is raised, re-root with within():\n" + "\n".join(found)
    )


PLANTED = {
    "removeprefix": """
from workbench.errors import InputError
def f():
    try:
        g()
    except InputError as exc:
        raise InputError(str(exc).removeprefix("base: ")) from None
""",
    "replace in a helper": """
def scrub(exc: WorkbenchError, real: str) -> WorkbenchError:
    return type(exc)(str(exc).replace(real, "x"))
""",
    "searched for words": """
def f():
    try:
        g()
    except (MeshError, InputError) as exc:
        msg = str(exc)
        units_off = "units" in msg and "1000x" in msg
""",
    "detail split": """
def f():
    try:
        g()
    except WorkbenchError as err:
        head, _, rest = err.detail.partition(": ")
""",
    "f-string stripped": """
def f():
    try:
        g()
    except ProjectError as e:
        text = f"{e}".strip().split(": ", 1)[1]
""",
}


@pytest.mark.parametrize("name", sorted(PLANTED))
def test_the_scanner_catches_a_planted_example(name: str) -> None:
    assert message_surgery(PLANTED[name]), name


def test_the_scanner_passes_building_and_embedding() -> None:
    clean = """
def f():
    try:
        g()
    except InputError as exc:
        raise exc.within("polishing") from exc
    except MeshError as exc:
        raise ProjectError.of(exc.within("part"))
    except OSError as exc:  # a foreign error's text may be embedded and parsed
        code = str(exc).split(" ", 1)[0]
        raise InputError(f"cannot read ({exc})", field="part_file") from None
    try:
        g()
    except InputError as exc:
        said = exc.detail if exc.field == "bend sequence" else str(exc)
        show(f"bend: {said}", str(exc).strip().splitlines())
"""
    assert message_surgery(clean) == []
