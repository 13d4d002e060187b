"""docs/api.md matches the code, and each package's `__all__` says what is public.

The page is read as the code would be: every backticked reference (`wb.bending.plan`,
`Workbench.open`, `sheetmetal.k_factor`, `MotionPlan.samples`, a class name, a return type
after `->`) must exist; every public name of `Workbench`, of its four services and of each
package's `__all__`, and every error class, must be on the page; a simple return type
written on the page (`-> EnginePathReport | None`) must be the one the code annotates.
"""

from __future__ import annotations

import ast
import builtins
import dataclasses
import functools
import importlib
import inspect
import pkgutil
import re
import subprocess
import sys
import textwrap
import typing
from pathlib import Path
from types import ModuleType
from typing import Any

import numpy as np
import pytest

import workbench
import workbench.errors
from workbench.kinematics.robot_library import preset_robot
from workbench.service import (
    AssemblyService,
    BendingService,
    CalibrationService,
    CollisionService,
    PolishingService,
    Workbench,
)

API = Path(__file__).resolve().parents[1] / "docs" / "api.md"
PACKAGES = (
    "geometry",
    "kinematics",
    "calibration",
    "motion",
    "motion.programs",
    "collision",
    "sheetmetal",
    "pressbrake",
    "assembly",
    "assembly.planners",
    "polishing",
    "project",
    "service",
)
SERVICES = {
    "collision": CollisionService,
    "bending": BendingService,
    "assembly": AssemblyService,
    "polishing": PolishingService,
    "calibration": CalibrationService,
}
SHORT = {p.split(".")[0] for p in PACKAGES} | {"errors"}
FOREIGN = {"np", "trimesh", "pin", "fcl", "ruckig"}  # other libraries' names: not checked
BUILTIN_TYPES = {"Any", "Path", *dir(builtins)}
DOTTED = re.compile(r"^([A-Za-z_]\w*(?:\.[A-Za-z_]\w*)+)")
CLASS_WORD = re.compile(r"^[A-Z][A-Za-z0-9]*[a-z][A-Za-z0-9]*$")
RETURNS = re.compile(r"->\s*([A-Z][A-Za-z0-9_]*)")
SIMPLE_TYPE = re.compile(r"^[A-Z][A-Za-z0-9_]+(?: \| None)?$")


# -- reading the page ------------------------------------------------------------------------
@functools.cache
def _spans() -> tuple[str, ...]:
    text = API.read_text()
    return tuple(" ".join(s.split()) for s in re.findall(r"`([^`]+)`", text))


def _short(ref: str) -> str:
    """Return `ref` with a leading `workbench.<package>` written as `<package>`."""
    parts = ref.split(".")
    if parts[0] == "workbench" and len(parts) > 1 and parts[1] in SHORT:
        return ".".join(parts[1:])
    return ref


@functools.cache
def _references() -> tuple[str, ...]:
    return tuple(m.group(1) for s in _spans() if (m := DOTTED.match(s)))


@functools.cache
def _mentioned() -> frozenset[str]:
    """Return every reference on the page and each of its dotted prefixes."""
    out = set()
    for ref in map(_short, _references()):
        parts = ref.split(".")
        out |= {".".join(parts[: i + 1]) for i in range(len(parts))}
    return frozenset(out)


# -- reading the code ------------------------------------------------------------------------
@functools.cache
def _modules() -> tuple[ModuleType, ...]:
    found = [workbench]
    for info in pkgutil.walk_packages(workbench.__path__, "workbench."):
        if info.name.startswith(("workbench.gui", "workbench.__main__")):
            continue  # the GUI imports viser; it has no public names of its own here
        found.append(importlib.import_module(info.name))
    return tuple(found)


@functools.cache
def _defined() -> dict[str, list[Any]]:
    """Return the classes defined in workbench modules and the names of `__all__`, by name."""
    out: dict[str, list[Any]] = {}
    for mod in _modules():
        for name, value in vars(mod).items():
            if inspect.isclass(value) and value.__module__ == mod.__name__:
                out.setdefault(name, []).append(value)
        for name in getattr(mod, "__all__", ()):
            out.setdefault(name, []).append(getattr(mod, name))
    return out


def _instance_attributes(cls: type) -> set[str]:
    """Return the public `self.<name> = ...` attributes assigned in the class's source."""
    try:
        tree = ast.parse(textwrap.dedent(inspect.getsource(cls)))
    except (OSError, TypeError):
        return set()
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign):
            targets = list(node.targets)
        elif isinstance(node, (ast.AnnAssign, ast.AugAssign)):
            targets = [node.target]
        else:
            continue
        for target in targets:
            for t in target.elts if isinstance(target, ast.Tuple) else [target]:
                if (
                    isinstance(t, ast.Attribute)
                    and isinstance(t.value, ast.Name)
                    and t.value.id == "self"
                    and not t.attr.startswith("_")
                ):
                    names.add(t.attr)
    return names


@functools.cache
def _public(cls: Any) -> frozenset[str]:
    """Return the public names of `cls`: attributes, fields, annotations and instance attributes."""
    names = {n for n in dir(cls) if not n.startswith("_")}
    for klass in cls.__mro__:
        if klass.__module__.startswith("workbench."):
            names |= _instance_attributes(klass)
            names |= {n for n in inspect.get_annotations(klass) if not n.startswith("_")}
    if dataclasses.is_dataclass(cls):
        names |= {f.name for f in dataclasses.fields(cls) if not f.name.startswith("_")}
    return frozenset(names)


def _function(cls: type, name: str) -> Any:
    attr = inspect.getattr_static(cls, name, None)
    if isinstance(attr, property):
        return attr.fget
    if isinstance(attr, functools.cached_property):
        return attr.func
    if isinstance(attr, (classmethod, staticmethod)):
        return attr.__func__
    return attr if inspect.isfunction(attr) else None


def _member_type(cls: type, name: str) -> type | None:
    """Return the class a member of `cls` holds or returns (None: not a single class)."""
    fn = _function(cls, name)
    try:
        hints = typing.get_type_hints(fn if fn is not None else cls)
    except Exception:
        return None
    hint = hints.get("return" if fn is not None else name)
    args = [a for a in typing.get_args(hint) if a is not type(None)]
    if len(args) == 1 and type(None) in typing.get_args(hint):
        hint = args[0]
    return hint if inspect.isclass(hint) else None


def _annotation(cls: type, name: str) -> str | None:
    """Return the return annotation of a method or property of `cls` as written in the code."""
    fn = _function(cls, name)
    if fn is None:
        return None
    ann = inspect.signature(fn).return_annotation
    return ann if isinstance(ann, str) else getattr(ann, "__name__", None)


def _walk(obj: Any, names: list[str], ref: str) -> str | None:
    """Follow `names` from `obj`; return what is wrong, or None when every step exists."""
    for i, name in enumerate(names):
        last = i == len(names) - 1
        if isinstance(obj, ModuleType):
            if hasattr(obj, name):
                obj = getattr(obj, name)
                continue
            try:
                obj = importlib.import_module(f"{obj.__name__}.{name}")
            except ModuleNotFoundError:
                return f"{ref}: {obj.__name__} has no {name!r}"
        elif inspect.isclass(obj):
            if name not in _public(typing.cast(Any, obj)) and not hasattr(obj, name):
                return f"{ref}: {obj.__qualname__} has no {name!r}"
            if last:
                return None
            nxt = _member_type(obj, name)
            if nxt is None:
                return f"{ref}: cannot tell the type of {obj.__qualname__}.{name}"
            obj = nxt
        else:
            if not hasattr(obj, name):
                return f"{ref}: {obj!r:.60} has no {name!r}"
            obj = getattr(obj, name)
    return None


def _resolve(ref: str) -> str | None:
    root, *rest = _short(ref).split(".")
    if root in FOREIGN:
        return None
    if root == "wb":
        return _walk(Workbench, rest, ref)
    if root == "workbench":
        return _walk(workbench, rest, ref)
    if root in SHORT:
        return _walk(importlib.import_module(f"workbench.{root}"), rest, ref)
    if root in _defined():
        problems = [_walk(c, rest, ref) for c in _defined()[root]]
        return None if None in problems else problems[0]
    return f"{ref}: no package, class or `wb` named {root!r}"


def _owner(ref: str) -> tuple[type, str] | None:
    """Return (class, member) that a reference names, or None for a module-level name."""
    root, *rest = _short(ref).split(".")
    if not rest:
        return None
    if root == "wb":
        obj: Any = Workbench
    elif root in _defined() and root not in SHORT:
        obj = next((c for c in _defined()[root] if inspect.isclass(c)), None)
    else:
        return None
    for name in rest[:-1]:
        obj = _member_type(obj, name) if inspect.isclass(obj) else None
        if obj is None:
            return None
    return (obj, rest[-1]) if inspect.isclass(obj) else None


# -- the page names only what exists ---------------------------------------------------------
def test_every_reference_on_the_page_exists() -> None:
    problems = [p for ref in _references() if (p := _resolve(ref))]
    assert problems == []


def test_every_class_and_return_type_named_on_the_page_exists() -> None:
    words = {s for s in _spans() if CLASS_WORD.match(s)}
    words |= {m for s in _spans() for m in RETURNS.findall(s)}
    assert sorted(words - set(_defined()) - BUILTIN_TYPES) == []


def test_return_types_on_the_page_are_the_annotated_ones() -> None:
    wrong = []
    for span in _spans():
        m = DOTTED.match(span)
        if not m or "->" not in span:
            continue
        owner = _owner(m.group(1))
        written = span.split("->", 1)[1].strip()
        if owner is None or not SIMPLE_TYPE.match(written):
            continue
        code = _annotation(*owner)
        if code is not None and SIMPLE_TYPE.match(code) and written != code:
            wrong.append(f"{m.group(1)}: the page says {written}, the code {code}")
    assert wrong == []


# -- the page names everything public --------------------------------------------------------
def test_every_public_name_of_workbench_is_on_the_page() -> None:
    missing = [n for n in sorted(_public(Workbench)) if f"wb.{n}" not in _mentioned()]
    missing = [n for n in missing if f"Workbench.{n}" not in _mentioned()]
    assert missing == []


@pytest.mark.parametrize("section", sorted(SERVICES))
def test_every_public_name_of_each_service_is_on_the_page(section: str) -> None:
    cls = SERVICES[section]
    assert _member_type(Workbench, section) is cls
    missing = [n for n in sorted(_public(cls)) if f"wb.{section}.{n}" not in _mentioned()]
    assert missing == []


@pytest.mark.parametrize("package", PACKAGES)
def test_every_name_of_each_package_is_on_the_page(package: str) -> None:
    mod = importlib.import_module(f"workbench.{package}")
    missing = [n for n in mod.__all__ if f"{package}.{n}" not in _mentioned()]
    assert missing == []


def test_every_error_is_on_the_page() -> None:
    errors = [
        name
        for name, value in vars(workbench.errors).items()
        if inspect.isclass(value) and issubclass(value, Exception)
        if value.__module__ == "workbench.errors"
    ]
    assert [n for n in errors if f"errors.{n}" not in _mentioned()] == []


# -- each package's __all__ --------------------------------------------------------------------
@pytest.mark.parametrize("package", ("", *PACKAGES))
def test_every_name_in_all_is_importable(package: str) -> None:
    name = f"workbench.{package}" if package else "workbench"
    mod = importlib.import_module(name)
    names = list(mod.__all__)
    assert len(names) == len(set(names)), "a name is listed twice"
    assert [n for n in names if not hasattr(mod, n)] == []
    star: dict[str, Any] = {}
    exec(f"from {name} import *", star)
    assert set(names) <= set(star)


@pytest.mark.parametrize("package", PACKAGES)
def test_no_public_name_hides_a_module(package: str) -> None:
    # `from .check_cost import check_cost` in an __init__ would make
    # `import workbench.sheetmetal.check_cost as m` return the function, not the module.
    mod = importlib.import_module(f"workbench.{package}")
    modules = {m.name for m in pkgutil.iter_modules(mod.__path__)}
    assert sorted(modules & set(mod.__all__)) == []


@pytest.mark.parametrize(
    ("statement", "heavy"),
    [
        ("import workbench", ("pinocchio", "fcl", "trimesh")),
        ("import workbench.polishing as p; p.PATTERNS; p.HybridForceParams", ("trimesh", "scipy")),
    ],
)
def test_light_imports_stay_light(statement: str, heavy: tuple[str, ...]) -> None:
    code = f"import sys; {statement}; print(sorted(m for m in {heavy!r} if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_the_public_contract() -> None:
    # The names scripts and outside checks rely on (docs/api.md, top of each section).
    from workbench import Workbench as Wb
    from workbench import WorkbenchError
    from workbench.geometry import OBB, obb_overlap
    from workbench.sheetmetal import bend_allowance, k_factor

    assert Wb is Workbench and issubclass(workbench.errors.InputError, WorkbenchError)
    assert all(callable(getattr(Wb, n)) for n in ("open", "from_dict", "save"))
    assert isinstance(inspect.getattr_static(Wb, "project"), property)
    robot = preset_robot("mz07")
    q = np.array([0.1, -0.2, 0.3, 0.4, -0.5, 0.6])
    T = robot.fk(q)
    assert T.shape == (4, 4) and robot.fk(np.stack([q, q])).shape == (2, 4, 4)
    sols = robot.ik(T)
    assert sols.shape[1] == 6 and 1 <= len(sols) <= 8
    np.testing.assert_allclose(robot.fk(sols), np.broadcast_to(T, (len(sols), 4, 4)), atol=1e-9)
    box = OBB(np.zeros(3), np.eye(3), np.ones(3))
    assert bool(obb_overlap(box, box))
    assert float(bend_allowance(0.002, 0.002, 0.0)) == 0.0 and 0 < float(k_factor(1.0)) < 0.5
