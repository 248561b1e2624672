"""docs/python.md lists every public name with its type, and help() shows the types."""

import inspect

import swarmagg as sa
from conftest import ROOT

REFERENCE = (ROOT / "docs" / "python.md").read_text()
CLASSES = [sa.World, sa.Simulation, sa.Run, sa.Rates, sa.Sweep]


def public(cls):
    names = {n for n in dir(cls) if not n.startswith("_")}
    if cls is sa.Sweep:
        names |= {"out"}  # an instance attribute
    return sorted(names)


def test_every_public_name_is_in_the_reference():
    missing = [n for n in sa.__all__ if f"`{n}" not in REFERENCE]
    for cls in CLASSES:
        missing += [f"{cls.__name__}.{n}" for n in public(cls) if f"`{n}" not in REFERENCE]
    assert not missing, f"not in docs/python.md: {missing}"


def test_help_shows_the_types_of_every_function():
    for name in sa.__all__:
        thing = getattr(sa, name)
        if not callable(thing) or inspect.isclass(thing):
            continue
        if inspect.isfunction(thing):  # written in Python: annotated
            signature = inspect.signature(thing)
            assert signature.return_annotation is not inspect.Signature.empty, name
            assert all(p.annotation is not inspect.Parameter.empty
                       for p in signature.parameters.values()), name
        else:  # bound in C++: pybind11 writes the signature with its types
            assert "->" in thing.__doc__.splitlines()[0], name
    for cls in CLASSES:
        for name in public(cls):
            member = inspect.getattr_static(cls, name, None)
            if member is not None:
                assert (getattr(member, "__doc__", None) or "").strip(), f"{cls.__name__}.{name}"
