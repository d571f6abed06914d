// Entry point of replay.bundle.js: builds each replay the page holds, a
// <script type="application/json" id="X-data"> beside a <div id="X">: the climb's replay (X = crux-replay,
// as window.cruxReplay) and, beside it, a climb performed in MuJoCo (X = crux-performed, as
// window.cruxPerformed); a page without them is left alone.
import { prepareReplayData } from './data.js';
import { ReplayViewer } from './viewer.js';

function mount(id) {
  const dataElement = document.getElementById(`${id}-data`);
  const container = document.getElementById(id);
  if (!dataElement || !container) return null;
  const data = prepareReplayData(JSON.parse(dataElement.textContent));
  const viewer = new ReplayViewer(container, data);
  return {
    ready: true,
    performed: data.performed,
    frameCount: data.frameCount,
    get frame() { return viewer.frame; },
    setFrame: (i) => viewer.setFrame(i),
    play: (options) => viewer.play(options),
    pause: () => viewer.pause(),
    get renderedFrames() { return viewer.renderedFrames; },
    get infoText() { return viewer.infoText; },
    graspPoints: (i) => viewer.graspPoints(i),
    screenPoints: (i) => viewer.screenPoints(i),
    wallToWorld: (p) => viewer.wallToWorld(p),
    get playing() { return viewer.playing; },
    stanceArrows: () => viewer.stanceArrows(),
    failureShown: () => Boolean(viewer.failure && viewer.failure.marker.visible),
  };
}

function start() {
  const replay = mount('crux-replay');
  if (replay) window.cruxReplay = replay;
  const performed = mount('crux-performed');
  if (performed) window.cruxPerformed = performed;
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start, { once: true });
else start();
