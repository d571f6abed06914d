// Entry point of replay.bundle.js: builds each replay the page holds, a <script type="application/json">
// of its data beside its <div>: the climb's replay (crux-replay-data, crux-replay; window.cruxReplay) and,
// beside it, a climb performed in MuJoCo (crux-performed-data, crux-performed; window.cruxPerformed). A page
// without them is left alone.
import { prepareReplayData } from './data.js';
import { ReplayViewer } from './viewer.js';

function mount(containerId, dataId) {
  const dataElement = document.getElementById(dataId);
  const container = document.getElementById(containerId);
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
  const replay = mount('crux-replay', 'crux-replay-data');
  if (replay) window.cruxReplay = replay;
  const performed = mount('crux-performed', 'crux-performed-data');
  if (performed) window.cruxPerformed = performed;
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start, { once: true });
else start();
