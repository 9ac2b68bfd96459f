/**
 * The app's entry: with ?renderer=webgpu the WebGPURenderer app (appWebGPU.ts) starts, which
 * falls back to WebGPURenderer's WebGL2 backend by itself and says why it cannot start; else,
 * without WebGL2 (which three.js and the simulation need) the page says so in words instead of
 * showing a blank canvas, and with it the app (app.ts) starts.
 */
import { parseState } from './urlState';

function hasWebGL2(): boolean {
  try {
    return document.createElement('canvas').getContext('webgl2') !== null;
  } catch {
    return false;
  }
}

if (parseState(location.search).state.renderer === 'webgpu') {
  void import('./appWebGPU');
} else if (hasWebGL2()) {
  void import('./app').then(({ startApp }) => startApp());
} else {
  const message = document.createElement('div');
  message.className = 'no-webgl';
  message.innerHTML =
    '<h1>This ocean needs WebGL2</h1>' +
    '<p>Your browser or device does not offer WebGL2, so the simulated sea cannot be drawn here. ' +
    'Recent versions of Chrome, Edge, Firefox and Safari support it; check that hardware ' +
    'acceleration is turned on in the browser settings.</p>';
  document.querySelector('#app')?.appendChild(message);
  document.querySelector('#status')?.remove();
}
