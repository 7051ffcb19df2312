// The page of csgray view: frames rendered by the server, exact, in three
// passes (a quarter of the size, full, antialiased) that restart whenever
// the camera moves; the state of the script by long poll (GET /wait); the
// customizer posting values (POST /define). No framework, nothing loaded
// from elsewhere.
'use strict';

const canvas = document.getElementById('frame');
const context = canvas.getContext('2d');
const $ = (id) => document.getElementById(id);

// ---- Vectors
const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => scale(a, 1 / Math.hypot(a[0], a[1], a[2]));
const degrees = Math.PI / 180;

// ---- The camera: it orbits `target` at `distance`, z up; yaw from +x
// about z, pitch above the xy plane, both in radians.
const view = { target: [0, 0, 0], distance: 10, yaw: -50 * degrees, pitch: 30 * degrees,
  fov: 45, ortho: false, framed: false };

function eye() {
  const c = Math.cos(view.pitch);
  return add(view.target, scale([c * Math.cos(view.yaw), c * Math.sin(view.yaw), Math.sin(view.pitch)],
    view.distance));
}
// Perpendicular to the view at every pitch, the poles included.
function up() {
  const s = Math.sin(view.pitch);
  return [-s * Math.cos(view.yaw), -s * Math.sin(view.yaw), Math.cos(view.pitch)];
}
// The screen's width at the target, in model units: the perspective
// camera's (its angle is horizontal) and the orthographic one's.
function screenWidth() { return 2 * view.distance * Math.tan(view.fov * degrees / 2); }
function worldPerPixel() { return screenWidth() / Math.max(1, canvas.clientWidth); }
function axes() {
  const forward = norm(sub(view.target, eye()));
  const right = norm(cross(forward, up()));
  return { forward, right, up: cross(right, forward) };
}

// An orthographic camera's rays start on a screen through the eye: it
// stands back beyond the part, however far in the view is zoomed.
function cameraEye() {
  if (!view.ortho || !state || !state.bounds) return eye();
  const { lo, hi } = state.bounds;
  const reach = Math.hypot(...sub(hi, lo)) + Math.hypot(...sub(view.target, scale(add(lo, hi), 0.5)));
  return add(view.target, scale(norm(sub(eye(), view.target)), view.distance + reach));
}

function cameraQuery() {
  const e = cameraEye(), u = up(), t = view.target;
  const numbers = [...e, ...t, ...u].map((x) => +x.toPrecision(17));
  return 'camera=' + numbers.join(',') +
    (view.ortho ? '&ortho=' + screenWidth().toPrecision(17) : '&fov=' + view.fov);
}

let state = null;

function fit() {
  if (!state || !state.bounds) return;
  const lo = state.bounds.lo, hi = state.bounds.hi;
  view.target = scale(add(lo, hi), 0.5);
  const radius = Math.max(Math.hypot(...sub(hi, lo)) / 2, 1e-9);
  const aspect = canvas.clientHeight / Math.max(1, canvas.clientWidth);
  // The horizontal angle is fov; the vertical one is narrower.
  const half = Math.atan(Math.tan(view.fov * degrees / 2) * Math.min(1, aspect));
  view.distance = 1.05 * radius / Math.sin(half);
  changed();
}

function look(yawDegrees, pitchDegrees) {
  view.yaw = yawDegrees * degrees;
  view.pitch = pitchDegrees * degrees;
  changed();
}

// The script's own camera, when it has one, else the bounds framed.
function initialView() {
  const c = state.camera;
  if (c) {
    view.target = c.lookAt;
    const d = sub(c.eye, c.lookAt);
    view.distance = Math.hypot(...d);
    view.yaw = Math.atan2(d[1], d[0]);
    view.pitch = Math.asin(Math.max(-1, Math.min(1, d[2] / view.distance)));
    view.fov = c.fov;
    view.ortho = c.ortho;
    if (c.ortho && c.orthoWidth > 0) view.distance = c.orthoWidth / (2 * Math.tan(view.fov * degrees / 2));
    changed();
  } else {
    fit();
  }
  view.framed = true;
}

// ---- The section: a plane that cuts the part at render time (the server
// renders the cut faces in the section colour). Along an axis the kept side
// is below the plane (above it flipped); along the view, the far side of a
// plane facing the camera (the near side flipped). The slider spans the
// part's bounds along the normal.
const sectionControls = ['section-on', 'section-axis', 'section-flip', 'section-offset'];

function sectionPlane() {
  if (!$('section-on').checked || !state || !state.bounds) return null;
  const { lo, hi } = state.bounds;
  const axis = $('section-axis').value;
  let normal, from, to;
  if (axis === 'view') {
    normal = scale(axes().forward, -1);
    const corners = [0, 1, 2, 3, 4, 5, 6, 7].map((i) =>
      dot(normal, [i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]]));
    from = Math.min(...corners);
    to = Math.max(...corners);
  } else {
    const a = 'xyz'.indexOf(axis);
    normal = [0, 0, 0];
    normal[a] = 1;
    from = lo[a];
    to = hi[a];
  }
  let offset = from + (to - from) * $('section-offset').value / 1000;
  $('section-where').textContent = (axis === 'view' ? 'depth' : axis) + ' = ' + shown(offset);
  if ($('section-flip').checked) {
    normal = scale(normal, -1);
    offset = -offset;
  }
  return [...normal, offset].map((x) => +x.toPrecision(17));
}

function sectionQuery() {
  const plane = sectionPlane();
  if (!plane) $('section-where').textContent = '–';
  return plane ? '&section=' + plane.join(',') : '';
}

for (const id of [...sectionControls, 'show-ghosts', 'show-highlights'])
  $(id).addEventListener('input', () => changed());

// ---- Frames: pass 0, 1 and 2, one request at a time; a move during
// pass 0 waits for it (it is quick), a move during a later pass aborts it
// (and the server cancels its render when the new request comes).
let inFlight = null;  // {pass, key, controller}
let dirty = false;
let later = null;  // the timer of a full pass put off during a drag

function frameKey() {
  return cameraQuery() + '&size=' + canvas.width + 'x' + canvas.height + sectionQuery() +
    ($('show-ghosts').checked ? '' : '&ghosts=0') + ($('show-highlights').checked ? '' : '&highlights=0');
}

function changed() {
  if (markers.length) placeMarkers();
  $('projection').textContent = view.ortho ? 'orthographic' : 'perspective';
  delete canvas.dataset.settled;
  clearTimeout(later);
  if (inFlight && inFlight.pass === 0) { dirty = true; return; }
  if (inFlight) inFlight.controller.abort();
  request(0);
}

async function request(pass) {
  if (!state || !state.bounds) return;
  const key = frameKey();
  const controller = new AbortController();
  const mine = { pass, key, controller };
  inFlight = mine;
  dirty = false;
  try {
    const response = await fetch('/frame?' + key + '&pass=' + pass, { signal: controller.signal });
    if (response.ok) {
      const image = await createImageBitmap(await response.blob());
      context.imageSmoothingEnabled = pass === 0;
      context.drawImage(image, 0, 0, canvas.width, canvas.height);
      // What is on the canvas, for the browser test (tests/browser/).
      canvas.dataset.pass = pass;
      canvas.dataset.version = response.headers.get('X-Csgray-Version');
      canvas.dataset.frames = +(canvas.dataset.frames || 0) + 1;
      placeMarkers();
      if (pass === 2 && !dirty && frameKey() === key) {
        canvas.dataset.settled = '1';
        fadeHiddenMarkers(key);
      }
    }
  } catch (e) {
    if (e.name !== 'AbortError') console.warn(e);
  }
  if (inFlight !== mine) return;  // superseded
  inFlight = null;
  if (dirty || frameKey() !== key) request(0);
  // While a drag goes on the next move is due within milliseconds: the
  // full size waits for a pause rather than start and be cancelled.
  else if (pass === 0 && drag && drag.moved) later = setTimeout(() => request(1), 60);
  else if (pass < 2) request(pass + 1);
}

function resize() {
  const w = Math.max(1, Math.round(canvas.clientWidth)), h = Math.max(1, Math.round(canvas.clientHeight));
  if (canvas.width !== w || canvas.height !== h) {
    canvas.width = w;
    canvas.height = h;
    changed();
  }
}
new ResizeObserver(resize).observe(canvas);

// ---- Mouse and keys
let drag = null;
canvas.addEventListener('contextmenu', (e) => e.preventDefault());
canvas.addEventListener('pointerdown', (e) => {
  canvas.setPointerCapture(e.pointerId);
  drag = { x: e.clientX, y: e.clientY, pan: e.button === 2 || e.button === 1 || e.shiftKey, moved: false };
  canvas.classList.add('dragging');
});
canvas.addEventListener('pointermove', (e) => {
  if (!drag) return;
  const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
  if (Math.abs(dx) + Math.abs(dy) > 2) drag.moved = true;
  if (!drag.moved) return;
  drag.x = e.clientX;
  drag.y = e.clientY;
  if (drag.pan) {
    const a = axes(), w = worldPerPixel();
    view.target = add(view.target, add(scale(a.right, -dx * w), scale(a.up, dy * w)));
  } else {
    view.yaw -= dx * 0.01;
    view.pitch = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, view.pitch + dy * 0.01));
  }
  changed();
});
canvas.addEventListener('pointerup', (e) => {
  canvas.classList.remove('dragging');
  if (drag && !drag.moved) pick(e, false);
  drag = null;
});
canvas.addEventListener('dblclick', (e) => pick(e, true));
canvas.addEventListener('wheel', (e) => {
  e.preventDefault();
  const factor = Math.exp(Math.max(-200, Math.min(200, e.deltaY)) * 0.002);
  // The point under the cursor, in the plane of the target, stays put.
  const r = canvas.getBoundingClientRect(), a = axes(), w = worldPerPixel();
  const cx = e.clientX - r.left - r.width / 2, cy = e.clientY - r.top - r.height / 2;
  const under = add(view.target, add(scale(a.right, cx * w), scale(a.up, -cy * w)));
  view.target = add(under, scale(sub(view.target, under), factor));
  view.distance *= factor;
  changed();
}, { passive: false });
// Keys anywhere on the page, but not those typed into the customizer's
// boxes, nor the browser's own shortcuts.
document.addEventListener('keydown', (e) => {
  if (e.ctrlKey || e.altKey || e.metaKey || e.target.closest('input, select, textarea')) return;
  const views = { 1: [-90, 0], 2: [90, 0], 3: [180, 0], 4: [0, 0], 5: [-90, 90], 6: [-90, -90], 0: [-50, 30] };
  if (e.key in views) look(...views[e.key]);
  else if (e.key === 'o') { view.ortho = !view.ortho; changed(); }
  else if (e.key === 'f') fit();
  else return;
  e.preventDefault();
});
canvas.focus();

const shown = (x) => (Math.abs(x) < 1e-12 ? 0 : x).toPrecision(10).replace(/\.?0+(e|$)/, '$1');
const point = (p) => '(' + p.map(shown).join(', ') + ')';

async function pick(e, centre) {
  const r = canvas.getBoundingClientRect();
  const x = (e.clientX - r.left) * canvas.width / r.width, y = (e.clientY - r.top) * canvas.height / r.height;
  const response = await fetch('/pick?' + frameKey() + '&x=' + x + '&y=' + y);
  if (!response.ok) return;
  const hit = await response.json();
  $('pick-point').textContent = hit.hit ? point(hit.point) : 'nothing there';
  $('pick-normal').textContent = hit.hit ? point(hit.normal) : '–';
  $('pick-kind').textContent = hit.hit ? hit.kind : '–';
  $('pick-source').textContent = hit.hit ? hit.source || 'unknown' : '–';
  if (centre && hit.hit) {
    // Keep the eye where it is: the new target is on its line of sight.
    const from = eye();
    view.target = hit.point;
    const d = sub(from, hit.point);
    view.distance = Math.hypot(...d);
    view.yaw = Math.atan2(d[1], d[0]);
    view.pitch = Math.asin(Math.max(-1, Math.min(1, d[2] / view.distance)));
    changed();
  }
}

// ---- The customizer
let parameterShape = '', parameterValues = '';

async function define(name, value) {
  const query = '/define?name=' + encodeURIComponent(name) +
    (value === undefined ? '' : '&value=' + encodeURIComponent(value));
  const response = await fetch(query, { method: 'POST' });
  // Taken: the long poll brings the new state (a rebuild now would end the
  // drag of a slider still under the hand).
  if (response.ok) return;
  // Refused: the controls show the value in force again, and why not.
  const reason = await response.text();
  if (state) showParameters(state.parameters, true);
  const row = document.querySelector(`.parameter[data-name="${CSS.escape(name)}"] .refused`);
  if (row) row.textContent = reason;
}

function defineText(p, value) {
  if (p.kind === 'vector') return '{' + value.join(',') + '}';
  return String(value);
}

function debounced(f, ms) {
  let timer;
  return (...args) => { clearTimeout(timer); timer = setTimeout(() => f(...args), ms); };
}

function numberInputs(p, value, onChange) {
  const row = document.createElement('div');
  row.className = 'row';
  const number = document.createElement('input');
  number.type = 'number';
  number.step = p.step > 0 ? p.step : 'any';
  number.value = value;
  let range = null;
  if (p.min !== undefined) {
    range = document.createElement('input');
    range.type = 'range';
    range.min = p.min;
    range.max = p.max;
    // Without a step the slider is continuous: a grid of its own would
    // move the value off the script's (40 on [10:100] to 39.97).
    range.step = p.step > 0 ? p.step : 'any';
    range.value = value;
    range.addEventListener('input', () => { number.value = range.value; onChange(+range.value); });
    row.append(range);
  }
  number.addEventListener('change', () => { if (range) range.value = number.value; onChange(+number.value); });
  row.append(number);
  return row;
}

function parameterRow(p) {
  const div = document.createElement('div');
  div.className = 'parameter';
  div.dataset.name = p.name;
  const label = document.createElement('label');
  label.textContent = p.name;
  div.append(label);
  const send = debounced((value) => define(p.name, defineText(p, value)), 120);
  if (p.choices) {
    const select = document.createElement('select');
    p.choices.forEach((c, i) => {
      const option = document.createElement('option');
      option.value = i;
      option.textContent = c;
      if (c === p.value) option.selected = true;
      select.append(option);
    });
    select.addEventListener('change', () => send(p.choices[+select.value]));
    div.append(select);
  } else if (p.kind === 'boolean') {
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.checked = p.value;
    box.addEventListener('change', () => send(box.checked));
    label.prepend(box);
  } else if (p.kind === 'string') {
    const text = document.createElement('input');
    text.value = p.value;
    text.addEventListener('change', () => send(text.value));
    div.append(text);
  } else if (p.kind === 'vector') {
    const value = p.value.slice();
    value.forEach((v, i) => div.append(numberInputs(p, v, (x) => { value[i] = x; send(value); })));
  } else {
    div.append(numberInputs(p, p.value, send));
  }
  if (p.description) {
    const d = document.createElement('div');
    d.className = 'description';
    d.textContent = p.description + ' (line ' + p.line + ')';
    div.append(d);
  }
  const reset = document.createElement('button');
  reset.type = 'button';
  reset.textContent = 'default';
  reset.addEventListener('click', () => define(p.name));
  const refused = document.createElement('div');
  refused.className = 'refused';
  div.append(reset, refused);
  return div;
}

function showParameters(parameters, force = false) {
  // Rebuilt when the annotations change, or a value changed elsewhere; not
  // under the user's hand (a slider being dragged, a box being typed in)
  // unless forced, when the server has answered that control's change.
  const shape = JSON.stringify(parameters.map((p) => ({ ...p, value: null })));
  const values = JSON.stringify(parameters.map((p) => p.value));
  const editing = document.activeElement &&
    document.activeElement.matches('#customizer input, #customizer select');
  if (!force && shape === parameterShape && (values === parameterValues || editing)) return;
  parameterShape = shape;
  parameterValues = values;
  $('parameters').replaceChildren(...parameters.map(parameterRow));
  $('customizer').hidden = parameters.length === 0;
}

// Values that came while a control had the focus show when it leaves.
$('parameters').addEventListener('focusout', () => setTimeout(() => state && showParameters(state.parameters)));

// ---- The script's state, by long poll
function showState(next) {
  const reloaded = !state || state.version !== next.version;
  state = next;
  $('title').textContent = state.script;
  document.title = state.script + ' – csgray view';
  $('error').hidden = !state.error;
  $('error').textContent = state.error;
  if (state.bounds) {
    const { lo, hi } = state.bounds;
    $('bounds').textContent = point(lo) + ' … ' + point(hi);
    $('size').textContent = point(sub(hi, lo));
  }
  $('volume').textContent = state.volume == null ? '–' : shown(state.volume);
  // The switches of the script's ghosts and highlights, when it has any.
  $('show-ghosts-label').hidden = !state.ghosts;
  $('show-highlights-label').hidden = !state.highlights;
  $('modifiers').hidden = !state.ghosts && !state.highlights;
  $('files').replaceChildren(...state.files.map((f) => {
    const li = document.createElement('li');
    li.textContent = f;
    return li;
  }));
  showParameters(state.parameters);
  if (!view.framed && state.bounds) initialView();
  else if (reloaded) changed();
  // A new run makes the last job's result stale.
  if (reloaded && $('job-line').dataset.stage) pollJob();
}

async function poll() {
  let version = -1;
  for (;;) {
    try {
      const response = await fetch(version < 0 ? '/scene' : '/wait?version=' + version);
      if (!response.ok) throw new Error(await response.text());
      const next = await response.json();
      version = next.version;
      showState(next);
    } catch (e) {
      $('error').hidden = false;
      $('error').textContent = 'the server does not answer: ' + e.message;
      await new Promise((r) => setTimeout(r, 2000));
    }
  }
}

// ---- Export and check: jobs on the server, one at a time; the page polls
// the stage, then takes the file as a download or shows the check's
// warnings as markers at their points (the title gives the text on hover).
let markers = [];  // [{at, text}]
let jobTimer = null;
let downloaded = 0;  // the last export's id already offered

// A model point's pixel on the canvas, as the server's camera maps it
// (scene/camera.cpp), or null behind the eye.
function project(p) {
  const a = axes(), e = cameraEye(), d = sub(p, e);
  const depth = view.ortho ? 1 : dot(d, a.forward);
  if (depth <= 0) return null;
  const pixel = (view.ortho ? screenWidth() : 2 * Math.tan(view.fov * degrees / 2)) / canvas.width;
  return [canvas.width / 2 + dot(d, a.right) / depth / pixel, canvas.height / 2 - dot(d, a.up) / depth / pixel];
}

function placeMarkers() {
  const r = canvas.getBoundingClientRect(), k = r.width / Math.max(1, canvas.width);
  $('markers').replaceChildren(...markers.flatMap((m, i) => {
    const at = project(m.at);
    if (!at || at[0] < 0 || at[1] < 0 || at[0] > canvas.width || at[1] > canvas.height) return [];
    const div = document.createElement('div');
    div.className = 'marker';
    div.style.left = at[0] * k + 'px';
    div.style.top = at[1] * k + 'px';
    div.textContent = i + 1;
    div.title = m.text;
    return [div];
  }));
}

// Once a view is settled, markers whose point lies behind the part (a
// pick at their pixel meets the part nearer the eye) are faded.
async function fadeHiddenMarkers(key) {
  if (!markers.length || !state || !state.bounds) return;
  const slack = 1e-4 * Math.hypot(...sub(state.bounds.hi, state.bounds.lo));
  const e = cameraEye();
  const divs = Array.from($('markers').children);
  for (const div of divs) {
    const m = markers[+div.textContent - 1], at = project(m.at);
    const response = await fetch('/pick?' + key + '&x=' + at[0] + '&y=' + at[1]);
    if (!response.ok || frameKey() !== key) return;
    const hit = await response.json();
    const far = (p) => (view.ortho ? dot(sub(p, e), axes().forward) : Math.hypot(...sub(p, e)));
    const hidden = hit.hit && far(hit.point) < far(m.at) - slack;
    div.classList.toggle('hidden', hidden);
    div.title = m.text + (hidden ? ' (behind the part)' : '');
  }
}

function jobLine(text, failed) {
  $('job-line').textContent = text;
  $('job-line').classList.toggle('failed', !!failed);
}

function showJob(job) {
  $('job-line').dataset.stage = job.stage || '';
  markers = [];
  $('job-warnings').replaceChildren();
  $('job-report').hidden = true;
  if (!job.id) jobLine('–');
  else if (job.running) jobLine(job.kind + ': ' + job.stage + ' …');
  else if (job.error) jobLine(job.kind + ' failed: ' + job.error, true);
  else if (job.stale) jobLine('the part changed since the ' + job.kind + '; run it again');
  else if (job.kind === 'export') {
    jobLine(job.name + ': ' + job.bytes + ' bytes');
    if (downloaded !== job.id) {
      downloaded = job.id;
      const a = document.createElement('a');
      a.href = job.file;
      a.download = job.name;
      a.click();
    }
  } else if (job.report) {
    const r = job.report;
    const warnings = r.warnings || [];
    jobLine(r.failure ? 'check failed: ' + r.failure
      : 'check: ' + (r.ok ? 'ok' : 'FAILED') + ', ' + warnings.length + ' warning' + (warnings.length === 1 ? '' : 's'),
    !r.ok);
    markers = warnings.map((w) => ({ at: w.at, text: w.kind + ': ' + w.message }));
    $('job-warnings').replaceChildren(...markers.map((m, i) => {
      const li = document.createElement('li');
      li.textContent = (i + 1) + '. ' + m.text;
      return li;
    }));
    $('job-text').textContent = job.text;
    $('job-report').hidden = false;
  }
  placeMarkers();
  if (canvas.dataset.settled) fadeHiddenMarkers(frameKey());
}

async function pollJob() {
  clearTimeout(jobTimer);
  try {
    const response = await fetch('/job');
    if (!response.ok) throw new Error(await response.text());
    const job = await response.json();
    showJob(job);
    if (job.running) jobTimer = setTimeout(pollJob, 250);
  } catch (e) {
    jobLine(e.message.trim(), true);
  }
}

async function startJob(path) {
  const response = await fetch(path, { method: 'POST' });
  if (!response.ok) {
    jobLine((await response.text()).trim(), true);
    return;
  }
  pollJob();
}

$('export-stl').addEventListener('click', () => startJob('/export?format=stl'));
$('export-3mf').addEventListener('click', () => startJob('/export?format=3mf'));
$('check').addEventListener('click', () => startJob('/check'));

resize();
poll();
