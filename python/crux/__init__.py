"""crux: a virtual human that learns to climb walls of holds, and carries what it
learnt to walls it has never seen (Libeau, Micaelli, Sigaud), as a Python module.

The body, IK, walls, the climbing MDP with Gymnasium's step conventions (ClimbMdp; the
Gymnasium environment itself is crux.gym.ClimbEnv), the
paper's agent (run_learning) and experiment (run_experiment), a wall's exact shortest
climb (plan), every climb it allows (climb_graph) and a climb performed in MuJoCo
(perform), and Q-tables as numpy arrays. Bad input raises ValueError with the CLI's
error line; docs/PYTHON.md has the tour.
"""

from ._crux import (
    CONFIGURATION_DOF,
    LIMB_NAMES,
    ROOT_DOF,
    BodyModel,
    ClimbMdp,
    GridPlacement,
    IkResult,
    LearningRun,
    QTable,
    Wall,
    __version__,
    agent_state,
    climb_graph,
    config_keys,
    forward_kinematics,
    grid_state_space,
    hold_in_tile,
    passes_filter,
    perform,
    place_grid,
    plan,
    possible_actions,
    root_target,
    run_experiment,
    run_learning,
    solve_ik,
    wall_state,
)

__all__ = [
    "CONFIGURATION_DOF",
    "LIMB_NAMES",
    "ROOT_DOF",
    "BodyModel",
    "ClimbMdp",
    "GridPlacement",
    "IkResult",
    "LearningRun",
    "QTable",
    "Wall",
    "__version__",
    "agent_state",
    "climb_graph",
    "config_keys",
    "forward_kinematics",
    "grid_state_space",
    "hold_in_tile",
    "passes_filter",
    "perform",
    "place_grid",
    "plan",
    "possible_actions",
    "root_target",
    "run_experiment",
    "run_learning",
    "solve_ik",
    "wall_state",
]


def __getattr__(name):
    # crux.ClimbEnv was the raw MDP's name until crux.gym.ClimbEnv, the Gymnasium
    # environment, took it over: kept one release, deprecated.
    if name == "ClimbEnv":
        import warnings

        warnings.warn("crux.ClimbEnv is now crux.ClimbMdp (crux.gym.ClimbEnv is the Gymnasium environment); "
                      "the old name goes in the next release", DeprecationWarning, stacklevel=2)
        return ClimbMdp
    raise AttributeError(f"module 'crux' has no attribute {name!r}")
