#!/usr/bin/python3
"""Writes a crux-replay JSON fixture (format "crux-replay", version 1) from the real body model.

The model part (joints, visuals, grasp points) is read from models/crux_human.urdf the way the
C++ report will write it: joints in URDF document order (3 prismatic root joints, then 32
revolute), fixed joints merged into the moving joint that carries them, links without visuals
skipped. The postures are hand-made: the standing posture at root (0.35, 0.5, 1.0) plus small
joint-angle variations, a few moves long (or --moves N for a large performance fixture).
`check` holds grasp points computed here, by a forward kinematics independent of three.js.

Usage: make_fixture.py [--urdf FILE] [--moves N] [--frames-per-move K] [--seed S] -o OUT.json
"""
import argparse
import json
import math
import os
import random
import xml.etree.ElementTree as ET

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
LIMBS = ["right_hand", "left_hand", "right_foot", "left_foot"]
GRASP_LINKS = ["right_palm", "left_palm", "right_foot_ball", "left_foot_ball"]
STANDING_ROOT = (0.35, 0.5, 1.0)


# ---- small rigid-transform algebra: a transform is (quat [x,y,z,w], translation [3]) ----
def q_mul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz]


def q_rot(q, v):
    x, y, z, w = q
    # v' = v + 2 w (u x v) + 2 u x (u x v)
    cx, cy, cz = y * v[2] - z * v[1], z * v[0] - x * v[2], x * v[1] - y * v[0]
    dx, dy, dz = y * cz - z * cy, z * cx - x * cz, x * cy - y * cx
    return [v[0] + 2 * (w * cx + dx), v[1] + 2 * (w * cy + dy), v[2] + 2 * (w * cz + dz)]


def q_axis_angle(axis, angle):
    s = math.sin(angle / 2)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(angle / 2)]


def q_rpy(r, p, y):
    # URDF: R = Rz(yaw) * Ry(pitch) * Rx(roll)
    return q_mul(q_axis_angle([0, 0, 1], y), q_mul(q_axis_angle([0, 1, 0], p), q_axis_angle([1, 0, 0], r)))


def t_mul(a, b):
    return (q_mul(a[0], b[0]), [a[1][i] + v for i, v in enumerate(q_rot(a[0], b[1]))])


IDENTITY = ([0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 0.0])


def origin_of(elem):
    o = elem.find("origin") if elem is not None else None
    xyz = [float(v) for v in (o.get("xyz", "0 0 0") if o is not None else "0 0 0").split()]
    rpy = [float(v) for v in (o.get("rpy", "0 0 0") if o is not None else "0 0 0").split()]
    return (q_rpy(*rpy), xyz)


def clean(values, digits=9):
    out = []
    for v in values:
        v = round(v, digits)
        out.append(0.0 if v == 0 else v)
    return out


def read_model(urdf_path):
    robot = ET.parse(urdf_path).getroot()
    materials = {}
    for m in robot.findall("material"):
        c = m.find("color")
        if c is not None:
            materials[m.get("name")] = [float(v) for v in c.get("rgba").split()]

    # carrier[link] = (moving joint index or -1 for the world, transform of the link in that joint's frame)
    carrier = {}
    joints = []
    parent_links = {j.find("child").get("link") for j in robot.findall("joint")}
    for link in robot.findall("link"):
        if link.get("name") not in parent_links:
            carrier[link.get("name")] = (-1, IDENTITY)  # the world
    pending = list(robot.findall("joint"))
    while pending:  # document order, but a joint waits until its parent link is placed
        progressed = False
        for j in list(pending):
            parent, child = j.find("parent").get("link"), j.find("child").get("link")
            if parent not in carrier:
                continue
            pending.remove(j)
            progressed = True
            pj, p_off = carrier[parent]
            origin = t_mul(p_off, origin_of(j))
            kind = j.get("type")
            if kind == "fixed":
                carrier[child] = (pj, origin)
                continue
            if kind not in ("revolute", "continuous", "prismatic"):
                raise SystemExit(f"unsupported joint type {kind} ({j.get('name')})")
            ax = j.find("axis")
            axis = [float(v) for v in (ax.get("xyz") if ax is not None else "1 0 0").split()]
            n = math.sqrt(sum(a * a for a in axis))
            joints.append({
                "name": j.get("name"),
                "parent": pj,
                "origin_xyz": clean(origin[1]),
                "origin_quat": clean(origin[0]),
                "axis": clean([a / n for a in axis]),
                "prismatic": kind == "prismatic",
            })
            carrier[child] = (len(joints) - 1, IDENTITY)
        if not progressed:
            raise SystemExit("URDF joints do not form a tree rooted at the world")

    visuals = []
    for link in robot.findall("link"):
        name = link.get("name")
        for v in link.findall("visual"):
            ji, off = carrier[name]
            pose = t_mul(off, origin_of(v))
            g = v.find("geometry")
            if g.find("box") is not None:
                shape, size = "box", [float(s) for s in g.find("box").get("size").split()]
            elif g.find("cylinder") is not None:
                c = g.find("cylinder")
                shape, size = "cylinder", [float(c.get("radius")), float(c.get("length"))]
            elif g.find("sphere") is not None:
                shape, size = "sphere", [float(g.find("sphere").get("radius"))]
            else:
                continue  # meshes are not part of the contract
            mat = v.find("material")
            rgba = [0.8, 0.8, 0.8, 1.0]
            if mat is not None:
                c = mat.find("color")
                rgba = [float(x) for x in c.get("rgba").split()] if c is not None else materials.get(mat.get("name"), rgba)
            visuals.append({"link": name, "joint": ji, "xyz": clean(pose[1]), "quat": clean(pose[0]),
                            "shape": shape, "size": size, "rgba": rgba})

    grasp_points = []
    for g in GRASP_LINKS:
        ji, off = carrier[g]
        grasp_points.append({"joint": ji, "offset": clean(off[1])})
    return {"joints": joints, "visuals": visuals, "grasp_points": grasp_points}


def forward_grasp_points(model, q):
    """World grasp points by the contract's kinematics (independent of the viewer)."""
    world = []
    for i, j in enumerate(model["joints"]):
        base = IDENTITY if j["parent"] < 0 else world[j["parent"]]
        t = t_mul(base, (j["origin_quat"], j["origin_xyz"]))
        if j["prismatic"]:
            motion = ([0.0, 0.0, 0.0, 1.0], [a * q[i] for a in j["axis"]])
        else:
            motion = (q_axis_angle(j["axis"], q[i]), [0.0, 0.0, 0.0])
        world.append(t_mul(t, motion))
    out = []
    for g in model["grasp_points"]:
        rot, trans = world[g["joint"]]
        out.append([trans[k] + v for k, v in enumerate(q_rot(rot, g["offset"]))])
    return out


def make(urdf, moves_wanted, frames_per_move, seed):
    model = read_model(urdf)
    names = [j["name"] for j in model["joints"]]
    if len(names) != 35 or [j["prismatic"] for j in model["joints"]].count(True) != 3:
        raise SystemExit(f"expected 3 prismatic + 32 revolute joints, got {len(names)}")
    idx = {n: i for i, n in enumerate(names)}
    rng = random.Random(seed)

    standing = [0.0] * 35
    standing[0:3] = STANDING_ROOT
    gp = forward_grasp_points(model, standing)

    # Holds: the start holds just in front of the wall near where the standing climber's limbs are,
    # then a grid of holds up the wall.
    holds = []
    def add_hold(y, z, r=0.03):
        holds.append({"id": len(holds) + 1, "position": [0.03, round(y, 4), round(z, 4)], "radius": r})
        return len(holds)
    start = {
        "right_hand": add_hold(gp[0][1], 1.45, 0.035),
        "left_hand": add_hold(gp[1][1], 1.45, 0.035),
        "right_foot": add_hold(gp[2][1], 0.25, 0.035),
        "left_foot": add_hold(gp[3][1], 0.25, 0.035),
    }
    for row in range(8):
        for col in range(4):
            add_hold(0.1 + 0.27 * col + (0.12 if row % 2 else 0.0), 0.45 + 0.3 * row)
    finish_height = 2.7

    # Joint-angle variations (radians) the moves pick from: small, within the joint limits.
    varied = {
        "right_hand": ["right_shoulder_flexion", "right_shoulder_abduction", "right_elbow_flexion", "right_wrist_flexion"],
        "left_hand": ["left_shoulder_flexion", "left_shoulder_abduction", "left_elbow_flexion", "left_wrist_flexion"],
        "right_foot": ["right_hip_flexion", "right_hip_abduction", "right_knee_flexion", "right_ankle_flexion"],
        "left_foot": ["left_hip_flexion", "left_hip_abduction", "left_knee_flexion", "left_ankle_flexion"],
    }
    ranges = {"shoulder_flexion": (-0.2, 0.4), "shoulder_abduction": (0.0, 0.6), "elbow_flexion": (0.0, 0.3),
              "wrist_flexion": (-0.3, 0.3), "hip_flexion": (0.0, 0.5), "hip_abduction": (0.0, 0.3),
              "knee_flexion": (0.0, 0.9), "ankle_flexion": (-0.3, 0.2)}

    postures = [list(standing)]
    configuration = dict(start)
    moves = []
    regimes = ["w_greedy", "g_greedy", "random"]
    rise_total = 0.0
    for m in range(moves_wanted):
        limb = LIMBS[m % 4]
        success = (m % 3) != 2
        hold = rng.randint(1, len(holds))
        current = postures[-1]
        target = list(current)
        if success:
            for n in varied[limb]:
                lo, hi = ranges[n.split("_", 1)[1]]
                target[idx[n]] = round(rng.uniform(lo, hi), 6)
            for n in ("lumbar_flexion", "lumbar_lateral", "neck_flexion", "neck_rotation"):
                target[idx[n]] = round(rng.uniform(-0.15, 0.15), 6)
            target[1] = round(0.5 + rng.uniform(-0.08, 0.08), 6)
            target[2] = round(1.0 + 0.02 * ((m // 4) % 5), 6)
        first = len(postures)
        for k in range(1, frames_per_move + 1):
            s = k / frames_per_move if success else 0.0
            s = s * s * (3 - 2 * s)
            postures.append([round(a + (b - a) * s, 6) for a, b in zip(current, target)])
        rise = round((target[2] - current[2]) * 100, 3)
        rise_total += rise
        if success:
            configuration[limb] = hold
        elif m % 6 == 5:
            configuration[limb] = 0  # the limb let go: a free limb is 0
        moves.append({
            "iteration": 1 + m // 40,
            "regime": regimes[m % 3],
            "limb": limb,
            "hold": hold,
            "success": success,
            "reward": round(rng.uniform(-1.0, 1.0) if success else -1.0, 4),
            "root_rise_cm": rise,
            "configuration": dict(configuration),
            "first_frame": first,
            "last_frame": len(postures) - 1,
        })

    # The check frame: mid-way through the second move (a varied, non-zero posture).
    check_frame = moves[min(1, len(moves) - 1)]["first_frame"] + frames_per_move // 2
    data = {
        "format": "crux-replay",
        "version": 1,
        "title": f"Fixture replay: crux_human on a hand-made wall ({moves_wanted} moves)",
        "model": model,
        "grasp_radius": 0.04,
        "wall": {"name": "fixture_wall", "finish_height": finish_height, "holds": holds, "start": start},
        "frames": {"count": len(postures), "postures": [v for p in postures for v in p]},
        "moves": moves,
    }
    # The check is computed from the numbers as written, read back.
    written = json.loads(json.dumps(data))
    q = written["frames"]["postures"][check_frame * 35:(check_frame + 1) * 35]
    data["check"] = {"frame": check_frame,
                     "grasp_points": [clean(p, 12) for p in forward_grasp_points(written["model"], q)]}
    return data


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--urdf", default=os.path.join(ROOT, "models", "crux_human.urdf"))
    ap.add_argument("--moves", type=int, default=6)
    ap.add_argument("--frames-per-move", type=int, default=20)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    data = make(a.urdf, a.moves, a.frames_per_move, a.seed)
    with open(a.output, "w") as f:
        json.dump(data, f, separators=(",", ":") if a.moves > 20 else (",", ": "),
                  indent=None if a.moves > 20 else 1)
        f.write("\n")


if __name__ == "__main__":
    main()
