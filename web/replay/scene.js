// The wall (plane x = 0 facing +x), its holds, start-hold rings, the tried-hold halo,
// the finish height and the floor.
import {
  BufferGeometry, Color, DoubleSide, Float32BufferAttribute, Group, Line, LineBasicMaterial,
  LineSegments, Matrix4, Mesh, MeshBasicMaterial, MeshLambertMaterial, PlaneGeometry, SphereGeometry, TorusGeometry, Vector3,
} from 'three';

export const COLORS = {
  wall: 0xe9e4da,
  hold: 0x8d8f94,
  held: 0xf08c00,
  start: 0x1c6fd1,
  reached: 0x1f9e3a,
  unreachable: 0xd62728,
  finish: 0x7b3fb8,
  floor: 0xb9bcc2,
  grasp: [0xd62728, 0x1c6fd1, 0xc77700, 0x2a9d8f],
};

/** Extent of the scene in y and z: the holds, the finish line and the climber's start. */
export function wallExtent(wall, rootY) {
  let ymin = rootY - 1, ymax = rootY + 1, zmax = 2.5;
  for (const h of wall.holds || []) {
    ymin = Math.min(ymin, h.position[1] - 0.5);
    ymax = Math.max(ymax, h.position[1] + 0.5);
    zmax = Math.max(zmax, h.position[2] + 0.5);
  }
  if (typeof wall.finish_height === 'number') zmax = Math.max(zmax, wall.finish_height + 0.4);
  return { ymin, ymax, zmax };
}

export class WallView {
  constructor(data, rootY) {
    this.group = new Group();
    this.group.name = 'crux-wall';
    const wall = data.wall;
    const { ymin, ymax, zmax } = wallExtent(wall, rootY);
    this.extent = { ymin, ymax, zmax };
    const width = ymax - ymin;

    // PlaneGeometry lies in xy facing +z: map its x to world -y, its y to world z and its normal to
    // -x, towards the climber, who stands at x < 0 (a rotation, so the frame stays right-handed).
    const plane = new PlaneGeometry(width, zmax);
    plane.applyMatrix4(new Matrix4().makeBasis(new Vector3(0, -1, 0), new Vector3(0, 0, 1), new Vector3(-1, 0, 0)));
    // Unlit: a lit plane under directional lights is one flat colour anyway, and an unlit one is far
    // cheaper to fill in software rendering (the wall covers most of the view).
    const wallMesh = new Mesh(plane, new MeshBasicMaterial({ color: COLORS.wall }));
    wallMesh.position.set(0, (ymin + ymax) / 2, zmax / 2);
    wallMesh.name = 'wall';
    this.group.add(wallMesh);

    // Floor grid in z = 0, from the wall out to x = -3 m on the climber's side: a group of
    // its own, level whatever the wall's incline.
    this.floor = new Group();
    this.floor.name = 'crux-floor';
    const pts = [];
    for (let x = 0; x >= -3.0001; x -= 0.25) pts.push(x, ymin, 0, x, ymax, 0);
    for (let y = Math.ceil(ymin * 4) / 4; y <= ymax; y += 0.25) pts.push(0, y, 0, -3, y, 0);
    const grid = new BufferGeometry();
    grid.setAttribute('position', new Float32BufferAttribute(pts, 3));
    this.floor.add(new LineSegments(grid, new LineBasicMaterial({ color: COLORS.floor })));

    // Finish height: a line on the wall and a translucent horizontal band in front of it.
    if (typeof wall.finish_height === 'number') {
      const fz = wall.finish_height;
      const line = new BufferGeometry();
      line.setAttribute('position', new Float32BufferAttribute([-0.004, ymin, fz, -0.004, ymax, fz], 3));
      this.group.add(new Line(line, new LineBasicMaterial({ color: COLORS.finish })));
      const band = new PlaneGeometry(0.6, width); // in xy, facing +z
      const bandMesh = new Mesh(band, new MeshBasicMaterial({
        color: COLORS.finish, transparent: true, opacity: 0.12, side: DoubleSide, depthWrite: false,
      }));
      bandMesh.position.set(-0.3, (ymin + ymax) / 2, fz);
      bandMesh.name = 'finish';
      this.group.add(bandMesh);
    }

    // Holds: all spheres merged into one geometry with per-vertex colours: one draw call, and a
    // highlight rewrites the colours of a few holds. (An InstancedMesh costs far more per frame in
    // software WebGL.)
    const holds = wall.holds || [];
    this.holdCount = holds.length;
    this.holdColor = new Color();
    this.holds = null;
    if (holds.length > 0) {
      const unit = new SphereGeometry(1, 16, 10).toNonIndexed();
      const up = unit.getAttribute('position').array;
      const un = unit.getAttribute('normal').array;
      const n = up.length / 3;
      this.holdVertices = n;
      const pos = new Float32Array(n * 3 * holds.length);
      const nor = new Float32Array(n * 3 * holds.length);
      const col = new Float32Array(n * 3 * holds.length);
      holds.forEach((h, i) => {
        const r = h.radius > 0 ? h.radius : 0.03;
        for (let k = 0; k < n; ++k) {
          const o = (i * n + k) * 3;
          pos[o] = h.position[0] + r * up[k * 3];
          pos[o + 1] = h.position[1] + r * up[k * 3 + 1];
          pos[o + 2] = h.position[2] + r * up[k * 3 + 2];
          nor[o] = un[k * 3];
          nor[o + 1] = un[k * 3 + 1];
          nor[o + 2] = un[k * 3 + 2];
        }
      });
      unit.dispose();
      const g = new BufferGeometry();
      g.setAttribute('position', new Float32BufferAttribute(pos, 3));
      g.setAttribute('normal', new Float32BufferAttribute(nor, 3));
      this.holdColors = new Float32BufferAttribute(col, 3);
      g.setAttribute('color', this.holdColors);
      g.computeBoundingSphere();
      this.holds = new Mesh(g, new MeshLambertMaterial({ vertexColors: true }));
      this.holds.name = 'holds';
      for (let i = 0; i < holds.length; ++i) this.paintHold(i, COLORS.hold);
      this.group.add(this.holds);
    }

    // Start holds: a ring on the wall around each.
    const ringMaterial = new MeshBasicMaterial({ color: COLORS.start });
    for (const limb of Object.keys(wall.start || {})) {
      const i = data.holdIndex.get(wall.start[limb]);
      if (i === undefined) continue;
      const h = holds[i];
      const r = (h.radius > 0 ? h.radius : 0.03) * 1.6;
      const ring = new TorusGeometry(r, Math.max(0.006, r * 0.12), 8, 32);
      ring.rotateY(Math.PI / 2); // lie in the wall plane
      const mesh = new Mesh(ring, ringMaterial);
      mesh.position.set(-0.006, h.position[1], h.position[2]);
      mesh.name = `start:${limb}`;
      this.group.add(mesh);
    }

    // Tried hold of the current move: a translucent halo, green when reached, red when unreachable.
    // Drawn through the body, which often stands in front of the hold it reaches for.
    this.haloMaterial = new MeshBasicMaterial({ color: COLORS.reached, transparent: true, opacity: 0.35, depthWrite: false, depthTest: false });
    this.halo = new Mesh(new SphereGeometry(1, 20, 14), this.haloMaterial);
    this.halo.renderOrder = 9;
    this.halo.name = 'tried-hold';
    this.halo.visible = false;
    this.group.add(this.halo);
    this.lastKey = '';
  }

  paintHold(i, colour) {
    const c = this.holdColor.set(colour);
    const a = this.holdColors.array;
    for (let k = i * this.holdVertices * 3, end = k + this.holdVertices * 3; k < end; k += 3) {
      a[k] = c.r;
      a[k + 1] = c.g;
      a[k + 2] = c.b;
    }
  }

  /** Colours the holds: held (configuration), tried (success or not), others plain. */
  highlight(data, configuration, triedId, success) {
    const key = `${triedId}:${success}:${configuration.right_hand},${configuration.left_hand},${configuration.right_foot},${configuration.left_foot}`;
    if (key === this.lastKey) return;
    this.lastKey = key;
    const holds = data.wall.holds || [];
    // Repaint only the holds whose colour changes.
    const wanted = new Map();
    for (const limb of Object.keys(configuration)) {
      const i = data.holdIndex.get(configuration[limb]);
      if (i !== undefined) wanted.set(i, COLORS.held);
    }
    const t = data.holdIndex.get(triedId);
    if (t === undefined) {
      this.halo.visible = false;
    } else {
      const colour = success ? COLORS.reached : COLORS.unreachable;
      wanted.set(t, colour);
      const h = holds[t];
      const r = (h.radius > 0 ? h.radius : 0.03) * 2.2;
      this.halo.position.set(h.position[0], h.position[1], h.position[2]);
      this.halo.scale.set(r, r, r);
      this.haloMaterial.color.set(colour);
      this.halo.visible = true;
    }
    if (this.holds) {
      const painted = this.painted || new Map();
      for (const [i] of painted) if (!wanted.has(i)) this.paintHold(i, COLORS.hold);
      for (const [i, colour] of wanted) if (painted.get(i) !== colour) this.paintHold(i, colour);
      this.painted = wanted;
      this.holdColors.needsUpdate = true;
    }
  }
}
