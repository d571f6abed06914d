"""crux.gym: the climbing MDP as a Gymnasium environment, `crux/Climb-v0`.

Imported only when wanted (`import crux.gym`), so that `import crux` needs no Gymnasium.
Importing it registers `crux/Climb-v0`; `gymnasium.make("crux/Climb-v0", ...)` passes
its keyword arguments to `ClimbEnv`, and `gymnasium.make_vec("crux/Climb-v0", num_envs,
vectorization_mode="vector_entry_point", ...)` to `VectorClimbEnv`, which steps them all
in one call into C++. docs/PYTHON.md describes the observation forms, their bounds, the
actions and the walls.
"""

import copy
import functools
import operator
import os

import gymnasium
import numpy as np
from gymnasium import spaces
from gymnasium.utils import seeding
from gymnasium.vector import AutoresetMode
from gymnasium.vector.utils import batch_space

from . import _crux

ENV_ID = "crux/Climb-v0"
# What TimeLimit allows an episode, the old crux.ClimbMdp's default max_steps.
MAX_EPISODE_STEPS = 1000
OBSERVATION_FORMS = ("numeric", "reach", "paper")
WALL_ORDERS = ("cycle", "sample")
RESET_OPTIONS = ("wall",)
# 40,000 random steps on the paper's random walls (4 x 8 tiles) met at most 27
# candidates; denser walls may need more (ValueError naming max_candidates otherwise).
DEFAULT_MAX_CANDIDATES = 32
# The most holds crux takes on a wall (kMaxHoldCount, src/wall/wall.hpp).
_MAX_HOLDS = 10000
# Random walls whose start cannot be taken, skipped in a row before the wall_config is
# refused: under the defaults about 1 in 1000 is, so this many means the config makes none.
_MAX_SKIPPED_WALLS = 1000

# The integer arguments of ClimbEnv and VectorClimbEnv and the range each is checked
# against where Python receives it, from what it feeds: (lowest, highest).
_INTEGER_ARGUMENTS = {
    # A slot per candidate hold, and a state offers at most its wall's holds.
    "max_candidates": (1, _MAX_HOLDS),
    # crux.Wall.random's seed is a uint64 (also each seed of a list, of wall_split and of
    # reset's options["wall"]).
    "wall": (0, 2**64 - 1),
    # Each environment keeps its own episode (MDP, posture cache, kinematics workspace):
    # 2**16 of them took 2.3 GB and 10 s to reset on the paper's wall 7 (measured), and
    # grow as they explore: what a workstation's memory holds (C++'s 2**20 would be 36 GB).
    "num_envs": (1, 2**16),
    # The C++ step count it is compared with is a C int.
    "max_episode_steps": (1, 2**31 - 1),
}
# The numeric form's candidate slots, num_envs x max_candidates, take 25 bytes each in a
# batch (features, mask, hold index, action mask) and 32 in the batched observation
# space's bounds: at most 2**22 of them (240 MB), 2**16 environments of 64 candidates.
_MAX_BATCH_SLOTS = 2**22


# rgb_array's colours are those of crux's SVG views (src/views/palette.hpp, wall_svg.cpp),
# so that a frame reads as `crux view` and `crux wall show` do: each limb its own
# Okabe-Ito colour (right hand vermillion, left hand blue, right foot orange, left foot
# reddish purple, in limb order), so left tells from right; held holds dark, other holds
# grey, and the holds a move may take in the palette's bluish green.
_LIMB_COLOURS = ("#d55e00", "#0072b2", "#e69f00", "#cc79a7")
_TRUNK_COLOUR = "#77624f"  # the URDF's crux_skin, as the body view strokes it
_HELD_HOLD_COLOUR = "#222222"
_POSSIBLE_HOLD_COLOUR = "#009e73"
_OTHER_HOLD_COLOUR = "#bbbbbb"
_FINISH_COLOUR = "#444444"
_COM_COLOUR = "#111111"
_RGB_WALL_WIDTH = 2 / 3  # of the frame's width; the legend takes the rest
# A limb's joints by name (the default body's): its side, then these words.
_LIMB_JOINT_WORDS = {"hand": ("shoulder", "elbow", "forearm", "wrist"), "foot": ("hip", "knee", "ankle")}


def _integer(value, argument, bounds=None, must_be="must be"):
    """value as an int if it is an integer (not a bool, nor a float even if whole, as for
    step's action) within the range _INTEGER_ARGUMENTS gives `bounds` (by default
    `argument`); otherwise a ValueError naming argument and the range."""
    low, high = _INTEGER_ARGUMENTS[bounds or argument]
    if isinstance(value, (int, np.integer)) and not isinstance(value, bool) and low <= int(value) <= high:
        return int(value)
    raise ValueError(f"{argument}: {must_be} an integer from {low} to {high}, got {value!r}")


def _check_options(options):
    if options is not None and not isinstance(options, dict):
        raise ValueError("options: must be a dict or None")
    for name in options or ():
        if name not in RESET_OPTIONS:
            raise ValueError(f"options: unknown option {name!r} ({', '.join(RESET_OPTIONS)})")


def _open_only(method):
    """method (or a property's getter) refused once close() has run, with the error
    Gymnasium's AsyncVectorEnv raises then."""

    @functools.wraps(method)
    def checked(self, *args, **kwargs):
        if self.closed:
            raise gymnasium.error.ClosedEnvironmentError(
                f"crux.gym.{type(self).__name__} is closed (close() was called): make a new one"
            )
        return method(self, *args, **kwargs)

    return checked


def _joint_limbs(joint_names):
    """Each joint's limb (its index in crux.LIMB_NAMES), or -1 for the root, trunk and head."""
    limb_of = {}
    for limb, limb_name in enumerate(_crux.LIMB_NAMES):
        side, part = limb_name.split("_")
        for word in _LIMB_JOINT_WORDS[part]:
            limb_of[f"{side}_{word}"] = limb
    return [next((limb for prefix, limb in limb_of.items() if name.startswith(prefix)), -1) for name in joint_names]


def _rgb_legend(finish_height):
    """The rgb_array frame's legend: what each colour and marker stands for."""
    from matplotlib.lines import Line2D

    def line(colour, label, **style):
        return Line2D([], [], color=colour, label=label, **style)

    limbs = [line(c, name.replace("_", " "), linewidth=3) for name, c in zip(_crux.LIMB_NAMES, _LIMB_COLOURS)]
    holds = [
        line(c, label, marker="o", linestyle="", markersize=6)
        for label, c in (("held hold", _HELD_HOLD_COLOUR), ("possible hold", _POSSIBLE_HOLD_COLOUR),
                         ("other hold", _OTHER_HOLD_COLOUR))
    ]
    return [
        *limbs,
        line(_TRUNK_COLOUR, "trunk, head", linewidth=3),
        *holds,
        line(_COM_COLOUR, "centre of mass", marker="x", linestyle="", markersize=7),
        line(_FINISH_COLOUR, f"finish, {finish_height:.2f} m", linestyle="--", linewidth=1),
    ]


def _plot_segment(axes, ends, colour):
    """A bone of the skeleton from its two ends (world points), as seen on the wall (y, z)."""
    axes.plot(ends[:, 1], ends[:, 2], color=colour, linewidth=3, zorder=2, solid_capstyle="round")


class MaskedDiscrete(spaces.Discrete):
    """Discrete(n) whose sample() with no mask draws among the actions the current state
    offers (the environment keeps `offered` up to date), so that a random agent, and
    Gymnasium's own checks, only take possible actions."""

    def __init__(self, n, seed=None):
        super().__init__(n, seed=seed)
        self.offered = np.ones(n, dtype=np.int8)

    def sample(self, mask=None, probability=None):
        if mask is None and probability is None:
            mask = self.offered
        return super().sample(mask=mask, probability=probability)


def _wall_key(wall):
    """What makes two walls the same wall whatever their names."""
    return (wall.positions.tobytes(), wall.radii.tobytes(), wall.start.tobytes(), wall.finish_height)


class _FixedWalls:
    """A list of walls, taken in turn or drawn at random at each reset."""

    def __init__(self, walls, order):
        self.walls = walls
        self.order = order
        self.next = 0

    def restart(self):
        self.next = 0

    def draw(self, rng):
        if self.order == "sample":
            index = int(rng.integers(len(self.walls)))
        else:
            index = self.next
            self.next = (self.next + 1) % len(self.walls)
        return index, self.walls[index]

    def hold_counts(self):
        return {wall.hold_count for wall in self.walls}


class _RandomWalls:
    """A new random wall at each reset, its seed drawn from the environment's np_random. A
    wall whose start the climber cannot take (about 1 in 1000 under the defaults) is
    skipped, the next seed drawn, so that an episode never fails to start; start_holds
    tells, by building the wall's MDP as the episode will."""

    def __init__(self, wall_config, start_holds):
        self.wall_config = wall_config
        self.start_holds = start_holds
        self.example = _crux.Wall.random(0, wall_config)

    def restart(self):
        pass

    def draw(self, rng):
        for _ in range(_MAX_SKIPPED_WALLS):
            seed = int(rng.integers(2**63))
            wall = _crux.Wall.random(seed, self.wall_config)
            if self.start_holds(wall):
                return seed, wall
        raise ValueError(
            f"wall_config: {_MAX_SKIPPED_WALLS} random walls in a row have a start the climber cannot take "
            f"(the last: {wall.name})"
        )

    def hold_counts(self):
        return {self.example.hold_count}


def _wall_from(item, wall_config, argument):
    if isinstance(item, _crux.Wall):
        return item
    if isinstance(item, (str, os.PathLike)):
        return _crux.Wall.load(item)
    if isinstance(item, (int, np.integer)) and not isinstance(item, bool):
        return _crux.Wall.random(_integer(item, argument, "wall", "a random wall's seed must be"), wall_config)
    raise ValueError(f"{argument}: holds {item!r}, which is not a crux.Wall, a wall file or a random wall's seed")


def _wall_list(items, wall_config, argument):
    if isinstance(items, (str, os.PathLike, _crux.Wall, int, np.integer)):
        items = [items]
    try:
        items = list(items)
    except TypeError:
        raise ValueError(f"{argument}: must be a wall, a wall file, a seed or a list of them, got {items!r}") from None
    walls = [_wall_from(item, wall_config, argument) for item in items]
    if not walls:
        raise ValueError(f"{argument}: is an empty list of walls")
    return walls


def _split_side(wall_split, evaluation, wall_config):
    if not isinstance(wall_split, dict) or set(wall_split) != {"train", "evaluation"}:
        raise ValueError('wall_split: must be a dict {"train": walls, "evaluation": walls}')
    train = _wall_list(wall_split["train"], wall_config, "wall_split")
    held_out = _wall_list(wall_split["evaluation"], wall_config, "wall_split")
    held_out_keys = {_wall_key(wall): wall.name for wall in held_out}
    for wall in train:
        if _wall_key(wall) in held_out_keys:
            raise ValueError(
                f"wall_split: the training wall '{wall.name}' is also an evaluation wall "
                f"('{held_out_keys[_wall_key(wall)]}'): the split overlaps"
            )
    return held_out if evaluation else train


def _next_wall(walls, rng, options, hold_count):
    """The wall of the next episode as (index, wall, seed): index that of a wall of a list
    (None for a random or a named wall, which serves that episode alone), seed a random
    wall's. hold_count: the paper form's action count, which a named wall must have
    (None: any)."""
    named = None if options is None else options.get("wall")
    if named is not None:
        wall = _wall_from(named, walls.wall_config if isinstance(walls, _RandomWalls) else None, "options")
        if hold_count is not None and wall.hold_count != hold_count:
            raise ValueError(
                f"options: the wall '{wall.name}' has {wall.hold_count} holds, not the {hold_count} "
                "hold indices of the action space"
            )
        return None, wall, int(named) if isinstance(named, (int, np.integer)) else None
    key, wall = walls.draw(rng)
    if isinstance(walls, _RandomWalls):
        return None, wall, key
    return key, wall, None


class ClimbEnv(gymnasium.Env):
    """The climbing MDP (paper, sections III-C and III-D) as a gymnasium.Env.

    wall: a crux.Wall, a wall file, a list of them (or of random walls' seeds), or None for
        a new random wall at every reset, drawn from the reset's seed with wall_config.
    observation: "numeric" (features relative to the free limb, any wall), "reach" (numeric
        and, per candidate, where it lies from the free limb's shoulder or hip and the held
        holds, and whether its move failed from this state) or "paper" (the paper's state
        codes; the action is then a hold index).
    wall_config: the wall.* keys of the random walls (None, wall, wall seeds) as crux.Wall.random takes them.
    wall_order: "cycle" or "sample", how a list of walls is taken at each reset.
    wall_split: {"train": walls, "evaluation": walls}, two lists that must not share a
        wall; the environment takes the evaluation walls when evaluation is true, the
        training walls otherwise. Instead of wall.
    config: the keys of config.toml's [reward], [ik], [physics], [filter] and [grid] tables, experiment.urdf and
        learning.gamma (the discount reward.height's shaping uses: the learner's own, 0.9 by default).
    max_candidates: the numeric form's action count, the most candidates a state may offer.
    model: a crux.BodyModel, or None for experiment.urdf's body or the default one.
    render_mode: None, "rgb_array" (the climber on the wall, each limb in its colour, with a
        legend; by matplotlib) or "ansi".
    """

    metadata = {"render_modes": ["rgb_array", "ansi"], "render_fps": 2}
    closed = False  # as gymnasium.vector.VectorEnv's: close() sets it

    def __init__(
        self,
        wall=None,
        observation="numeric",
        *,
        wall_config=None,
        wall_order="cycle",
        wall_split=None,
        evaluation=False,
        config=None,
        max_candidates=DEFAULT_MAX_CANDIDATES,
        model=None,
        render_mode=None,
    ):
        if observation not in OBSERVATION_FORMS:
            raise ValueError(f"observation: unknown form {observation!r} (numeric, reach, paper)")
        if wall_order not in WALL_ORDERS:
            raise ValueError(f"wall_order: unknown order {wall_order!r} (cycle, sample)")
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode: unknown mode {render_mode!r} (rgb_array, ansi)")
        self.max_candidates = _integer(max_candidates, "max_candidates")
        self.observation_form = observation
        self.render_mode = render_mode
        self._config = config
        self._model_argument = model
        if evaluation and wall_split is None:
            raise ValueError("evaluation: takes the evaluation walls of a wall_split, and there is none")
        if wall_split is not None:
            if wall is not None:
                raise ValueError("wall_split: give either wall or wall_split")
            self._walls = _FixedWalls(_split_side(wall_split, evaluation, wall_config), wall_order)
        elif wall is None:
            self._walls = _RandomWalls(wall_config, self._start_holds)
        else:
            self._walls = _FixedWalls(_wall_list(wall, wall_config, "wall"), wall_order)
        self._envs = {}  # per wall of a list: its crux.ClimbMdp, built once

        counts = self._walls.hold_counts()
        if observation == "paper" and len(counts) > 1:
            raise ValueError(
                f"wall: walls of different hold counts ({sorted(counts)}) have no common hold index: "
                "use observation='numeric'"
            )
        self._paper_hold_count = max(counts) if observation == "paper" else None
        # One environment up front: the config is checked, the body and the grid's size known.
        self._draw_wall(np.random.default_rng(0))
        self._walls.restart()
        self._model = self._env.model
        self._span = self._env.max_span
        self.action_space = MaskedDiscrete(max(counts) if observation == "paper" else self.max_candidates)
        self.observation_space = self._paper_space() if observation == "paper" else self._numeric_space()

    # --- spaces ---------------------------------------------------------------------

    def _paper_space(self):
        holds = self._env.action_count
        tiles = self._env.grid_action_count
        return spaces.Dict(
            {
                "wall_state": spaces.Discrete((holds + 1) ** 4),
                "grid_state": spaces.Discrete(4 * (tiles + 1) ** 3),
                "free_limb": spaces.Discrete(4),
            }
        )

    def _numeric_space(self):
        # The filter keeps the holds of a configuration within max_span of each other, the
        # free limb grasps (to the IK's tolerance) the hold it left, and the body's extent
        # is at most max_span: held holds, the root and the centre of mass are within
        # 2 max_span of the free limb's grasp point, candidates within 3 max_span. The
        # height left to the finish is clipped to the same bound.
        span = self._span
        k = self.max_candidates

        def box(bound, shape):
            return spaces.Box(-bound, bound, shape, dtype=np.float32)

        lower = np.concatenate([np.full(3, -2 * span), self._model.lower_limits[3:]]).astype(np.float32)
        upper = np.concatenate([np.full(3, 2 * span), self._model.upper_limits[3:]]).astype(np.float32)
        reach = {}
        if self.observation_form == "reach":
            # The shoulder or hip lies within s of the root, so within 3s of the grasp point,
            # and a candidate within 3s: 6s apart on each axis. A held hold lies within 2s:
            # 5s from a candidate on each axis. The norms follow.
            reach_lower = np.concatenate([np.full(3, -6 * span), np.zeros(4)]).astype(np.float32)
            reach_upper = np.concatenate([np.full(3, 6 * span), [6 * np.sqrt(3) * span], np.full(3, 5 * np.sqrt(3) * span)])
            reach = {
                "candidate_reach": spaces.Box(
                    np.tile(reach_lower, (k, 1)), np.tile(reach_upper.astype(np.float32), (k, 1)), dtype=np.float32
                ),
                "candidate_failed": spaces.Box(0.0, 1.0, (k,), dtype=np.float32),
            }
        return spaces.Dict(
            {
                "free_limb": spaces.Box(0.0, 1.0, (4,), dtype=np.float32),
                "held": box(2 * span, (4, 3)),
                "candidates": box(3 * span, (k, 3)),
                "candidate_mask": spaces.Box(0.0, 1.0, (k,), dtype=np.float32),
                "posture": spaces.Box(lower, upper, dtype=np.float32),
                "centre_of_mass": box(2 * span, (3,)),
                "to_finish": box(2 * span, (1,)),
                **reach,
            }
        )

    # --- walls ----------------------------------------------------------------------

    def _draw_wall(self, rng, options=None):
        index, wall, self.wall_seed = _next_wall(self._walls, rng, options, self._paper_hold_count)
        if index is None:
            self._env = self._climb_env(wall)
        else:
            if index not in self._envs:
                self._envs[index] = self._climb_env(wall)
            self._env = self._envs[index]

    def _climb_env(self, wall):
        return _crux.ClimbMdp(wall, config=self._config, max_steps=None, model=self._model_argument)

    def _start_holds(self, wall):
        try:
            self._climb_env(wall)
        except ValueError as error:
            if "the start configuration" not in str(error):
                raise  # the config, not the wall
            return False
        return True

    @property
    @_open_only
    def wall(self):
        """The wall of the current episode."""
        return self._env.wall

    @property
    @_open_only
    def model(self):
        return self._model

    # --- Gymnasium's API --------------------------------------------------------------

    @_open_only
    def reset(self, *, seed=None, options=None):
        _check_options(options)
        super().reset(seed=seed)
        if seed is not None:
            self._walls.restart()  # the same seed, the same walls
        self._draw_wall(self.np_random, options)
        raw, info = self._env.reset()
        return self._observe(raw, info)

    @_open_only
    def step(self, action):
        try:
            if isinstance(action, (bool, np.bool_)):
                raise TypeError
            action = operator.index(action)  # ints, numpy integers and 0-d integer arrays
        except TypeError:
            message = f"action: must be an integer from 0 to {self.action_space.n - 1}, got {action!r}"
            raise ValueError(message) from None
        if not 0 <= action < self.action_space.n or not self._mask[action]:
            raise ValueError(f"action: {action} is not a possible action of this state (see info['action_mask'])")
        hold = int(self._candidates[action]) if self.observation_form != "paper" else action
        raw, reward, terminated, _, info = self._env.step(hold)
        obs, info = self._observe(raw, info)
        # Truncation is Gymnasium's TimeLimit's (the registered max_episode_steps).
        return obs, float(reward), bool(terminated), False, info

    @_open_only
    def action_masks(self):
        """The possible actions of the state as bools, for maskable agents."""
        return self._mask.astype(bool)

    @_open_only
    def render(self):
        if self.render_mode == "ansi":
            return self._render_ansi()
        if self.render_mode == "rgb_array":
            return self._render_rgb()
        return None

    def close(self):
        self._envs.clear()
        self._env = None
        self.closed = True

    # --- observations -------------------------------------------------------------------

    def _observe(self, raw, info):
        self._raw = raw
        self._centre_of_mass = info["centre_of_mass"]
        holds = np.flatnonzero(self._env.action_mask())  # ascending hold indices
        if self.observation_form == "paper":
            mask = np.zeros(self.action_space.n, dtype=np.int8)
            mask[holds] = 1
            self._candidates = None
            obs = {
                "wall_state": int(raw["wall_state"]),
                "grid_state": int(raw["grid_state"]),
                "free_limb": int(raw["free_limb"]),
            }
        else:
            # The features are computed in C++, as the vector environment computes them.
            obs = self._env.numeric_observation(self.max_candidates, reach=self.observation_form == "reach")
            mask = np.zeros(self.max_candidates, dtype=np.int8)
            mask[: len(holds)] = 1
            self._candidates = holds
        self._mask = mask
        self.action_space.offered = mask
        info = dict(info)
        info["action_mask"] = mask.copy()
        if self.observation_form != "paper":
            # The hold index of each slot, -1 for padding (a fixed shape, as vector envs batch it).
            slots = np.full(self.max_candidates, -1, dtype=np.int64)
            slots[: len(holds)] = holds
            info["candidate_holds"] = slots
        info["wall_name"] = self.wall.name
        if self.wall_seed is not None:
            info["wall_seed"] = self.wall_seed
        return obs, info

    # --- rendering ----------------------------------------------------------------------

    def _render_ansi(self):
        raw = self._raw
        ids = self.wall.hold_ids
        limbs = ", ".join(
            f"{name} {'free' if hold < 0 else f'hold {ids[hold]}'}"
            for name, hold in zip(_crux.LIMB_NAMES, raw["configuration"])
        )
        offered = " ".join(str(ids[h]) for h in np.flatnonzero(self._env.action_mask()))
        return (
            f"{self.wall.name}: {limbs}\n"
            f"centre of mass at {self._centre_of_mass[2]:.2f} m, finish at {self.wall.finish_height:.2f} m\n"
            f"possible holds: {offered}\n"
        )

    def _render_rgb(self):
        figure = self._rgb_figure()
        figure.canvas.draw()
        return np.asarray(figure.canvas.buffer_rgba())[:, :, :3].copy()

    def _rgb_figure(self):
        """The rgb_array frame as a matplotlib Figure: the wall on the left, its legend on the right."""
        # Imported here: only rgb_array needs matplotlib (Debian's python3-matplotlib).
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        wall, raw = self.wall, self._raw
        positions = wall.positions
        figure = Figure(figsize=(4.8, 4.8), dpi=100)
        FigureCanvasAgg(figure)
        axes = figure.add_axes((0, 0, _RGB_WALL_WIDTH, 1))
        axes.set_aspect("equal")
        axes.axis("off")
        # Seen from behind the climber (x < 0, facing +x, y to its left): y grows leftwards.
        low, high = positions.min(axis=0), positions.max(axis=0)
        axes.set_xlim(high[1] + 0.5, low[1] - 0.5)
        axes.set_ylim(low[2] - 0.5, max(high[2], wall.finish_height) + 0.5)
        axes.axhline(wall.finish_height, color=_FINISH_COLOUR, linestyle="--", linewidth=1)
        offered = self._env.action_mask()
        held = raw["configuration"][raw["configuration"] >= 0]
        colours = np.array([_OTHER_HOLD_COLOUR] * wall.hold_count, dtype=object)
        colours[offered] = _POSSIBLE_HOLD_COLOUR
        colours[held] = _HELD_HOLD_COLOUR
        axes.scatter(positions[:, 1], positions[:, 2], s=40, c=list(colours), zorder=1)
        # The skeleton: each joint past the root's translations joined to its parent, the
        # segment coloured by the limb its parent joint moves, then each limb's last joint
        # joined to its grasp point.
        body = _crux.forward_kinematics(self._model, raw["posture"], joints=True)
        origins, parents = body["joint_origins"], self._model.joint_parents
        limbs = _joint_limbs(self._model.joint_names)
        for joint in range(_crux.ROOT_DOF, len(parents)):
            parent = parents[joint]
            colour = _TRUNK_COLOUR if limbs[parent] < 0 else _LIMB_COLOURS[limbs[parent]]
            _plot_segment(axes, origins[[parent, joint]], colour)
        for limb, colour in enumerate(_LIMB_COLOURS):
            ends = [j for j in range(len(parents)) if limbs[j] == limb and j not in parents]
            for end in ends:
                _plot_segment(axes, np.stack([origins[end], body["points"][1 + limb]]), colour)
            axes.scatter([body["points"][1 + limb, 1]], [body["points"][1 + limb, 2]], s=16, c=colour, zorder=3)
        axes.scatter([self._centre_of_mass[1]], [self._centre_of_mass[2]], s=60, c=_COM_COLOUR, marker="x", zorder=4)
        figure.legend(
            handles=_rgb_legend(wall.finish_height), loc="center left", bbox_to_anchor=(_RGB_WALL_WIDTH, 0.5),
            frameon=False, fontsize=8, title="from behind the climber", title_fontsize=8,
        )
        return figure


class VectorClimbEnv(gymnasium.vector.VectorEnv):
    """num_envs ClimbEnvs as one gymnasium.vector.VectorEnv, stepped together in one call
    into C++ that releases the GIL and spreads the environments over threads.

    Takes ClimbEnv's arguments (but render_mode), environment i being the ClimbEnv they
    make: reset(seed=s) seeds it with s + i, and its observations, rewards, ends and masks
    are, bit for bit, those of that ClimbEnv under Gymnasium's TimeLimit and SyncVectorEnv.
    Autoreset is Gymnasium's next-step mode: the step after an episode's end resets that
    environment (its action unused). Gymnasium's TimeLimit wraps no vector env, so the
    truncation is here: after max_episode_steps actions (the registered limit; None for
    none), as TimeLimit does it. info holds the masks, info["action_mask"] of shape
    (num_envs, n), and what the single environments' infos hold, batched as SyncVectorEnv
    batches them ("_key" marking the environments that have "key").
    """

    metadata = {"autoreset_mode": AutoresetMode.NEXT_STEP}

    def __init__(
        self,
        num_envs,
        wall=None,
        observation="numeric",
        *,
        wall_config=None,
        wall_order="cycle",
        wall_split=None,
        evaluation=False,
        config=None,
        max_candidates=DEFAULT_MAX_CANDIDATES,
        model=None,
        max_episode_steps=MAX_EPISODE_STEPS,
    ):
        num_envs = _integer(num_envs, "num_envs")
        if max_episode_steps is not None:
            max_episode_steps = _integer(max_episode_steps, "max_episode_steps", must_be="must be None or")
        # One single environment checks the arguments and gives the walls and the spaces.
        single = ClimbEnv(
            wall,
            observation,
            wall_config=wall_config,
            wall_order=wall_order,
            wall_split=wall_split,
            evaluation=evaluation,
            config=config,
            max_candidates=max_candidates,
            model=model,
        )
        if observation != "paper" and num_envs * single.max_candidates > _MAX_BATCH_SLOTS:
            raise ValueError(
                f"num_envs: must be an integer from 1 to {_MAX_BATCH_SLOTS // single.max_candidates} with "
                f"max_candidates={single.max_candidates} (at most {_MAX_BATCH_SLOTS} candidate slots a batch), "
                f"got {num_envs}"
            )
        self.num_envs = num_envs
        self.observation_form = observation
        self.max_episode_steps = max_episode_steps
        self.single_observation_space = single.observation_space
        self.single_action_space = spaces.Discrete(single.action_space.n)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self._paper_hold_count = single._paper_hold_count
        # Each environment takes the walls in its own turn, from its own np_random.
        self._walls = [copy.copy(single._walls) for _ in range(self.num_envs)]
        self._rngs = [None] * self.num_envs
        listed = single._walls.walls if isinstance(single._walls, _FixedWalls) else []
        single.close()
        self._vector = _crux.VectorClimbEnv(
            self.num_envs,
            listed,
            observation,
            single.action_space.n,
            max_episode_steps,
            config=config,
            model=model,
        )
        self._wall_names = np.full(self.num_envs, None, dtype=object)
        self._wall_seeds = np.zeros(self.num_envs, dtype=np.int64)
        self._seeded = np.zeros(self.num_envs, dtype=np.bool_)
        self._mask = None

    @_open_only
    def reset(self, *, seed=None, options=None):
        if seed is None or isinstance(seed, (int, np.integer)):
            seeds = [None if seed is None else int(seed) + i for i in range(self.num_envs)]
        else:
            seeds = list(seed)
            if len(seeds) != self.num_envs:
                raise ValueError(f"seed: {len(seeds)} seeds for {self.num_envs} environments")
        if isinstance(options, dict) and "reset_mask" in options:
            raise ValueError("options: reset_mask is not supported: reset() resets every environment")
        _check_options(options)
        super().reset(seed=int(seed) if isinstance(seed, (int, np.integer)) else None)
        for env, env_seed in enumerate(seeds):
            if env_seed is not None or self._rngs[env] is None:
                self._rngs[env], _ = seeding.np_random(env_seed)
            if env_seed is not None:
                self._walls[env].restart()  # the same seed, the same walls
            self._choose_wall(env, options)
        obs, _, _, _, parts = self._vector.reset()
        return obs, self._info(parts)

    @_open_only
    def step(self, actions):
        if self._rngs[0] is None:
            raise gymnasium.error.ResetNeeded("Cannot call step() before reset()")  # as OrderEnforcing
        for env in np.flatnonzero(self._vector.needs_reset()):
            self._choose_wall(int(env), None)
        obs, rewards, terminated, truncated, parts = self._vector.step(actions)
        return obs, rewards, terminated, truncated, self._info(parts)

    @_open_only
    def action_masks(self):
        """The possible actions of each environment's state as bools, (num_envs, n), for maskable agents."""
        return self._mask.astype(bool)

    @_open_only
    def render(self):
        return super().render()

    def close_extras(self, **kwargs):
        self._vector = None

    def _choose_wall(self, env, options):
        index, wall, seed = _next_wall(self._walls[env], self._rngs[env], options, self._paper_hold_count)
        self._vector.set_next_wall(env, wall if index is None else index)
        self._wall_names[env] = wall.name
        self._seeded[env] = seed is not None
        self._wall_seeds[env] = 0 if seed is None else seed

    def _info(self, parts):
        """The single environments' infos, batched as SyncVectorEnv batches them."""
        info = {}

        def add(key, value, present):
            info[key] = value
            info[f"_{key}"] = present.copy()

        everyone = np.ones(self.num_envs, dtype=np.bool_)
        stepped = parts["stepped"]
        if stepped.any():  # what a step's info holds and a reset's does not
            for key in ("hold_id", "reached", "fell", "root_rise"):
                add(key, parts[key], stepped)
        add("centre_of_mass", parts["centre_of_mass"], everyone)
        add("action_mask", parts["action_mask"], everyone)
        if self.observation_form != "paper":
            add("candidate_holds", parts["candidate_holds"], everyone)
        add("wall_name", self._wall_names.copy(), everyone)
        if self._seeded.any():
            add("wall_seed", self._wall_seeds.copy(), self._seeded)
        self._mask = parts["action_mask"]
        return info


# By name, so that the spec serialises (EnvSpec.to_json) and
# gymnasium.make("crux.gym:crux/Climb-v0") imports this module first.
gymnasium.register(
    id=ENV_ID,
    entry_point="crux.gym:ClimbEnv",
    vector_entry_point="crux.gym:VectorClimbEnv",
    max_episode_steps=MAX_EPISODE_STEPS,
)
