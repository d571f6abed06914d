"""What the tests of crux.gym's environments (test_gym.py, test_vector_climb_env.py) try
them at: each integer argument at its extremes, from the ranges crux.gym checks them
against, and every operation of a closed environment."""

import inspect
import json

import gymnasium
import numpy as np
import pytest

import crux
import crux.gym

# What a hostile caller gives an integer argument, beside each range's ends and just beyond.
HOSTILE_INTEGERS = (0, -1, 2**31, 2**63, 2**64)


def integer_arguments(cls):
    """cls's constructor's integer arguments: those crux.gym bounds. Each parameter whose
    default is an integer must be one, so that an argument added later is walked too."""
    parameters = inspect.signature(cls).parameters
    for name, parameter in parameters.items():
        default = parameter.default
        if isinstance(default, int) and not isinstance(default, bool):
            assert name in crux.gym._INTEGER_ARGUMENTS, f"{cls.__name__}({name}=...) has no range in _INTEGER_ARGUMENTS"
    return [name for name in crux.gym._INTEGER_ARGUMENTS if name in parameters]


def integer_walk(name):
    """The values an integer argument is tried at, each with whether it is in range: its
    range's ends, just beyond each, the hostile ones, and the in-range ones again as numpy
    integers."""
    low, high = crux.gym._INTEGER_ARGUMENTS[name]
    values = sorted({low - 1, low, high, high + 1, *HOSTILE_INTEGERS})
    values += [np.int64(v) for v in values if low <= v <= high and v < 2**63]
    return [(value, low <= value <= high) for value in values]


def refusal(name, value):
    """The start and end of the ValueError that refuses `value` for the argument `name`."""
    low, high = crux.gym._INTEGER_ARGUMENTS[name]
    return rf"^{name}: .*an integer from {low} to {high}, got {value}$"


def start_holds_alone():
    """Random wall 7 with its four start holds alone: each state offers one candidate, the
    hold the free limb left, so that the least max_candidates climbs it."""
    wall = json.loads(crux.Wall.random(7).to_json())
    held = set(wall["start"].values())
    wall["holds"] = [hold for hold in wall["holds"] if hold["id"] in held]
    return crux.Wall.from_json(json.dumps(wall))


def public_operations(cls):
    """The public methods and properties crux.gym gives cls, but close() and the
    close_extras() that Gymnasium's VectorEnv.close calls."""
    names = set()
    for owner in cls.__mro__:
        if owner.__module__ == crux.gym.__name__:
            names |= {name for name, value in vars(owner).items() if callable(value) or isinstance(value, property)}
    return sorted(name for name in names if not name.startswith("_") and name not in ("close", "close_extras"))


def operate(env, name):
    """Reads the property `name` of env, or calls the method with no arguments: a closed
    environment refuses before it looks at them."""
    if isinstance(getattr(type(env), name), property):
        return getattr(env, name)
    return getattr(env, name)()


def check_every_operation_refused_once_closed(cls, make):
    """Each public operation of an environment `make()` builds, closed twice (harmlessly)
    with or without a reset first, raises Gymnasium's ClosedEnvironmentError naming cls."""
    closed = rf"^crux.gym.{cls.__name__} is closed \(close\(\) was called\): make a new one$"
    operations = public_operations(cls)
    for reset_first in (True, False):
        env = make()
        if reset_first:
            env.reset(seed=0)
        env.close()
        env.close()  # harmless
        for name in operations:
            with pytest.raises(gymnasium.error.ClosedEnvironmentError, match=closed):
                operate(env, name)
    return operations
