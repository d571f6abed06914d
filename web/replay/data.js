// Reads and checks the crux-replay JSON (format "crux-replay", version 1) and indexes it for playback.

export const LIMBS = ['right_hand', 'left_hand', 'right_foot', 'left_foot'];

function fail(message) {
  throw new Error(`crux replay data: ${message}`);
}

function isVec(v, n) {
  return Array.isArray(v) && v.length === n && v.every((x) => typeof x === 'number' && Number.isFinite(x));
}

/**
 * Validates `raw` and returns it with derived lookups (postures as Float64Array, move of each frame, hold index;
 * for a performed climb the root's rotations and the hold forces of each frame).
 */
export function prepareReplayData(raw) {
  if (!raw || raw.format !== 'crux-replay') fail('format is not "crux-replay"');
  if (raw.version !== 1) fail(`unsupported version ${raw.version}`);
  const model = raw.model;
  if (!model || !Array.isArray(model.joints) || model.joints.length === 0) fail('model.joints missing');
  const dof = model.joints.length;
  model.joints.forEach((j, i) => {
    if (!(Number.isInteger(j.parent) && j.parent >= -1 && j.parent < i)) fail(`joint ${i} parent must come before it`);
    if (!isVec(j.origin_xyz, 3) || !isVec(j.origin_quat, 4) || !isVec(j.axis, 3)) fail(`joint ${i} has a bad origin or axis`);
  });
  for (const v of model.visuals || []) {
    if (!(v.joint >= -1 && v.joint < dof)) fail(`visual of ${v.link} names joint ${v.joint}`);
  }
  if (!Array.isArray(model.grasp_points) || model.grasp_points.length !== 4) fail('model.grasp_points must have 4 entries');

  const frames = raw.frames;
  if (!frames || !Number.isInteger(frames.count) || frames.count < 1) fail('frames.count missing');
  if (!Array.isArray(frames.postures) || frames.postures.length !== frames.count * dof) {
    fail(`frames.postures has ${frames.postures ? frames.postures.length : 0} numbers, expected ${frames.count} x ${dof}`);
  }
  const postures = Float64Array.from(frames.postures);

  const moves = Array.isArray(raw.moves) ? raw.moves : [];
  // moveAt[f]: the move a frame belongs to (frame 0, the start posture, belongs to the first move).
  const moveAt = new Int32Array(frames.count);
  moves.forEach((m, k) => {
    if (!(m.first_frame >= 0 && m.last_frame >= m.first_frame && m.last_frame < frames.count)) {
      fail(`move ${k} frames ${m.first_frame}..${m.last_frame} are outside 0..${frames.count - 1}`);
    }
    moveAt.fill(k, m.first_frame, m.last_frame + 1);
  });
  // Frames after the last move (if any) stay with the last move.
  if (moves.length > 0) moveAt.fill(moves.length - 1, moves[moves.length - 1].last_frame + 1);

  // Under the static model: the stance in effect at each frame (null while a limb moves, or
  // under the kinematic model). A failed move leaves the body in the stance it was in.
  const checkStance = (s, where) => {
    if (!s || !Array.isArray(s.forces) || s.forces.length !== 4 || !Array.isArray(s.joint_ratios)) fail(`${where} is not a stance`);
    s.forces.forEach((f, i) => { if (f !== null && !isVec(f, 3)) fail(`${where}.forces[${i}] is not a force`); });
    s.joint_ratios.forEach((r) => {
      if (!(Array.isArray(r) && Number.isInteger(r[0]) && r[0] >= 0 && r[0] < dof && Number.isFinite(r[1]))) fail(`${where}.joint_ratios has a bad entry`);
    });
    return s;
  };
  const stances = new Array(frames.count).fill(null);
  if (raw.start_stance !== undefined) {
    let current = checkStance(raw.start_stance, 'start_stance');
    stances[0] = current;
    moves.forEach((m, k) => {
      if (m.success) {
        current = m.stance === undefined ? null : checkStance(m.stance, `moves[${k}].stance`);
        stances[m.last_frame] = current;
      } else {
        stances.fill(current, m.first_frame, m.last_frame + 1);
      }
    });
    if (moves.length > 0) stances.fill(current, moves[moves.length - 1].last_frame + 1);
  }

  // A climb performed in MuJoCo: each frame also has the root's rotation, each limb's force
  // from its hold (drawn as the static model's are) and its simulated time.
  const performed = raw.performed === true;
  let rootRotations = null;
  let frameSeconds = null;
  if (performed) {
    const perFrame = (name, n) => {
      const values = frames[name];
      if (!Array.isArray(values) || values.length !== frames.count * n || !values.every(Number.isFinite)) {
        fail(`frames.${name} must hold ${n} numbers per frame`);
      }
      return Float64Array.from(values);
    };
    rootRotations = perFrame('root_rotations', 4);
    const forces = perFrame('hold_forces', 12);
    const times = perFrame('times', 1);
    for (let f = 0; f < frames.count; ++f) {
      const limbForces = [0, 1, 2, 3].map((i) => {
        const v = Array.from(forces.subarray(12 * f + 3 * i, 12 * f + 3 * i + 3));
        return v.some((x) => x !== 0) ? v : null;
      });
      stances[f] = { forces: limbForces, joint_ratios: [], effort: undefined };
    }
    for (let f = 1; f < frames.count; ++f) if (times[f] < times[f - 1]) fail(`frames.times decreases at frame ${f}`);
    frameSeconds = frames.count > 1 && times[frames.count - 1] > times[0] ? (times[frames.count - 1] - times[0]) / (frames.count - 1) : null;
    if (!Number.isInteger(raw.climb_moves) || raw.climb_moves < moves.length) fail('climb_moves must count the moves at least');
    moves.forEach((m, k) => {
      if (typeof m.success !== 'boolean') fail(`moves[${k}].success missing`);
      if (!LIMBS.includes(m.limb)) fail(`moves[${k}].limb is not a limb`);
    });
  }

  const wall = raw.wall || { holds: [], start: {} };
  const holdIndex = new Map();
  (wall.holds || []).forEach((h, i) => holdIndex.set(h.id, i));

  return {
    raw,
    title: raw.title || 'crux replay',
    model,
    dof,
    graspRadius: typeof raw.grasp_radius === 'number' ? raw.grasp_radius : 0.04,
    wall,
    holdIndex,
    frameCount: frames.count,
    postures,
    moves,
    moveAt,
    stances,
    hasStances: raw.start_stance !== undefined,
    performed,
    rootRotations,
    frameSeconds,
    hasForces: performed || raw.start_stance !== undefined,
    check: raw.check || null,
  };
}

/** The holds held at frame f: the configuration before the current move until its last frame, then the move's own. */
export function configurationAt(data, f) {
  const k = data.moveAt[f];
  const move = data.moves[k];
  if (move && f >= move.last_frame) return move.configuration;
  if (k > 0) return data.moves[k - 1].configuration;
  return data.wall.start || {};
}
