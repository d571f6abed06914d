"""crux: a virtual human that learns to climb walls of holds, and carries what it
learnt to walls it has never seen (Libeau, Micaelli, Sigaud), as a Python module.

The body, IK, walls, the climbing MDP as a Gymnasium-style environment (ClimbEnv), the
paper's agent (run_learning) and experiment (run_experiment), and Q-tables as numpy
arrays. Bad input raises ValueError with the CLI's error line; docs/PYTHON.md has the
tour.
"""

from ._crux import (
    CONFIGURATION_DOF,
    LIMB_NAMES,
    ROOT_DOF,
    BodyModel,
    ClimbEnv,
    GridPlacement,
    IkResult,
    LearningRun,
    QTable,
    Wall,
    __version__,
    agent_state,
    config_keys,
    forward_kinematics,
    grid_state_space,
    hold_in_tile,
    passes_filter,
    place_grid,
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
    "ClimbEnv",
    "GridPlacement",
    "IkResult",
    "LearningRun",
    "QTable",
    "Wall",
    "__version__",
    "agent_state",
    "config_keys",
    "forward_kinematics",
    "grid_state_space",
    "hold_in_tile",
    "passes_filter",
    "place_grid",
    "possible_actions",
    "root_target",
    "run_experiment",
    "run_learning",
    "solve_ik",
    "wall_state",
]
