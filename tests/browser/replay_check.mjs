#!/usr/bin/env node
// Browser test of a crux report's 3D replay, in Debian's headless chromium (no browser download).
//
//   node replay_check.mjs --report FILE.html --out DIR [--expect-figures N] [--fps] [--npm-dir DIR]
//
// Fails (exit 1, with the reasons) on any console error or warning, page error, or network request
// other than the page's own file URL; checks that the replay becomes ready, draws a non-blank
// canvas, draws frame 0 and the middle frame differently, shows the first move's reward as it is
// (the shortest text of the number, not a fixed count of decimals), puts the grasp points where the C++
// forward kinematics put them (data.check, within 1e-6 m), puts the left hand and foot on the
// same side as Fig. 1's front view does (left of the right ones), shows at least N SVG figures in
// #figures, plays when Play is clicked and steps with the keyboard. A page may hold two replays, the climb's
// and one performed in MuJoCo (the hold forces and the failed move are checked there too); each is checked. Saves replay_start.png,
// replay_middle.png and page.png into DIR. With --fps, plays one replay frame per animation frame
// for about 5 s and prints {"fps": ...} measured from cruxReplay.renderedFrames.
//
// playwright-core is loaded from build/npm/node_modules (scripts/setup_web.sh), or --npm-dir /
// CRUX_NPM_DIR (the folder that holds node_modules).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { createRequire } from 'node:module';
import { fileURLToPath, pathToFileURL } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));

// Headless chromium on a machine without a GPU: WebGL runs on SwiftShader (software), which
// chromium no longer falls back to on its own; --use-angle=swiftshader selects ANGLE's SwiftShader
// backend and --enable-unsafe-swiftshader allows WebGL on it (without it the WebGL context is
// refused or comes with a deprecation warning in the console, which this test treats as a failure).
export const CHROMIUM_ARGS = [
  '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync',
  '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
];

// With --disable-gpu the page is composited in software, so chromium reads every WebGL frame back
// from SwiftShader and logs its own ANGLE performance note for it (4 times, then "will no longer
// repeat"), whatever the page draws. Only that exact message is tolerated (and counted);
// any other console warning or error fails the test.
const CHROMIUM_READBACK_NOTE = /^\[\.WebGL-0x[0-9a-f]+\]GL Driver Message \(OpenGL, Performance, GL_CLOSE_PATH_NV, High\): GPU stall due to ReadPixels( \(this message will no longer repeat\))?$/;

function usage(message) {
  if (message) console.error(`replay_check: ${message}`);
  console.error('usage: node replay_check.mjs --report FILE --out DIR [--expect-figures N] [--fps] [--npm-dir DIR]');
  process.exit(2);
}

function parseArgs(argv) {
  const a = { report: null, out: null, expectFigures: null, fps: false, npmDir: process.env.CRUX_NPM_DIR || path.resolve(here, '../../build/npm'), chromium: '/usr/bin/chromium' };
  for (let i = 0; i < argv.length; ++i) {
    const k = argv[i];
    const value = () => { if (i + 1 >= argv.length) usage(`${k} needs a value`); return argv[++i]; };
    if (k === '--report') a.report = value();
    else if (k === '--out') a.out = value();
    else if (k === '--expect-figures') { a.expectFigures = Number(value()); if (!Number.isInteger(a.expectFigures) || a.expectFigures < 0) usage('--expect-figures needs a count'); }
    else if (k === '--fps') a.fps = true;
    else if (k === '--npm-dir') a.npmDir = value();
    else if (k === '--chromium') a.chromium = value();
    else if (k === '--help' || k === '-h') usage();
    else usage(`unknown argument ${k}`);
  }
  if (!a.report || !a.out) usage('--report and --out are required');
  return a;
}

// ---- a minimal PNG decoder (8-bit greyscale/RGB/RGBA, not interlaced): what chromium writes ----
export function decodePng(buf) {
  if (buf.readUInt32BE(0) !== 0x89504e47) throw new Error('not a PNG');
  let off = 8, width = 0, height = 0, bitDepth = 0, colorType = 0, interlace = 0;
  const idat = [];
  while (off < buf.length) {
    const len = buf.readUInt32BE(off);
    const type = buf.toString('latin1', off + 4, off + 8);
    const body = buf.subarray(off + 8, off + 8 + len);
    if (type === 'IHDR') {
      width = body.readUInt32BE(0); height = body.readUInt32BE(4);
      bitDepth = body[8]; colorType = body[9]; interlace = body[12];
    } else if (type === 'IDAT') idat.push(body);
    else if (type === 'IEND') break;
    off += 12 + len;
  }
  const channels = { 0: 1, 2: 3, 4: 2, 6: 4 }[colorType];
  if (bitDepth !== 8 || !channels || interlace) throw new Error(`unsupported PNG (depth ${bitDepth}, type ${colorType}, interlace ${interlace})`);
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const stride = width * channels;
  const px = Buffer.alloc(stride * height);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    const out = px.subarray(y * stride, (y + 1) * stride);
    const prev = y > 0 ? px.subarray((y - 1) * stride, y * stride) : null;
    for (let x = 0; x < stride; ++x) {
      const a = x >= channels ? out[x - channels] : 0;
      const b = prev ? prev[x] : 0;
      const c = prev && x >= channels ? prev[x - channels] : 0;
      let v = line[x];
      if (filter === 1) v += a;
      else if (filter === 2) v += b;
      else if (filter === 3) v += (a + b) >> 1;
      else if (filter === 4) { const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c); v += pa <= pb && pa <= pc ? a : pb <= pc ? b : c; }
      out[x] = v & 0xff;
    }
  }
  return { width, height, channels, px };
}

function luminance(img) {
  const n = img.width * img.height;
  const lum = new Float64Array(n);
  for (let i = 0; i < n; ++i) {
    const p = i * img.channels;
    lum[i] = img.channels >= 3 ? 0.299 * img.px[p] + 0.587 * img.px[p + 1] + 0.114 * img.px[p + 2] : img.px[p];
  }
  return lum;
}

function variance(values) {
  let s = 0, s2 = 0;
  for (const v of values) { s += v; s2 += v * v; }
  const m = s / values.length;
  return s2 / values.length - m * m;
}

function changedPixels(a, b) {
  if (a.length !== b.length) return Infinity;
  let n = 0;
  for (let i = 0; i < a.length; ++i) if (Math.abs(a[i] - b[i]) > 8) ++n;
  return n;
}

// Checks one replay of the page: the climb's (id crux-replay, window.cruxReplay) or the one
// performed in MuJoCo (crux-performed, window.cruxPerformed); its screenshots are named `prefix`_*.png.
async function checkReplay(page, id, global, prefix, args, fail) {
  const sides = {};
  try {
    await page.waitForFunction((g) => window[g] && window[g].ready === true, global, { timeout: 30000 });
  } catch {
    throw new Error(`window.${global}.ready never became true`);
  }

  await page.evaluate(([g, i]) => { window.cruxCheck = window[g]; window.cruxCheckId = i; }, [global, id]);
  const info = await page.evaluate(() => {
    const data = JSON.parse(document.getElementById(`${window.cruxCheckId}-data`).textContent);
    return { performed: data.performed === true, check: data.check, frameCount: data.frames.count, moves: data.moves.length, firstMoveEnd: data.moves.length ? data.moves[0].last_frame : 0, firstReward: data.moves.length ? data.moves[0].reward : null };
  });
  const count = await page.evaluate(() => window.cruxCheck.frameCount);
  if (count !== info.frameCount) fail(`${global}.frameCount ${count} != frames.count ${info.frameCount}`);

  const canvas = page.locator(`#${id} canvas`);
  const panel = page.locator(`#${id}`);
  await canvas.scrollIntoViewIfNeeded();
  const middle = Math.floor((info.frameCount - 1) / 2);
  await page.evaluate(() => window.cruxCheck.setFrame(0));
  const shotStart = await canvas.screenshot();
  await panel.screenshot({ path: path.join(args.out, `${prefix}_start.png`) });
  const startInfo = await page.locator(`#${id} .crux-replay-info`).textContent();
  if (!info.performed && info.moves > 0 && !/Move 1 of \d+/.test(startInfo)) fail(`info line at frame 0 does not say "Move 1 of M": ${startInfo}`);
  // The reward as it is (200000, not 200000.000): the shortest text that reads back to it.
  if (!info.performed && info.moves > 0 && !startInfo.includes(` · reward ${String(info.firstReward)} · `)) fail(`info line at frame 0 does not show the reward ${info.firstReward} as it is: ${startInfo}`);
  await page.evaluate((f) => window.cruxCheck.setFrame(f), middle);
  const shotMiddle = await canvas.screenshot();
  await panel.screenshot({ path: path.join(args.out, `${prefix}_middle.png`) });
  const lumStart = luminance(decodePng(shotStart));
  const lumMiddle = luminance(decodePng(shotMiddle));
  const v = variance(lumStart);
  if (!(v > 25)) fail(`the canvas looks blank (luminance variance ${v.toFixed(2)})`);
  const changed = changedPixels(lumStart, lumMiddle);
  if (middle > 0 && !(changed > 50)) fail(`frames 0 and ${middle} render the same image (${changed} pixels differ)`);

  if (info.check) {
    const got = await page.evaluate((f) => window.cruxCheck.graspPoints(f), info.check.frame);
    let worst = 0;
    info.check.grasp_points.forEach((p, i) => p.forEach((x, k) => { worst = Math.max(worst, Math.abs(x - got[i][k])); }));
    if (!(worst <= 1e-6)) fail(`grasp points at frame ${info.check.frame} are off by ${worst.toExponential(3)} m (> 1e-6): got ${JSON.stringify(got)}, expected ${JSON.stringify(info.check.grasp_points)}`);
  } else fail('the data has no check');

  // Issue 26: under the static model each stance draws its contact forces: one arrow per
  // held limb from its grasp point, along the force, 0.1 m per 100 N; none while a limb moves.
  const stanceData = await page.evaluate(() => {
    const raw = JSON.parse(document.getElementById(`${window.cruxCheckId}-data`).textContent);
    if (raw.start_stance === undefined) return null;
    const moving = raw.moves.find((m) => m.success && m.last_frame > m.first_frame);
    return { start: raw.start_stance.forces, movingFrame: moving ? moving.first_frame : null };
  });
  if (stanceData) {
    const grasp = await page.evaluate(() => window.cruxCheck.graspPoints(0));
    const arrows = await page.evaluate(() => window.cruxCheck.stanceArrows());
    stanceData.start.forEach((force, i) => {
      const arrow = arrows[i];
      if (force === null) { if (arrow !== null) fail(`limb ${i} holds nothing at the start but has an arrow`); return; }
      if (arrow === null) fail(`limb ${i}'s start force has no arrow`);
      const n = Math.hypot(...force);
      const worst = Math.max(...force.map((x, k) => Math.abs(x / n - arrow.direction[k])), ...grasp[i].map((x, k) => Math.abs(x - arrow.origin[k])));
      if (!(worst <= 1e-6) || !(Math.abs(arrow.length - 0.001 * n) <= 1e-6)) fail(`limb ${i}'s arrow ${JSON.stringify(arrow)} is not its force ${JSON.stringify(force)} at ${JSON.stringify(grasp[i])}`);
    });
    await panel.screenshot({ path: path.join(args.out, `${prefix}_stance.png`) });
    if (stanceData.movingFrame !== null) {
      const during = await page.evaluate((f) => { window.cruxCheck.setFrame(f); return window.cruxCheck.stanceArrows(); }, stanceData.movingFrame);
      if (during.some((a) => a !== null)) fail(`frame ${stanceData.movingFrame}, during a move, still draws forces`);
    }
  }

  // Issue 26: an inclined wall stands as it does in the world: a metre up the wall is
  // (-sin, 0, cos) of the incline (its top leans towards the climber, at x < 0, on an overhang).
  const incline = await page.evaluate(() => JSON.parse(document.getElementById(`${window.cruxCheckId}-data`).textContent).wall.incline || 0);
  const up = await page.evaluate(() => window.cruxCheck.wallToWorld([0, 0, 1]));
  const theta = (incline * Math.PI) / 180;
  const expectedUp = [-Math.sin(theta), 0, Math.cos(theta)];
  if (!up.every((x, k) => Math.abs(x - expectedUp[k]) <= 1e-9)) fail(`the wall of incline ${incline} degrees stands at ${JSON.stringify(up)}, expected ${JSON.stringify(expectedUp)}`);

  // Issue 26: Fig. 1's front view and the replay's first view both look at the climber from
  // behind, so each puts the left hand and the left foot left of the right ones, as the page
  // shows them (the replay's start frame is Fig. 1's posture).
  const shown = await page.evaluate(() => window.cruxCheck.screenPoints(0));
  const figure = await page.evaluate(() => {
    const svg = [...document.querySelectorAll('#figures svg')].find((s) => s.textContent.includes('front, from behind the climber'));
    if (!svg) return null;
    const front = svg.querySelector('g.grasp-spheres'); // the front panel is drawn first
    const x = (limb) => Number(front.querySelector(`circle[data-limb="${limb}"]`).getAttribute('cx'));
    return { RH: x('RH'), LH: x('LH'), RF: x('RF'), LF: x('LF') };
  });
  // (A page without Fig. 1, such as the fixture's, has the replay's side checked alone.)
  if (figure && !(figure.LH < figure.RH && figure.LF < figure.RF)) fail(`Fig. 1's front view puts a left limb right of the right one: ${JSON.stringify(figure)}`);
  const [rh, lh, rf, lf] = shown;
  if (!(lh[0] < rh[0] && lf[0] < rf[0])) fail(`the replay's first view puts a left limb right of the right one: ${JSON.stringify(shown)}`);
  sides.checked = figure ? 'Fig. 1 and the replay' : 'the replay';

  // Play: the frame advances.
  await page.evaluate(() => window.cruxCheck.setFrame(0));
  await page.locator(`#${id} button.crux-replay-play`).click();
  await page.waitForTimeout(700);
  const played = await page.evaluate(() => { const f = window.cruxCheck.frame; window.cruxCheck.pause(); return f; });
  if (!(played > 0)) fail('clicking Play did not advance the frame');

  // Keyboard: arrow right steps to the end of the first move, space plays.
  await page.evaluate(() => window.cruxCheck.setFrame(0));
  await page.locator(`#${id} .crux-replay-view`).focus();
  await page.keyboard.press('ArrowRight');
  const stepped = await page.evaluate(() => window.cruxCheck.frame);
  if (info.moves > 0 && stepped !== info.firstMoveEnd) fail(`ArrowRight went to frame ${stepped}, expected ${info.firstMoveEnd}`);
  await page.keyboard.press('ArrowLeft');
  const back = await page.evaluate(() => window.cruxCheck.frame);
  if (back !== 0) fail(`ArrowLeft went to frame ${back}, expected 0`);
  await page.keyboard.press('Space');
  await page.waitForTimeout(300);
  const spacePlayed = await page.evaluate(() => { const p = window.cruxCheck.playing; window.cruxCheck.pause(); return p; });
  if (!spacePlayed) fail('space did not start playing');

  return { middle, sides: sides.checked };
}

// A replay performed in MuJoCo: each limb's force from its hold drawn from its grasp point
// (0.1 m per 100 N) as the frame records it, and a failed move's end marked, its cause in words.
async function checkPerformed(page, args, fail) {
  const facts = await page.evaluate(() => {
    const raw = JSON.parse(document.getElementById('crux-performed-data').textContent);
    const f = raw.moves.length ? raw.moves[0].first_frame : 0;
    const forces = [0, 1, 2, 3].map((i) => raw.frames.hold_forces.slice(12 * f + 3 * i, 12 * f + 3 * i + 3));
    return { frame: f, forces, failed: raw.moves.find((m) => !m.success) || null };
  });
  const grasp = await page.evaluate((f) => window.cruxPerformed.graspPoints(f), facts.frame);
  const arrows = await page.evaluate(() => window.cruxPerformed.stanceArrows());
  let drawn = 0;
  facts.forces.forEach((force, i) => {
    const n = Math.hypot(...force);
    const arrow = arrows[i];
    if (n === 0) { if (arrow !== null) fail(`frame ${facts.frame}: limb ${i} has no hold force but an arrow`); return; }
    if (arrow === null) { fail(`frame ${facts.frame}: limb ${i}'s hold force has no arrow`); return; }
    drawn += 1;
    const worst = Math.max(...force.map((x, k) => Math.abs(x / n - arrow.direction[k])), ...grasp[i].map((x, k) => Math.abs(x - arrow.origin[k])));
    if (!(worst <= 1e-6) || !(Math.abs(arrow.length - 0.001 * n) <= 1e-6)) fail(`frame ${facts.frame}: limb ${i}'s arrow ${JSON.stringify(arrow)} is not its force ${JSON.stringify(force)} at ${JSON.stringify(grasp[i])}`);
  });
  if (drawn < 3) fail(`frame ${facts.frame}, the first move's start, draws ${drawn} hold forces, expected at least 3`);
  if (facts.failed) {
    await page.evaluate(() => window.cruxPerformed.setFrame(0));
    if (await page.evaluate(() => window.cruxPerformed.failureShown())) fail('the failure is marked at frame 0, before the move failed');
    await page.evaluate((f) => window.cruxPerformed.setFrame(f), facts.failed.last_frame);
    const text = await page.locator('#crux-performed .crux-replay-info').textContent();
    if (!text.includes(`failed: ${facts.failed.cause_text}`)) fail(`the failed move's end does not say "failed: ${facts.failed.cause_text}": ${text}`);
    if (!(await page.evaluate(() => window.cruxPerformed.failureShown()))) fail('the failed move\'s end is not marked');
    await page.locator('#crux-performed').screenshot({ path: path.join(args.out, 'performed_failed.png') });
  }
}

async function main() {
  const args = parseArgs(process.argv.slice(2));
  const reportPath = path.resolve(args.report);
  if (!fs.existsSync(reportPath)) usage(`no report at ${reportPath}`);
  const require = createRequire(path.join(args.npmDir, 'package.json'));
  let chromium;
  try {
    ({ chromium } = require('playwright-core'));
  } catch (e) {
    console.error(`replay_check: cannot load playwright-core from ${args.npmDir}/node_modules: run scripts/setup.sh (${e.message})`);
    process.exit(1);
  }
  if (!fs.existsSync(args.chromium)) {
    console.error(`replay_check: no chromium at ${args.chromium}: run scripts/setup.sh (Debian's chromium package)`);
    process.exit(1);
  }
  fs.mkdirSync(args.out, { recursive: true });
  const pageUrl = pathToFileURL(reportPath).href;
  const problems = [];
  const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'crux-replay-check-'));
  const context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: args.chromium,
    headless: true,
    args: CHROMIUM_ARGS,
    viewport: { width: 1280, height: 900 },
    deviceScaleFactor: 1,
    offline: false,
  });
  const fail = (message) => { problems.push(message); };
  let readbackNotes = 0;
  let sidesChecked = 'nothing';
  let page;
  try {
    context.on('request', (r) => {
      const url = r.url();
      if (url !== pageUrl && !url.startsWith('data:') && !url.startsWith('blob:')) fail(`network request: ${r.method()} ${url}`);
    });
    page = context.pages()[0] || await context.newPage();
    page.on('console', (m) => {
      if (m.type() !== 'error' && m.type() !== 'warning') return;
      if (m.type() === 'warning' && CHROMIUM_READBACK_NOTE.test(m.text())) { readbackNotes += 1; return; }
      fail(`console ${m.type()}: ${m.text()}`);
    });
    page.on('pageerror', (e) => fail(`page error: ${e.message}`));
    await page.goto(pageUrl, { waitUntil: 'load' });
    const replays = await page.evaluate(() => ['crux-replay', 'crux-performed'].filter((i) => document.getElementById(`${i}-data`)));
    if (replays.length === 0) throw new Error('the page holds no replay');
    let last = null;
    for (const id of replays) {
      const performed = id === 'crux-performed';
      last = await checkReplay(page, id, performed ? 'cruxPerformed' : 'cruxReplay', performed ? 'performed' : 'replay', args, fail);
      if (performed) await checkPerformed(page, args, fail);
      sidesChecked = last.sides;
    }

    if (args.expectFigures !== null) {
      const svgs = await page.evaluate(() => document.querySelectorAll('#figures svg').length);
      if (svgs < args.expectFigures) fail(`#figures holds ${svgs} svg elements, expected at least ${args.expectFigures}`);
    }

    await page.evaluate((f) => window.cruxCheck.setFrame(f), last.middle);
    await page.screenshot({ path: path.join(args.out, 'page.png'), fullPage: true });

    if (args.fps) {
      const r = await page.evaluate(async () => {
        const R = window.cruxCheck;
        R.pause();
        R.setFrame(0);
        await new Promise((ok) => requestAnimationFrame(() => ok()));
        const r0 = R.renderedFrames, f0 = R.frame, t0 = performance.now();
        R.play({ perAnimationFrame: true });
        while (performance.now() - t0 < 5000 && R.playing) await new Promise((ok) => setTimeout(ok, 50));
        const t1 = performance.now(), r1 = R.renderedFrames, f1 = R.frame;
        R.pause();
        return { rendered: r1 - r0, advanced: f1 - f0, seconds: (t1 - t0) / 1000 };
      });
      const fps = r.rendered / r.seconds;
      console.log(JSON.stringify({ fps: Number(fps.toFixed(1)), rendered_frames: r.rendered, replay_frames_advanced: r.advanced, seconds: Number(r.seconds.toFixed(2)), frame_count: info.frameCount }));
    }
  } catch (e) {
    fail(e.message);
  } finally {
    await context.close();
    fs.rmSync(userDataDir, { recursive: true, force: true });
  }
  if (problems.length > 0) {
    console.error(`replay_check: FAILED for ${reportPath}`);
    for (const p of problems) console.error(`  - ${p}`);
    process.exit(1);
  }
  const note = readbackNotes ? ` (ignored ${readbackNotes} chromium ReadPixels note${readbackNotes > 1 ? 's' : ''} of software compositing)` : '';
  console.error(`replay_check: ok (${reportPath}); left limbs on the left in ${sidesChecked}; screenshots in ${path.resolve(args.out)}${note}`);
}

main().catch((e) => { console.error(`replay_check: ${e.stack || e}`); process.exit(1); });
