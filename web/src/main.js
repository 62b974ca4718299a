// Klueng's page (issue 41): the editor, the check while typing, the explain line, the run
// drawn on a canvas. Every answer about a program comes from the core in the worker
// (worker.js -> klueng.wasm); this file only shows them.
import { EditorView, basicSetup } from 'codemirror';
import { EditorState, StateEffect, StateField } from '@codemirror/state';
import { Decoration } from '@codemirror/view';
import { setDiagnostics, lintGutter } from '@codemirror/lint';
import { texts } from './i18n.js';
import { handle, makeApi } from './api.js';

const $ = (id) => document.getElementById(id);
const ui = { lang: localStorage.getItem('klueng.lang') === 'th' ? 'th' : 'en', machine: '', units: 0 };
const T = () => texts[ui.lang];
const langCode = () => (ui.lang === 'th' ? 1 : 0);

// ---------------------------------------------------------------- the worker

let worker = null;
let nextId = 1;
const waiting = new Map();
function call(type, args = {}) {
  if (local) return local.then((k) => handle(k, { type, ...args }));
  return new Promise((resolve, reject) => {
    const id = nextId++;
    waiting.set(id, { resolve, reject });
    worker.postMessage({ id, type, ...args });
  });
}
let local = null;  // the module on this thread (a page opened from a file)
function startWorker() {
  if (location.protocol === 'file:') {
    // Browsers start no worker and fetch no file for a page opened from a file: the module
    // with its code inside (klueng-single.js) runs here instead, and a check holds the page
    // while it runs (docs/web.md).
    local = new Promise((resolve, reject) => {
      const s = document.createElement('script');
      s.src = 'klueng-single.js';
      s.onload = () => createKlueng().then((M) => resolve(makeApi(M)), reject);  // eslint-disable-line no-undef
      s.onerror = () => reject(new Error('klueng-single.js could not be loaded'));
      document.head.append(s);
    });
    return;
  }
  worker = new Worker('worker.js');
  worker.onmessage = (e) => {
    const w = waiting.get(e.data.id);
    if (!w) return;
    waiting.delete(e.data.id);
    if (e.data.error) w.reject(new Error(e.data.error));
    else w.resolve(e.data.result);
  };
  worker.onerror = (e) => showMessage(`${e.message || e}`);
}

// ---------------------------------------------------------------- the editor

const setExecuting = StateEffect.define();
const executingLine = StateField.define({
  create: () => Decoration.none,
  update(deco, tr) {
    deco = deco.map(tr.changes);
    for (const e of tr.effects) {
      if (!e.is(setExecuting)) continue;
      const line = e.value;
      if (line < 1 || line > tr.state.doc.lines) return Decoration.none;
      const from = tr.state.doc.line(line).from;
      return Decoration.set([Decoration.line({ class: 'cm-executing' }).range(from)]);
    }
    return deco;
  },
  provide: (f) => EditorView.decorations.from(f),
});

let fileName = 'program.nc';
const view = new EditorView({
  parent: $('editor'),
  state: EditorState.create({
    doc: '',
    extensions: [
      basicSetup,
      EditorView.lineWrapping,
      lintGutter(),
      executingLine,
      EditorView.updateListener.of((u) => {
        if (u.docChanged) textChanged();
        if (u.docChanged || u.selectionSet) scheduleExplain();
      }),
    ],
  }),
});
const text = () => view.state.doc.toString();
function setText(t) {
  view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: t }, selection: { anchor: 0 } });
  view.scrollDOM.scrollTop = 0;
}

// A diagnostic's column counts UTF-8 bytes (the core's); the editor counts UTF-16 units.
const encoder = new TextEncoder();
function charsOfBytes(lineText, bytes) {
  let b = 0;
  let i = 0;
  while (i < lineText.length && b < bytes) {
    const cp = lineText.codePointAt(i);
    b += encoder.encode(String.fromCodePoint(cp)).length;
    i += cp > 0xffff ? 2 : 1;
  }
  return i;
}

// ---------------------------------------------------------------- the check

let checkTimer = 0;
let checkInFlight = false;
let checkPending = false;
let diagnostics = [];

function textChanged() {
  forgetRun();
  clearTimeout(checkTimer);
  checkTimer = setTimeout(checkNow, 300);  // as the desktop: once typing pauses
}

async function checkNow() {
  clearTimeout(checkTimer);
  if (checkInFlight) {
    checkPending = true;  // one check at a time; the newest text goes next
    return;
  }
  checkInFlight = true;
  const program = text();
  document.body.dataset.checked = '';
  try {
    const result = await call('check', { text: program, machine: ui.machine, units: ui.units, lang: langCode() });
    checkInFlight = false;
    if (checkPending || program !== text()) {
      checkPending = false;
      checkNow();
      return;
    }
    $('check-time').textContent = T().checkedIn(Math.round(result.ms));
    showDiagnostics(result.diagnostics || []);
    document.body.dataset.checked = 'yes';
  } catch (e) {
    checkInFlight = false;
    showMessage(String(e));
  }
}

function showDiagnostics(list) {
  diagnostics = list;
  const doc = view.state.doc;
  const marks = [];
  const ul = $('diagnostics');
  ul.textContent = '';
  for (const d of list) {
    const li = document.createElement('li');
    li.className = `sev-${d.severity}`;
    li.dataset.line = d.line;
    li.dataset.code = d.code;
    li.dataset.severity = d.severity;
    const place = document.createElement('span');
    place.className = 'place';
    place.textContent = d.line > 0 ? `${d.line}:${d.column} ` : '';
    li.append(place, `${d.code}: ${d.message}`);
    ul.append(li);
    if (d.file !== 'program.nc' || d.line < 1 || d.line > doc.lines) continue;
    const line = doc.line(d.line);
    const from = line.from + Math.min(line.length, charsOfBytes(line.text, Math.max(0, d.column - 1)));
    let to = line.from + Math.min(line.length, charsOfBytes(line.text, Math.max(0, d.column - 1 + d.length)));
    if (to <= from) to = Math.min(line.to, from + 1);
    const severity = d.severity === 'warning' ? 'warning' : d.severity === 'note' ? 'info' : 'error';
    marks.push({ from, to: Math.max(from, to), severity, message: `${d.code}: ${d.message}` });
    li.addEventListener('click', () => {
      view.dispatch({ selection: { anchor: from }, scrollIntoView: true });
      view.focus();
    });
  }
  if (!list.length) {
    const li = document.createElement('li');
    li.className = 'none';
    li.textContent = T().noDiagnostics;
    ul.append(li);
  }
  view.dispatch(setDiagnostics(view.state, marks));
}

// ---------------------------------------------------------------- the explain line

let explainTimer = 0;
function scheduleExplain() {
  clearTimeout(explainTimer);
  explainTimer = setTimeout(explainNow, 120);
}
async function explainNow() {
  const line = view.state.doc.lineAt(view.state.selection.main.head).number;
  const program = text();
  const r = await call('explain', { text: program, line, machine: ui.machine, units: ui.units, lang: langCode() });
  if (program === text()) $('explain').textContent = r.text || '';
}

// ---------------------------------------------------------------- the run

let run = null;     // klueng_run's answer for the text, machine, units and language below
let runKey = '';
let t = 0;          // the time shown, seconds
let playing = false;
let advancing = false;
let state = null;   // klueng_advance's last answer
let toolKey = '';
let toolPicture = null;  // { canvas, info }
let pathCache = null;

const runKeyNow = () => `${ui.machine}\u001f${ui.units}\u001f${ui.lang}\u001f${text()}`;

function forgetRun() {
  playing = false;
  run = null;
  runKey = '';
  state = null;
  t = 0;
  showExecuting(0);
  showFeatures();
  setRunState('ready');
  $('message').textContent = '';
  draw();
}

async function ensureRun() {
  const key = runKeyNow();
  if (run && runKey === key) return run;
  setRunState('preparing');
  const keepTime = run ? t : 0;
  const r = await call('run', { text: text(), machine: ui.machine, units: ui.units, lang: langCode() });
  if (key !== runKeyNow()) return null;  // the text changed meanwhile
  if (!r.ok) {
    showDiagnostics(r.diagnostics || []);
    showMessage(T().errorsFirst);
    setRunState('ready');
    return null;
  }
  run = r;
  runKey = key;
  pathCache = null;
  toolKey = '';
  $('message').textContent = '';
  $('st-cycle').textContent = seconds(run.cycleTime);
  $('st-cycle').dataset.seconds = run.cycleTime;
  t = Math.min(keepTime, run.endTime);
  await advanceTo(t);
  return run;
}

async function advanceTo(time) {
  advancing = true;
  try {
    state = await call('advance', { t: time, lang: langCode() });
  } finally {
    advancing = false;
  }
  if (!state.ok) return;
  if (state.toolKey !== toolKey) {
    toolKey = state.toolKey;
    toolPicture = toolKey ? makeToolPicture(await call('toolImage')) : null;
  }
  showExecuting(state.line || 0);
  showStatus();
  draw();
  if (state.finished && time >= run.endTime - 1e-9) finish();
}

// The executing block is marked and kept in sight, as the desktop's editor follows the run.
let executing = 0;
function showExecuting(line) {
  const effects = [setExecuting.of(line)];
  if (line !== executing && line >= 1 && line <= view.state.doc.lines)
    effects.push(EditorView.scrollIntoView(view.state.doc.line(line).from, { y: 'nearest' }));
  executing = line;
  view.dispatch({ effects });
}

function finish() {
  playing = false;
  t = run.endTime;
  setRunState(state.alarm ? 'alarm' : 'finished');
  if (state.alarm) showMessage(`${state.alarm.line}:${state.alarm.column} ${state.alarm.code}: ${state.alarm.message}`);
  showFeatures(run.features);
}

const speeds = [1, 2, 5, 10, 50, 0];
let speed = 5;
function tick(now, last) {
  if (!playing || !run) return;
  const dt = Math.min(0.1, (now - last) / 1000);
  if (!advancing) {
    t = speed === 0 ? run.endTime : Math.min(run.endTime, t + dt * speed);
    advanceTo(t).catch((e) => showMessage(String(e)));
  }
  requestAnimationFrame((n) => tick(n, now));
}

async function go() {
  const r = await ensureRun();
  if (!r) return;
  if (t >= r.endTime - 1e-9) {
    t = 0;
    await advanceTo(0);
    showFeatures();
  }
  playing = true;
  setRunState('running');
  requestAnimationFrame((n) => tick(n, n));
}

async function step() {
  playing = false;
  const r = await ensureRun();
  if (!r) return;
  if (t >= r.endTime - 1e-9) {
    t = 0;
    showFeatures();
  }
  // The end of the next block that takes time (or the next stop).
  const next = r.blocks.find((b) => b[1] > t + 1e-9);
  t = next ? Math.min(next[1], r.endTime) : r.endTime;
  setRunState('paused');
  await advanceTo(t);
}

function pause() {
  if (!run || !playing) return;
  playing = false;
  setRunState('paused');
}

async function stop() {
  playing = false;
  if (!run) return;
  t = 0;
  await advanceTo(0);
  showFeatures();
  $('message').textContent = '';
  setRunState('stopped');
}

// ---------------------------------------------------------------- status

function setRunState(s) {
  document.body.dataset.run = s;
  $('st-state').textContent = T()[s];
  $('go').disabled = s === 'running' || s === 'preparing';
  $('pause').disabled = s !== 'running';
}

function seconds(s) {
  return `${(Math.round(s * 10) / 10).toFixed(1)} ${T().seconds}`;
}

function length(mm) {
  const inch = run && run.units === 'inch';
  const v = inch ? mm / 25.4 : mm;
  const text = v.toFixed(inch ? 4 : 3);
  return /^-0\.0+$/.test(text) ? text.slice(1) : text;
}

function showStatus() {
  $('st-time').textContent = seconds(state.time);
  $('st-line').textContent = state.line || '';
  $('st-tool').textContent = state.tool
    ? `T${String(state.tool).padStart(2, '0')}${String(state.offset).padStart(2, '0')}`
    : '';
  $('st-x').textContent = length(2 * state.x);
  $('st-z').textContent = length(state.z);
  const inch = run && run.units === 'inch';
  $('st-feed').textContent = state.kind && state.kind !== 'dwell'
    ? `${(inch ? state.feed / 25.4 : state.feed).toFixed(state.feed >= 1000 ? 0 : inch ? 2 : 1)} ${inch ? T().inMin : T().mmMin}`
    : '';
  $('st-rpm').textContent = state.rpm ? `${Math.round(state.rpm)} ${T().rpm}` : '';
}

function showFeatures(features) {
  const ul = $('features');
  ul.textContent = '';
  if (!features) {
    const li = document.createElement('li');
    li.className = 'hint';
    li.textContent = T().notYet;
    ul.append(li);
    document.body.dataset.part = '';
    return;
  }
  for (const f of features) {
    const li = document.createElement('li');
    li.textContent = f.text;
    li.dataset.kind = f.kind;
    li.dataset.diameter = f.diameter;
    ul.append(li);
  }
  document.body.dataset.part = 'yes';
}

function showMessage(m) {
  $('message').textContent = m;
}

// ---------------------------------------------------------------- drawing

const canvas = $('view');
const ctx = canvas.getContext('2d');

function makeToolPicture(info) {
  if (!info.ok) return null;
  const c = document.createElement('canvas');
  c.width = info.width;
  c.height = info.height;
  const g = c.getContext('2d');
  const img = g.createImageData(info.width, info.height);
  const rgb = Uint8Array.from(atob(info.rgb), (ch) => ch.charCodeAt(0));
  for (let i = 0, j = 0; i < info.width * info.height; ++i, j += 3) {
    const r = rgb[j], gr = rgb[j + 1], b = rgb[j + 2];
    const white = r === 255 && gr === 255 && b === 255;
    const black = r === 0 && gr === 0 && b === 0;
    img.data[4 * i] = black ? 70 : r;
    img.data[4 * i + 1] = black ? 78 : gr;
    img.data[4 * i + 2] = black ? 88 : b;
    img.data[4 * i + 3] = white ? 0 : 235;
  }
  g.putImageData(img, 0, 0);
  return { canvas: c, info };
}

function viewBounds() {
  const R = run.stock.diameter / 2;
  const L = run.stock.length;
  // The part fills the view: the path around it is shown as far as it stays near (a tool
  // far away at its reference point is left out of the picture rather than shrink the part).
  const reachZ = Math.max(20, 0.35 * L);
  const reachX = Math.max(15, 0.6 * R);
  let zMin = -L - run.chuck.bodyWidth * 0.6;
  let zMax = 5;
  let xMax = R + run.chuck.jawHeight + 4;
  for (const m of run.moves) {
    for (const [z, x] of [[m[4], m[5]], [m[6], m[7]]]) {
      if (z > reachZ || x > R + reachX) continue;
      zMin = Math.min(zMin, z);
      zMax = Math.max(zMax, z);
      xMax = Math.max(xMax, x);
    }
  }
  zMax += 12;
  xMax += 6;
  return { zMin, zMax, xMin: -(R + run.chuck.jawHeight + 6), xMax };
}

function arcPoints(m, into) {
  const [cz, cx, ccw] = [m[10], m[11], m[12]];
  let a0 = Math.atan2(m[5] - cx, m[4] - cz);
  let a1 = Math.atan2(m[7] - cx, m[6] - cz);
  if (ccw && a1 <= a0) a1 += 2 * Math.PI;
  if (!ccw && a1 >= a0) a1 -= 2 * Math.PI;
  const r = Math.hypot(m[4] - cz, m[5] - cx);
  const n = Math.max(4, Math.ceil(Math.abs(a1 - a0) * 12));
  for (let k = 1; k <= n; ++k) {
    const a = a0 + ((a1 - a0) * k) / n;
    into.lineTo(cz + r * Math.cos(a), cx + r * Math.sin(a));
  }
}

function paths() {
  if (pathCache) return pathCache;
  const feed = new Path2D();
  const rapid = new Path2D();
  for (const m of run.moves) {
    if (m[0] === 'dwell') continue;
    const p = m[0] === 'rapid' ? rapid : feed;
    p.moveTo(m[4], m[5]);
    if (m.length > 10) arcPoints(m, p);
    else p.lineTo(m[6], m[7]);
  }
  pathCache = { feed, rapid };
  return pathCache;
}

function draw() {
  const dpr = window.devicePixelRatio || 1;
  const w = canvas.clientWidth;
  const h = canvas.clientHeight;
  if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
    canvas.width = Math.round(w * dpr);
    canvas.height = Math.round(h * dpr);
  }
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, w, h);
  if (!run || !state || !state.profile) return;
  const b = viewBounds();
  const scale = Math.min(w / (b.zMax - b.zMin), h / (b.xMax - b.xMin));
  const ox = (w - (b.zMax - b.zMin) * scale) / 2 - b.zMin * scale;
  const oy = (h - (b.xMax - b.xMin) * scale) / 2 + b.xMax * scale;
  const world = (sx = 1) => ctx.setTransform(dpr * scale, 0, 0, -dpr * scale * sx, dpr * ox, dpr * oy);
  const px = 1 / scale;  // one screen pixel in mm

  const R = run.stock.diameter / 2;
  const L = run.stock.length;
  const ch = run.chuck;
  // The chuck: jaws on the bar, the body behind it, both halves.
  for (const side of [1, -1]) {
    world(side);
    ctx.fillStyle = '#9aa5b1';
    ctx.fillRect(-L, R, ch.grip, ch.jawHeight);
    ctx.fillStyle = '#c3cbd3';
    ctx.fillRect(-L - ch.bodyWidth, ch.spindleBoreRadius, ch.bodyWidth, R + ch.jawHeight + 10 - ch.spindleBoreRadius);
  }
  // The stock: the upper half as cut, the lower half its mirror (the bar is round).
  const prof = state.profile;
  const n = prof.length / 2;
  const dz = run.stock.resolution;
  const stock = new Path2D();
  stock.moveTo(-L, prof[1]);
  for (let i = 0; i < n; ++i) {
    const z0 = -L + i * dz;
    const z1 = i + 1 === n ? 0 : z0 + dz;
    stock.lineTo(z0, prof[2 * i]);
    stock.lineTo(z1, prof[2 * i]);
  }
  for (let i = n - 1; i >= 0; --i) {
    const z0 = -L + i * dz;
    const z1 = i + 1 === n ? 0 : z0 + dz;
    stock.lineTo(z1, prof[2 * i + 1]);
    stock.lineTo(z0, prof[2 * i + 1]);
  }
  stock.closePath();
  world(1);
  ctx.fillStyle = '#c9a56a';
  ctx.fill(stock);
  ctx.strokeStyle = '#7a5c2e';
  ctx.lineWidth = px;
  ctx.stroke(stock);
  world(-1);
  ctx.fillStyle = '#dcc49a';
  ctx.fill(stock);
  // The centre line.
  world(1);
  ctx.strokeStyle = '#5d6b79';
  ctx.setLineDash([12 * px, 3 * px, 2 * px, 3 * px]);
  ctx.beginPath();
  ctx.moveTo(b.zMin, 0);
  ctx.lineTo(b.zMax, 0);
  ctx.stroke();
  // The programmed path: feeds solid, rapids dashed.
  const p = paths();
  ctx.lineWidth = px;
  ctx.setLineDash([]);
  ctx.strokeStyle = 'rgba(30, 90, 170, 0.55)';
  ctx.stroke(p.feed);
  ctx.setLineDash([4 * px, 3 * px]);
  ctx.strokeStyle = 'rgba(190, 40, 40, 0.45)';
  ctx.stroke(p.rapid);
  ctx.setLineDash([]);
  // The tool: its bitmap placed by the controlled point, and the exact nose.
  if (toolPicture) {
    const i = toolPicture.info;
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    const sx = ox + (state.z - i.controlX / i.pixelsPerMm) * scale;
    const sy = oy - (state.x + i.controlY / i.pixelsPerMm) * scale;
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(toolPicture.canvas, sx, sy, (i.width / i.pixelsPerMm) * scale, (i.height / i.pixelsPerMm) * scale);
    if (i.noseRadius > 0) {
      world(1);
      ctx.strokeStyle = '#d0021b';
      ctx.lineWidth = 1.5 * px;
      ctx.beginPath();
      ctx.arc(state.z + i.noseZ, state.x + i.noseX, i.noseRadius, 0, 2 * Math.PI);
      ctx.stroke();
    }
  }
  // The controlled point.
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  const cx = ox + state.z * scale;
  const cy = oy - state.x * scale;
  ctx.strokeStyle = '#111';
  ctx.lineWidth = 1;
  ctx.beginPath();
  ctx.moveTo(cx - 5, cy);
  ctx.lineTo(cx + 5, cy);
  ctx.moveTo(cx, cy - 5);
  ctx.lineTo(cx, cy + 5);
  ctx.stroke();
}

new ResizeObserver(() => draw()).observe($('view-box'));

// ---------------------------------------------------------------- files, samples, language

async function loadSample(name) {
  const r = await call('sample', { name });
  fileName = name;
  setText(r.text);
  checkNow();
}

function decode(bytes) {
  try {
    return new TextDecoder('utf-8', { fatal: true }).decode(bytes);
  } catch {
    return new TextDecoder('windows-874').decode(bytes);  // TIS-620, as the desktop reads it
  }
}

$('open').addEventListener('click', () => $('file').click());
$('file').addEventListener('change', async () => {
  const f = $('file').files[0];
  if (!f) return;
  fileName = f.name;
  setText(decode(new Uint8Array(await f.arrayBuffer())).replace(/\r\n?/g, '\n'));
  $('file').value = '';
  checkNow();
});
$('save').addEventListener('click', () => {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([text()], { type: 'text/plain;charset=utf-8' }));
  a.download = fileName;
  document.body.append(a);
  a.click();
  setTimeout(() => {
    URL.revokeObjectURL(a.href);
    a.remove();
  }, 1000);
});
$('samples').addEventListener('change', () => {
  const name = $('samples').value;
  $('samples').value = '';
  if (name) loadSample(name);
});
$('machine').addEventListener('change', () => {
  ui.machine = $('machine').value;
  forgetRun();
  checkNow();
});
$('units').addEventListener('change', () => {
  ui.units = Number($('units').value);
  forgetRun();
  checkNow();
});
$('speed').addEventListener('change', () => {
  speed = Number($('speed').value);
});
$('lang').addEventListener('click', async () => {
  ui.lang = ui.lang === 'en' ? 'th' : 'en';
  localStorage.setItem('klueng.lang', ui.lang);
  await applyLanguage();
  checkNow();
  scheduleExplain();
  if (run) {
    const wasDone = document.body.dataset.part === 'yes';
    const s = document.body.dataset.run;
    await ensureRun();  // the run's texts in the new language, at the same time
    if (wasDone && run) showFeatures(run.features);
    setRunState(s);
  }
});
$('go').addEventListener('click', () => go().catch((e) => showMessage(String(e))));
$('step').addEventListener('click', () => step().catch((e) => showMessage(String(e))));
$('pause').addEventListener('click', pause);
$('stop').addEventListener('click', () => stop().catch((e) => showMessage(String(e))));

function option(select, value, label) {
  const o = document.createElement('option');
  o.value = value;
  o.textContent = label;
  select.append(o);
}

async function applyLanguage() {
  document.documentElement.lang = ui.lang;
  document.title = T().title;
  for (const e of document.querySelectorAll('[data-t]')) e.textContent = T()[e.dataset.t];
  const info = await call('info', { lang: langCode() });
  const samples = $('samples');
  samples.textContent = '';
  option(samples, '', T().chooseSample);
  for (const s of info.samples) option(samples, s, s);
  const machine = $('machine');
  machine.textContent = '';
  option(machine, '', T().programMachine);
  for (const m of info.machines) option(machine, m.id, m.name);
  machine.value = ui.machine;
  machine.title = T().programMachineHint;
  const units = $('units');
  units.textContent = '';
  option(units, 0, T().unitsMachine);
  option(units, 1, T().unitsMm);
  option(units, 2, T().unitsInch);
  units.value = String(ui.units);
  units.title = T().unitsHint;
  const sp = $('speed');
  sp.textContent = '';
  for (const s of speeds) option(sp, s, s ? `${s}×` : T().speedMax);
  sp.value = String(speed);
  setRunState(document.body.dataset.run || 'ready');
  if (!run) showFeatures();
  else if (document.body.dataset.part === 'yes') showFeatures(run.features);
  if (diagnostics.length === 0 && document.body.dataset.checked === 'yes') showDiagnostics([]);
}

async function main() {
  $('explain').textContent = texts[ui.lang].loading;
  try {
    startWorker();
  } catch (e) {
    showMessage(`${e}`);
    return;
  }
  await applyLanguage();
  $('explain').textContent = '';
  const first = new URLSearchParams(location.search).get('sample');
  const info = await call('info', { lang: langCode() });
  if (info.samples.length) await loadSample(first && info.samples.includes(first) ? first : info.samples[0]);
  document.body.dataset.ready = 'yes';
}

main().catch((e) => showMessage(String(e)));
