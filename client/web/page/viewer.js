// The page around ocean-web.wasm: the connect box, the canvas size, the progress line over the sea
// until its first frame (the module's download, the connection, the first frame), and a report a
// test can read.
// Query parameters: ws=URL (the server's WebSocket; default: the port /ocean-web.json names, on
// this page's host), profile=ID, connect=1 (connect at once), record=1 (keep the received
// messages), ui=0 (no panel or help over the sea, for screenshots), scale=S (render at S times
// the page's pixels, 0.25..1, stretched to fit: for a device too weak for its own screen),
// report=SECONDS (after that long, write the report into #report and stop), follow=ID (the camera
// follows vessel ID from behind and above, as the V key or a double tap do), camera=X,Y,Z,PITCH,YAW
// (the eye's place in world metres and its turn in degrees, as ocean-viewer's flags).
'use strict';
const params = new URLSearchParams(location.search);
const canvas = document.getElementById('ocean');
const statusLine = document.getElementById('status');
const progress = document.getElementById('progress');
// Asked for at once, beside the module's download: the WebSocket's port and the module's size.
const pageConfig = fetch('ocean-web.json').then((r) => r.json()).catch(() => ({}));
let wasmBytes = 0;
pageConfig.then((config) => { wasmBytes = Number(config.wasm_bytes) || 0; });
// When the module arrived and the runtime was ready, in ms from navigation (for the first-frame test).
window.oceanStages = {};

const scale = Math.min(1, Math.max(0.25, Number(params.get('scale')) || 1));  // not a number: 1

function fitCanvas() {
  const ratio = (window.devicePixelRatio || 1) * scale;
  canvas.width = Math.round(canvas.clientWidth * ratio);
  canvas.height = Math.round(canvas.clientHeight * ratio);
}
window.addEventListener('resize', fitCanvas);
fitCanvas();
if (params.get('ui') === '0')
  for (const id of ['panel', 'help']) document.getElementById(id).hidden = true;

async function defaultServer() {
  if (params.get('ws')) return params.get('ws');
  const config = await pageConfig;  // {} when opened from a file or another server: the user types it
  if (!config.ws_port) return '';
  // An https page may open only wss (the server serves both with --tls-cert).
  return `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.hostname}:${config.ws_port}/`;
}

// The line over the sea until its first frame: what the page is waiting for.
function showProgress(text) {
  progress.textContent = text;
  progress.hidden = !text;
}

function report() {
  return JSON.parse(Module.UTF8ToString(Module.ccall('ocean_web_report', 'number', [], [])));
}

function connect() {
  const url = document.getElementById('server').value.trim();
  const profile = Number(document.getElementById('profile').value);
  let parsed = null;
  try { parsed = new URL(url); } catch (e) { /* not a URL: said below */ }
  if (!parsed || (parsed.protocol !== 'ws:' && parsed.protocol !== 'wss:')) {
    statusLine.textContent = `'${url}' is not a WebSocket address: type one like ws://host:7702/`;
    return;
  }
  try {
    Module.ccall('ocean_web_connect', null, ['string', 'number'], [url, profile]);
    showStatus();
  } catch (e) {
    Module.ccall('ocean_web_disconnect', null, [], []);
    statusLine.textContent = `cannot connect to ${url}: ${e.message}`;
    return;
  }
  canvas.focus();
}

function showStatus() {
  const r = report();
  let text = `${r.state}`;
  if (r.profile) text += ` · ${r.profile} ${r.grid}² · ${r.frames} frames · ${r.decode_ms_per_frame.toFixed(2)} ms decode`;
  if (r.state === 'closed' && r.close_reason) text += ` · ${r.close_reason}`;
  statusLine.textContent = text;
  const waiting = r.first_frame_ms < 0;
  if (r.state === 'connecting') showProgress(`connecting to ${document.getElementById('server').value.trim()}...`);
  else if (r.state === 'streaming') showProgress(waiting ? `${r.profile}: waiting for the first frame...` : '');
  else if ((r.state === 'closed' || r.state === 'failed') && waiting) showProgress(`no stream: ${r.close_reason}`);
  else showProgress('');
}

function finishReport() {
  const r = report();
  if (params.get('record') === '1')
    r.messages = Module.UTF8ToString(Module.ccall('ocean_web_recorded_messages', 'number', [], []));
  Module.ccall('ocean_web_disconnect', null, [], []);
  const out = document.getElementById('report');
  out.textContent = JSON.stringify(r);
  out.hidden = false;
  document.title = 'ocean-web report ready';
}

// The module's download with its progress, compiled as it arrives (as Emscripten's own loader does).
function instantiateWasm(imports, receiveInstance) {
  fetch('ocean-web.wasm').then((response) => {
    if (!response.ok) throw new Error(`HTTP ${response.status}`);
    let received = 0;
    const counting = new TransformStream({
      transform(chunk, out) {
        received += chunk.byteLength;
        const kb = (n) => Math.round(n / 1024);
        showProgress(wasmBytes ? `loading the viewer: ${Math.min(100, Math.round(100 * received / wasmBytes))} % of ${kb(wasmBytes)} KB`
                               : `loading the viewer: ${kb(received)} KB`);
        out.enqueue(chunk);
      },
    });
    const body = new Response(response.body.pipeThrough(counting), { headers: { 'Content-Type': 'application/wasm' } });
    return WebAssembly.instantiateStreaming(body, imports);
  }).then((result) => {
    window.oceanStages.module = performance.now();
    showProgress('starting the viewer...');
    receiveInstance(result.instance, result.module);
  }).catch((e) => showProgress(`cannot load the viewer (ocean-web.wasm): ${e.message}`));
  return {};  // the exports arrive through receiveInstance
}

// A browser without streams or streaming compilation (Safari before 14.1) loads the module with
// Emscripten's own loader: the same module, only no per cent on the way.
const canCountDownload = typeof TransformStream === 'function' && typeof WebAssembly.instantiateStreaming === 'function';

var Module = {
  canvas,
  instantiateWasm: canCountDownload ? instantiateWasm : undefined,
  print: (text) => console.log(text),
  printErr: (text) => console.warn(text),
  onRuntimeInitialized: async () => {
    window.oceanStages.ready = performance.now();
    showProgress('');
    document.getElementById('server').value = await defaultServer();
    if (params.get('profile') !== null) document.getElementById('profile').value = params.get('profile');
    document.getElementById('connect').addEventListener('submit', (e) => { e.preventDefault(); connect(); });
    statusLine.textContent = 'ready';
    setInterval(showStatus, 250);
    if (params.get('record') === '1') Module.ccall('ocean_web_record', null, ['number'], [1]);
    if (params.get('connect') === '1') connect();
    const eye = (params.get('camera') || '').split(',').map(Number);
    if (eye.length === 5 && eye.every(Number.isFinite)) Module.ccall('ocean_web_camera', null, Array(5).fill('number'), eye);
    const follow = Number(params.get('follow'));
    if (params.get('follow') !== null && Number.isInteger(follow) && follow >= 0)
      Module.ccall('ocean_web_follow', null, ['number'], [follow]);
    const seconds = Number(params.get('report') || 0);
    if (seconds > 0) setTimeout(finishReport, seconds * 1000);
  },
};
