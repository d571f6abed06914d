// Entry point of replay.bundle.js: builds the replay when the page holds both
// <script type="application/json" id="crux-replay-data"> and <div id="crux-replay">; otherwise does nothing.
import { prepareReplayData } from './data.js';
import { ReplayViewer } from './viewer.js';

function start() {
  const dataElement = document.getElementById('crux-replay-data');
  const container = document.getElementById('crux-replay');
  if (!dataElement || !container) return;
  const data = prepareReplayData(JSON.parse(dataElement.textContent));
  const viewer = new ReplayViewer(container, data);
  window.cruxReplay = {
    ready: true,
    frameCount: data.frameCount,
    get frame() { return viewer.frame; },
    setFrame: (i) => viewer.setFrame(i),
    play: (options) => viewer.play(options),
    pause: () => viewer.pause(),
    get renderedFrames() { return viewer.renderedFrames; },
    graspPoints: (i) => viewer.graspPoints(i),
    screenPoints: (i) => viewer.screenPoints(i),
    wallToWorld: (p) => viewer.wallToWorld(p),
    get playing() { return viewer.playing; },
    stanceArrows: () => viewer.stanceArrows(),
  };
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start, { once: true });
else start();
