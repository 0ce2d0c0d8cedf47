"""Every public class, function, method and property of the package has a docstring beyond
pybind11's generated signature."""

import inspect
import re

import thyrix
import thyrix.envs


SIGNATURE = re.compile(r"^(\d+\. )?\w+\(.*\) -> \S+$")


def described(obj):
    """True when the docstring has a line that is not one of pybind11's signatures."""
    doc = inspect.getdoc(obj) or ""
    return any(line.strip() and not SIGNATURE.match(line) and line.strip() != "Overloaded function."
               for line in doc.splitlines())


def public_members(namespace):
    for name, member in vars(namespace).items():
        if (name.startswith("_") and name != "__init__") or name in ("name", "value"):
            continue
        yield name, member


def test_everything_public_is_documented():
    missing = []
    for module in (thyrix, thyrix.envs):
        for name, member in public_members(module):
            if inspect.ismodule(member) or not (inspect.isclass(member) or callable(member)):
                continue
            if getattr(member, "__module__", "thyrix").split(".")[0] != "thyrix":
                continue
            if not described(member):
                missing.append(f"{module.__name__}.{name}")
            if inspect.isclass(member):
                for attribute, value in public_members(member):
                    if attribute == "__init__" and hasattr(member, "__members__"):
                        continue  # an enumeration's, written by pybind11
                    if callable(value) or isinstance(value, property):
                        if not described(value):
                            missing.append(f"{module.__name__}.{name}.{attribute}")
    assert missing == []
