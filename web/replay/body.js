// The climber as a three.js scene graph: per joint one fixed-origin group and one moving group,
// so that three computes the forward kinematics; visuals and grasp points hang off the moving groups.
import {
  BoxGeometry, Color, CylinderGeometry, Group, Mesh, MeshLambertMaterial, Object3D, SphereGeometry,
  SRGBColorSpace, Vector3,
} from 'three';

function makeGeometry(shape, size) {
  if (shape === 'box') return new BoxGeometry(size[0], size[1], size[2]);
  if (shape === 'cylinder') {
    // URDF cylinders lie along their local z axis; three's CylinderGeometry lies along y.
    const g = new CylinderGeometry(size[0], size[0], size[1], 24, 1);
    g.rotateX(Math.PI / 2);
    return g;
  }
  if (shape === 'sphere') return new SphereGeometry(size[0], 24, 16);
  return null;
}

export class Body {
  constructor(model) {
    this.root = new Group();
    this.root.name = 'crux-body';
    this.joints = model.joints;
    this.moving = [];
    this.axes = model.joints.map((j) => new Vector3(j.axis[0], j.axis[1], j.axis[2]).normalize());
    model.joints.forEach((j, i) => {
      const fixed = new Group();
      fixed.name = `${j.name}:origin`;
      fixed.position.set(j.origin_xyz[0], j.origin_xyz[1], j.origin_xyz[2]);
      fixed.quaternion.set(j.origin_quat[0], j.origin_quat[1], j.origin_quat[2], j.origin_quat[3]).normalize();
      const moving = new Group();
      moving.name = j.name;
      fixed.add(moving);
      (j.parent < 0 ? this.root : this.moving[j.parent]).add(fixed);
      this.moving.push(moving);
    });

    const materials = new Map();
    this.visualMeshes = [];
    this.ratioMaterials = new Map();
    for (const v of model.visuals || []) {
      const geometry = makeGeometry(v.shape, v.size);
      if (!geometry) continue;
      const rgba = v.rgba || [0.8, 0.8, 0.8, 1];
      const key = rgba.join(',');
      if (!materials.has(key)) {
        const transparent = rgba[3] < 1;
        materials.set(key, new MeshLambertMaterial({
          color: new Color().setRGB(rgba[0], rgba[1], rgba[2], SRGBColorSpace),
          transparent,
          opacity: rgba[3],
          depthWrite: !transparent,
        }));
      }
      const mesh = new Mesh(geometry, materials.get(key));
      this.visualMeshes.push({ mesh, joint: v.joint, material: mesh.material });
      mesh.name = `${v.link}:visual`;
      mesh.position.set(v.xyz[0], v.xyz[1], v.xyz[2]);
      mesh.quaternion.set(v.quat[0], v.quat[1], v.quat[2], v.quat[3]).normalize();
      (v.joint < 0 ? this.root : this.moving[v.joint]).add(mesh);
    }

    this.grasp = model.grasp_points.map((g, i) => {
      const o = new Object3D();
      o.name = `grasp:${i}`;
      o.position.set(g.offset[0], g.offset[1], g.offset[2]);
      (g.joint < 0 ? this.root : this.moving[g.joint]).add(o);
      return o;
    });
  }

  /** Sets every joint from posture coordinates q[offset .. offset + joints.length). */
  apply(q, offset = 0) {
    const n = this.joints.length;
    for (let i = 0; i < n; ++i) {
      const value = q[offset + i];
      const m = this.moving[i];
      if (this.joints[i].prismatic) {
        const a = this.axes[i];
        m.position.set(a.x * value, a.y * value, a.z * value);
      } else {
        m.quaternion.setFromAxisAngle(this.axes[i], value);
      }
    }
  }

  /**
   * Turns the body about its root's frame (after the root's translations, the free joint's body in
   * MuJoCo) by the quaternion r[offset .. offset + 4) = (x, y, z, w), from its orientation on the wall.
   */
  applyRootRotation(r, offset = 0) {
    const last = this.joints.findIndex((j) => !j.prismatic) - 1;
    this.moving[Math.max(last, 0)].quaternion.set(r[offset], r[offset + 1], r[offset + 2], r[offset + 3]).normalize();
  }

  /**
   * Paints each segment whose carrying joint has a torque ratio in `ratios` (joint -> ratio)
   * with colour(ratio), and gives the others their own colours back (ratios null: all).
   */
  paintByJoint(ratios, colour) {
    for (const v of this.visualMeshes) {
      const ratio = ratios ? ratios.get(v.joint) : undefined;
      if (ratio === undefined) {
        v.mesh.material = v.material;
        continue;
      }
      const hex = colour(ratio);
      if (!this.ratioMaterials.has(hex)) {
        this.ratioMaterials.set(hex, new MeshLambertMaterial({ color: new Color(hex) }));
      }
      v.mesh.material = this.ratioMaterials.get(hex);
    }
  }

  /** World positions of the grasp points (after apply). */
  graspWorld() {
    return this.grasp.map((o) => {
      const p = o.getWorldPosition(new Vector3());
      return [p.x, p.y, p.z];
    });
  }
}
