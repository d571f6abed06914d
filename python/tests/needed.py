"""What a test module needs beyond crux: the tests skip, saying so, when it is not
importable (a newcomer's clone without ../shared beside it), and fail instead under CI
(CI=true), which always has it."""

import importlib
import os

import pytest

GYMNASIUM = (
    "crux.gym's tests need Gymnasium's source in ../shared/third_party/gymnasium-1.4.0 and Debian's "
    "python3-cloudpickle and python3-typing-extensions"
)


def need(names, why):
    """The modules `names`, imported; otherwise a skip (or, under CI, an ImportError) naming `why`."""
    modules = []
    for name in names:
        try:
            modules.append(importlib.import_module(name))
        except ImportError as error:
            reason = f"{why} ({error})"
            if os.environ.get("CI") == "true":
                raise ImportError(f"under CI: {reason}") from error
            pytest.skip(reason, allow_module_level=True)
    return modules
