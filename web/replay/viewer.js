// The replay panel: renderer, camera, orbit controls, playback loop, controls and info line.
import {
  AmbientLight, ArrowHelper, DirectionalLight, HemisphereLight, Mesh, MeshBasicMaterial, PerspectiveCamera, Scene,
  SphereGeometry, Vector3, WebGLRenderer, Group,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { Body } from './body.js';
import { configurationAt, LIMBS } from './data.js';
import { COLORS, WallView } from './scene.js';

export const BASE_FPS = 30; // 1x = 30 replay frames per second
export const SPEEDS = [0.25, 0.5, 1, 2, 4];
const LIMB_NAMES = { right_hand: 'right hand', left_hand: 'left hand', right_foot: 'right foot', left_foot: 'left foot' };
const REGIME_NAMES = { w_greedy: 'w-greedy', g_greedy: 'g-greedy', random: 'random' };

// The static model's drawing (docs/OUTPUTS.md, "crux report"): contact forces 0.1 m per
// 100 N, as crux view draws them, and segments coloured by their joint's torque over its
// limit, green at 0, yellow at 0.5, red from 1 (the same ramp as crux view's).
const METRES_PER_NEWTON = 0.001;
const FORCE_COLOUR = 0x222222;
const RATIO_STOPS = [[26, 152, 80], [254, 224, 139], [215, 48, 39]];

export function torqueRatioColour(ratio) {
  const t = Math.min(Math.max(Number.isFinite(ratio) ? ratio : 1, 0), 1) * 2;
  const segment = Math.min(Math.floor(t), 1);
  const f = t - segment;
  const rgb = [0, 1, 2].map((c) => Math.round((1 - f) * RATIO_STOPS[segment][c] + f * RATIO_STOPS[segment + 1][c]));
  return `#${rgb.map((c) => c.toString(16).padStart(2, '0')).join('')}`;
}

function el(tag, props = {}, children = []) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'class') e.className = v;
    else if (k === 'text') e.textContent = v;
    else if (k in e) e[k] = v;
    else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

function fmt(x, digits) {
  return typeof x === 'number' && Number.isFinite(x) ? x.toFixed(digits) : '–';
}

// A value as it is (200000, -1, 0.25): JavaScript's shortest text that reads back to the number.
function exact(x) {
  return typeof x === 'number' && Number.isFinite(x) ? String(x) : '–';
}

export class ReplayViewer {
  constructor(container, data) {
    this.data = data;
    this.container = container;
    this.frame = 0;
    this.playing = false;
    this.speed = 1;
    this.perAnimationFrame = false;
    this.renderedFrames = 0;
    this.accumulator = 0;
    this.lastTime = null;
    this.dirty = true;
    this.follow = true;
    this.lastUiUpdate = 0;

    this.buildDom();
    this.buildScene();
    this.bindEvents();
    this.setFrame(0);
    this.loop = this.loop.bind(this);
    requestAnimationFrame(this.loop);
  }

  buildDom() {
    const c = this.container;
    c.classList.add('crux-replay');
    c.replaceChildren();
    this.view = el('div', { class: 'crux-replay-view', tabIndex: 0, 'aria-label': 'Replay of the climb: drag to orbit, wheel to zoom, space plays or pauses, arrows step between moves' });
    this.info = el('div', { class: 'crux-replay-info', 'aria-live': 'off' });
    this.playButton = el('button', { type: 'button', class: 'crux-replay-play', title: 'Play / pause (space)', text: 'Play' });
    this.prevButton = el('button', { type: 'button', title: 'Previous move (←)', text: '◀ Move' });
    this.nextButton = el('button', { type: 'button', title: 'Next move (→)', text: 'Move ▶' });
    this.slider = el('input', { type: 'range', class: 'crux-replay-slider', min: 0, max: this.data.frameCount - 1, step: 1, value: 0, 'aria-label': 'Frame' });
    this.speedSelect = el('select', { class: 'crux-replay-speed', title: this.data.performed ? 'Playback speed (1x = the simulated time)' : 'Playback speed (1x = 30 frames per second)', 'aria-label': 'Speed' },
      SPEEDS.map((s) => el('option', { value: String(s), text: `${s}x`, selected: s === 1 })));
    this.frameLabel = el('span', { class: 'crux-replay-frame' });
    this.followBox = el('input', { type: 'checkbox', checked: true });
    const follow = el('label', { class: 'crux-replay-follow', title: 'Keep the camera on the climber as it moves' }, [this.followBox, ' follow']);
    const controls = el('div', { class: 'crux-replay-controls' }, [
      this.prevButton, this.playButton, this.nextButton, this.slider, this.frameLabel,
      el('label', { class: 'crux-replay-speed-label' }, ['speed ', this.speedSelect]), follow,
    ]);
    const swatch = (colour, label, shape = 'dot') => el('span', { class: 'crux-replay-key' }, [
      el('span', { class: `crux-replay-swatch crux-replay-swatch-${shape}`, style: `--swatch: #${colour.toString(16).padStart(6, '0')}` }), label,
    ]);
    const legend = el('div', { class: 'crux-replay-legend' }, [
      swatch(COLORS.hold, 'hold'), swatch(COLORS.start, 'start hold', 'ring'), swatch(COLORS.held, 'held'),
      swatch(COLORS.reached, this.data.performed ? 'performed' : 'tried, reached'),
      swatch(COLORS.unreachable, this.data.performed ? 'failed' : 'tried, unreachable'),
      swatch(COLORS.grasp[0], 'grasp zone', 'ring'), swatch(COLORS.finish, 'finish height', 'line'),
    ]);
    if (this.data.performed) {
      legend.append(swatch(FORCE_COLOUR, 'force from the hold in MuJoCo, 0.1 m per 100 N', 'line'),
        swatch(COLORS.unreachable, 'where the move failed'));
    } else if (this.data.hasStances) {
      legend.append(swatch(FORCE_COLOUR, 'contact force, 0.1 m per 100 N', 'line'),
        swatch(parseInt(torqueRatioColour(0).slice(1), 16), 'joint torque 0'),
        swatch(parseInt(torqueRatioColour(0.5).slice(1), 16), '0.5'),
        swatch(parseInt(torqueRatioColour(1).slice(1), 16), '1 x its limit'));
    }
    const title = el('div', { class: 'crux-replay-title', text: this.data.title });
    c.append(title, this.view, this.info, controls, legend);
  }

  buildScene() {
    const data = this.data;
    // No MSAA: in software WebGL it halves the frame rate; the still view is drawn supersampled instead.
    this.renderer = new WebGLRenderer({ antialias: false, powerPreference: 'high-performance' });
    this.basePixelRatio = Math.min(window.devicePixelRatio || 1, 2);
    this.renderer.setPixelRatio(this.basePixelRatio);
    this.renderer.setClearColor(0xf6f7f9, 1);
    this.canvas = this.renderer.domElement;
    this.canvas.style.removeProperty('display'); // three sets display:block inline; report.css decides (print hides it)
    this.view.append(this.canvas);

    this.scene = new Scene();
    this.body = new Body(data.model);
    const q0 = data.postures.subarray(0, data.dof);
    this.body.apply(q0);
    this.body.root.updateMatrixWorld(true);
    let start = this.rootPosition();
    this.wall = new WallView(data, start.y);
    // Wall and body are in wall coordinates; an inclined wall turns them about y, its top
    // leaning towards the climber (x < 0) for an overhang, so that gravity is down.
    this.tilted = new Group();
    this.tilted.name = 'crux-wall-frame';
    this.tilted.rotation.y = -((data.wall.incline || 0) * Math.PI) / 180;
    this.tilted.add(this.wall.group, this.body.root);
    this.scene.add(this.tilted, this.wall.floor);
    this.tilted.updateMatrixWorld(true);
    start = this.rootPosition(); // in the world, where the camera looks

    // Grasp zones: translucent spheres of radius grasp_radius at the 4 grasp points.
    this.graspSpheres = this.body.grasp.map((g, i) => {
      const s = new Mesh(new SphereGeometry(data.graspRadius, 20, 14),
        new MeshBasicMaterial({ color: COLORS.grasp[i], transparent: true, opacity: 0.4, depthWrite: false, depthTest: false }));
      // Drawn last and through the body: the zone around a palm or a foot ball is mostly inside the hand or foot.
      s.name = `grasp-zone:${LIMBS[i]}`;
      s.renderOrder = 10;
      g.add(s);
      return s;
    });

    // The static model's contact forces, in the wall's frame, shown at the stances.
    this.forceArrows = data.hasForces ? LIMBS.map((limb) => {
      const arrow = new ArrowHelper(new Vector3(0, 0, 1), new Vector3(), 0.1, FORCE_COLOUR, 0.04, 0.025);
      arrow.name = `force:${limb}`;
      arrow.visible = false;
      // Drawn over the body, like the grasp zones: a force at a palm starts inside the hand.
      for (const part of [arrow.line, arrow.cone]) {
        part.material.depthTest = false;
        part.renderOrder = 11;
      }
      this.tilted.add(arrow);
      return arrow;
    }) : [];

    // A performed climb's failed move: a red ball where its free limb was when it failed.
    this.failure = data.performed ? this.failureMarker() : null;

    const hemi = new HemisphereLight(0xffffff, 0x8c8a86, 1.6);
    hemi.position.set(0, 0, 1); // z is up
    const sun = new DirectionalLight(0xffffff, 1.6);
    sun.position.set(-4, -2, 5);
    this.scene.add(hemi, sun, new AmbientLight(0xffffff, 0.25));

    // Camera: behind the climber (who faces +x, the wall) and slightly to its left side (+y), a
    // little above, so the climber's left limbs are on the left of the picture as in Fig. 1's front view.
    this.camera = new PerspectiveCamera(40, 1.6, 0.05, 100);
    this.camera.up.set(0, 0, 1);
    // The target sits above the torso so that the whole body and the wall above it (towards the
    // finish) are in view.
    const target = new Vector3(start.x + 0.25, start.y, start.z + 0.3);
    this.camera.position.copy(target).add(new Vector3(-4.2, 1.45, 0.55));
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.target.copy(target);
    this.controls.enableDamping = false;
    this.controls.update();
    this.lastRoot = start.clone();
  }

  failureMarker() {
    const data = this.data;
    const k = data.moves.findIndex((m) => !m.success);
    if (k < 0) return null;
    const move = data.moves[k];
    this.body.apply(data.postures, move.last_frame * data.dof);
    this.body.applyRootRotation(data.rootRotations, move.last_frame * 4);
    this.tilted.updateMatrixWorld(true);
    const p = this.body.graspWorld()[LIMBS.indexOf(move.limb)];
    const marker = new Mesh(new SphereGeometry(0.06, 20, 14),
      new MeshBasicMaterial({ color: COLORS.unreachable, transparent: true, opacity: 0.8, depthTest: false }));
    marker.name = 'failure';
    marker.renderOrder = 12;
    marker.position.copy(this.tilted.worldToLocal(new Vector3(p[0], p[1], p[2])));
    marker.visible = false;
    this.tilted.add(marker);
    return { marker, frame: move.last_frame };
  }

  rootPosition() {
    // The torso origin: the moving group of the last root joint (prismatic z).
    const i = this.data.model.joints.findIndex((j) => !j.prismatic);
    const anchor = this.body.moving[Math.max(0, (i < 0 ? this.data.dof : i) - 1)];
    return anchor.getWorldPosition(new Vector3());
  }

  bindEvents() {
    this.playButton.addEventListener('click', () => (this.playing ? this.pause() : this.play()));
    this.prevButton.addEventListener('click', () => this.stepMove(-1));
    this.nextButton.addEventListener('click', () => this.stepMove(1));
    this.slider.addEventListener('input', () => { this.pause(); this.setFrame(Number(this.slider.value)); });
    this.speedSelect.addEventListener('change', () => { this.speed = Number(this.speedSelect.value); });
    this.followBox.addEventListener('change', () => { this.follow = this.followBox.checked; });
    this.controls.addEventListener('change', () => { this.dirty = true; });
    this.view.addEventListener('pointerdown', () => this.view.focus({ preventScroll: true }));
    this.container.addEventListener('keydown', (e) => this.onKey(e));
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(this.view);
    this.resize();
    window.addEventListener('beforeprint', () => this.snapshotForPrint());
  }

  onKey(e) {
    const tag = e.target && e.target.tagName;
    if (tag === 'SELECT' || (tag === 'INPUT' && e.target.type !== 'checkbox' && e.key !== ' ')) return;
    if (e.key === ' ' || e.code === 'Space') {
      e.preventDefault();
      this.playing ? this.pause() : this.play();
    } else if (e.key === 'ArrowRight') {
      e.preventDefault();
      this.stepMove(1);
    } else if (e.key === 'ArrowLeft') {
      e.preventDefault();
      this.stepMove(-1);
    }
  }

  resize() {
    // The canvas fills the view; it has no size while hidden (print media shows a still instead).
    const w = this.canvas.clientWidth;
    const h = this.canvas.clientHeight;
    if (w === 0 || h === 0 || (w === this.width && h === this.height)) return;
    this.width = w;
    this.height = h;
    this.applyResolution();
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  applyResolution() {
    // Paused: 1.5x supersampling stands in for MSAA (the stills are what a reader looks at).
    const scale = this.playing ? 1 : 1.5;
    const ratio = Math.min(this.basePixelRatio * scale, 3);
    if (ratio !== this.renderer.getPixelRatio()) this.renderer.setPixelRatio(ratio);
    this.renderer.setSize(this.width, this.height, false);
  }

  /** Frame the step buttons go to: the end of a move (the state it leaves). */
  stepMove(direction) {
    this.pause();
    const moves = this.data.moves;
    if (moves.length === 0) return;
    const f = this.frame;
    let target;
    if (direction > 0) {
      const next = moves.find((m) => m.last_frame > f);
      target = next ? next.last_frame : this.data.frameCount - 1;
    } else {
      const prev = [...moves].reverse().find((m) => m.last_frame < f);
      target = prev ? prev.last_frame : 0;
    }
    this.setFrame(target);
  }

  play(options = {}) {
    this.perAnimationFrame = Boolean(options.perAnimationFrame);
    if (this.frame >= this.data.frameCount - 1) this.setFrame(0);
    this.playing = true;
    this.accumulator = 0;
    this.lastTime = null;
    this.applyResolution();
    this.playButton.textContent = 'Pause';
    this.playButton.setAttribute('aria-pressed', 'true');
  }

  pause() {
    const wasPlaying = this.playing;
    this.playing = false;
    this.perAnimationFrame = false;
    if (wasPlaying) {
      this.applyResolution();
      this.updateControls(this.frame);
      this.dirty = true;
    }
    this.playButton.textContent = 'Play';
    this.playButton.setAttribute('aria-pressed', 'false');
  }

  /** Shows frame i and renders it synchronously. */
  setFrame(i) {
    const data = this.data;
    const f = Math.max(0, Math.min(data.frameCount - 1, Math.round(Number(i)) || 0));
    this.frame = f;
    this.body.apply(data.postures, f * data.dof);
    if (data.performed) this.body.applyRootRotation(data.rootRotations, f * 4);
    this.body.root.updateMatrixWorld(true);
    if (this.failure) this.failure.marker.visible = f >= this.failure.frame;
    if (this.follow) {
      const root = this.rootPosition();
      const delta = new Vector3(0, root.y - this.lastRoot.y, root.z - this.lastRoot.z);
      if (delta.lengthSq() > 0) {
        this.camera.position.add(delta);
        this.controls.target.add(delta);
        this.controls.update();
      }
      this.lastRoot.copy(root);
    } else {
      this.lastRoot.copy(this.rootPosition());
    }
    this.showStance(data.stances[f]);
    const k = data.moveAt[f];
    const move = data.moves[k];
    this.wall.highlight(data, configurationAt(data, f), move ? move.hold : undefined, move ? move.success : false);
    this.updateInfo(f, k, move);
    this.render();
  }

  /** The stance's forces as arrows from the grasp points, its torque ratios on the segments. */
  showStance(stance) {
    if (!this.data.hasForces) return;
    const grasp = this.body.graspWorld();
    this.forceArrows.forEach((arrow, i) => {
      const force = stance ? stance.forces[i] : null;
      const newtons = force ? Math.hypot(force[0], force[1], force[2]) : 0;
      arrow.visible = newtons > 0;
      if (!arrow.visible) return;
      arrow.position.copy(this.tilted.worldToLocal(new Vector3(grasp[i][0], grasp[i][1], grasp[i][2])));
      arrow.setDirection(new Vector3(force[0], force[1], force[2]).divideScalar(newtons));
      const length = newtons * METRES_PER_NEWTON;
      arrow.setLength(length, Math.min(0.04, 0.5 * length), Math.min(0.025, 0.3 * length));
    });
    if (this.data.hasStances) this.body.paintByJoint(stance ? new Map(stance.joint_ratios) : null, torqueRatioColour);
    this.stance = stance;
  }

  /** The arrows drawn now, per limb: null when hidden, else origin, unit direction (wall coordinates) and length (m). */
  stanceArrows() {
    return this.forceArrows.map((a) => {
      if (!a.visible) return null;
      const d = new Vector3(0, 1, 0).applyQuaternion(a.quaternion);
      return { origin: [a.position.x, a.position.y, a.position.z], direction: [d.x, d.y, d.z], length: a.line.scale.y + a.cone.scale.y };
    });
  }

  updateInfo(f, k, move) {
    const data = this.data;
    const M = data.moves.length;
    let text;
    if (data.performed) {
      text = this.performedInfo(f, k, move);
    } else if (!move) {
      text = `No moves · frame ${f} of ${data.frameCount - 1}`;
    } else {
      const rise = move.root_rise_cm;
      text = [
        `Move ${k + 1} of ${M}`,
        move.iteration === null ? 'greedy policy, after learning' : `iteration ${move.iteration}`,
        REGIME_NAMES[move.regime] || move.regime,
        LIMB_NAMES[move.limb] || move.limb,
        `hold ${move.hold}`,
        move.success ? 'reached' : 'unreachable',
        `reward ${exact(move.reward)}`,
        `root rise ${typeof rise === 'number' && rise > 0 ? '+' : ''}${fmt(rise, 1)} cm`,
      ].join(' · ');
      if (this.stance) text += this.stance.effort === null ? ' · stance: no balance' : ` · stance effort ${fmt(this.stance.effort, 2)}`;
    }
    if (text !== this.infoText) {
      this.infoText = text;
      this.info.textContent = text;
      // A performed move has failed at its last frame; a learnt one is unreachable throughout.
      const failedFrom = move ? (data.performed ? move.last_frame : move.first_frame) : 0;
      this.info.classList.toggle('crux-replay-failed', Boolean(move) && !move.success && f >= failedFrom);
    }
    // While playing, the slider and frame counter follow at 10 Hz: repainting them every frame
    // costs more than the 3D view in a software-composited browser.
    const now = performance.now();
    if (!this.playing || now - this.lastUiUpdate >= 100) {
      this.lastUiUpdate = now;
      this.updateControls(f);
    }
  }

  /** The info line of a performed climb: the move under way, its outcome once it has one, the time. */
  performedInfo(f, k, move) {
    const data = this.data;
    const time = `t ${fmt(data.raw.frames.times[f], 2)} s`;
    if (!move) return `No moves performed · ${time}`;
    if (f < move.first_frame) return `The start stance settles on its four holds · ${time}`;
    const parts = [`Move ${k + 1} of ${data.raw.climb_moves}`, `${LIMB_NAMES[move.limb] || move.limb} to hold ${move.hold}`];
    if (f < move.last_frame) parts.push('under way');
    else parts.push(move.success ? 'performed' : `failed: ${move.cause_text || move.cause}`);
    parts.push(`peak torque ${fmt(move.max_torque_ratio, 2)} of its limit`, time);
    return parts.join(' · ');
  }

  updateControls(f) {
    this.slider.value = String(f);
    this.frameLabel.textContent = `frame ${f} / ${this.data.frameCount - 1}`;
  }

  render() {
    this.renderer.render(this.scene, this.camera);
    this.renderedFrames += 1;
    this.dirty = false;
  }

  loop(time) {
    requestAnimationFrame(this.loop);
    if (this.playing) {
      let advance = 0;
      if (this.perAnimationFrame) {
        advance = 1;
      } else {
        const dt = this.lastTime === null ? 0 : Math.min(0.25, (time - this.lastTime) / 1000);
        // 1x plays a performed climb in real time, any other at BASE_FPS.
        const fps = this.data.frameSeconds ? 1 / this.data.frameSeconds : BASE_FPS;
        this.accumulator += dt * fps * this.speed;
        advance = Math.floor(this.accumulator);
        this.accumulator -= advance;
      }
      this.lastTime = time;
      if (advance > 0) {
        const last = this.data.frameCount - 1;
        const next = Math.min(last, this.frame + advance);
        this.setFrame(next);
        if (next >= last) this.pause();
        return;
      }
    }
    if (this.dirty) this.render();
  }

  snapshotForPrint() {
    // A WebGL canvas does not print reliably: print a still image of the current view instead.
    this.render();
    let img = this.view.querySelector('img.crux-replay-print');
    if (!img) {
      img = el('img', { class: 'crux-replay-print', alt: 'Replay view at the current frame' });
      this.view.append(img);
    }
    img.src = this.canvas.toDataURL('image/png');
  }

  /** A point of the wall frame (wall coordinates) in the world the camera sees. */
  wallToWorld(p) {
    const v = this.tilted.localToWorld(new Vector3(p[0], p[1], p[2]));
    return [v.x, v.y, v.z];
  }

  /** The grasp points at frame i in wall coordinates, as crux computes them. */
  graspPoints(i) {
    this.setFrame(i);
    return this.body.graspWorld().map((p) => {
      const v = this.tilted.worldToLocal(new Vector3(p[0], p[1], p[2]));
      return [v.x, v.y, v.z];
    });
  }

  /** The grasp points at frame i as the camera shows them now: [x, y] in [-1, 1], x to the right. */
  screenPoints(i) {
    this.setFrame(i);
    this.camera.updateMatrixWorld();
    return this.body.graspWorld().map((p) => {
      const v = new Vector3(p[0], p[1], p[2]).project(this.camera);
      return [v.x, v.y];
    });
  }
}
