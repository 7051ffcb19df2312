// csgray view's speed as the page sees it, over HTTP, requests made as the
// page makes them (view/page/view.js): one frame at a time, the camera
// orbiting the script's own look_at at its distance and height, 800x600.
//   node bench/view_bench.mjs CSGRAY SCRIPT [NAME=VALUE] [--frames N] [--saves N]
// Prints one Markdown row: primitives, frames per second of pass 0 (a
// quarter of the size each way: what a drag shows), of pass 1 (the full
// size: where a drag stops) and of pass 2 (antialiased edges), and the
// median time from a save of the script to the first pass on the page
// (the watcher's 0.1 s debounce, the script, the first frame); and the
// frames per second that the page itself draws in chromium during a drag.
import { spawn, execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import { createRequire } from 'node:module';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  if (i < 0) return fallback;
  const value = +args[i + 1];
  args.splice(i, 2);
  return value;
};
const frames = option('--frames', 60);
const saves = option('--saves', 7);
const [csgray, original, define] = args;
const [width, height] = [800, 600];

// The script is copied into a folder of its own, so that a save is seen
// and the original stays as it was; the files it reads lie beside it.
const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'csgray-view-bench-'));
const script = path.join(folder, path.basename(original));
fs.copyFileSync(original, script);
const defines = define ? ['-D', define] : [];
const primitives = /primitives:\s*(\d+)/.exec(
  execFileSync(csgray, ['info', script, ...defines], { encoding: 'utf8' }))[1];

const server = spawn(csgray, ['view', script, '--threads', '2', ...defines],
  { stdio: ['ignore', 'pipe', 'inherit'] });
const url = await new Promise((resolve, reject) => {
  let out = '';
  server.stdout.on('data', (c) => {
    out += c;
    const m = /at (http:\/\/127\.0\.0\.1:\d+)\//.exec(out);
    if (m) resolve(m[1]);
  });
  server.on('exit', (code) => reject(new Error(`csgray view exited with ${code}`)));
});

// Frames per second that the page draws in chromium (headless) during a
// drag of 3 s, 3 pixels a move, the moves as fast as the DevTools protocol
// takes them (their rate follows, in brackets: the page cannot draw more
// frames than it is sent moves), its canvas 800x600; "-" without chromium
// or the browser test's puppeteer-core (tests/browser/).
async function browserDrag(url) {
  const chromium = process.env.CHROMIUM || '/usr/bin/chromium';
  let puppeteer;
  try {
    const require = createRequire(path.resolve('tests/browser/package.json'));
    puppeteer = (await import(pathToFileURL(require.resolve('puppeteer-core')))).default;
  } catch {
    return '-';
  }
  if (!fs.existsSync(chromium)) return '-';
  const browser = await puppeteer.launch({ executablePath: chromium, headless: true,
    args: ['--no-sandbox', '--disable-gpu'] });
  try {
    const page = await browser.newPage();
    // The panel's width is the page's; the canvas gets the rest.
    await page.setViewport({ width: width + 400, height });
    await page.goto(url);
    const panel = await page.$eval('aside', (e) => e.getBoundingClientRect().width);
    await page.setViewport({ width: width + Math.round(panel), height });
    const box = await (await page.$('#frame')).boundingBox();
    if (Math.round(box.width) !== width || Math.round(box.height) !== height)
      throw new Error(`canvas ${box.width}x${box.height}`);
    const settled = () => page.waitForFunction(() => document.getElementById('frame').dataset.settled === '1',
      { polling: 20, timeout: 60000 });
    await settled();
    const count = () => page.$eval('#frame', (e) => +e.dataset.frames);
    let x = box.x + 100, y = box.y + box.height / 2;
    await page.mouse.move(x, y);
    await page.mouse.down();
    const before = await count(), start = performance.now();
    let moves = 0;
    while (performance.now() - start < 3000) {
      await page.mouse.move((x += 3), y);
      ++moves;
    }
    const drawn = (await count()) - before, seconds = (performance.now() - start) / 1000;
    await page.mouse.up();
    return `${(drawn / seconds).toFixed(1)} (${(moves / seconds).toFixed(0)})`;
  } finally {
    await browser.close();
  }
}

try {
  const state = await (await fetch(url + '/scene')).json();
  if (!state.camera) throw new Error(`${original} has no camera to orbit about`);
  // The page's orbit (view.js): yaw about z, pitch above the xy plane.
  const { eye, lookAt, fov } = state.camera;
  const d = eye.map((v, i) => v - lookAt[i]);
  const distance = Math.hypot(...d);
  const pitch = Math.asin(d[2] / distance);
  const yaw0 = Math.atan2(d[1], d[0]);
  const camera = (k) => {
    const yaw = yaw0 + k * 0.03;  // a drag of 3 pixels a frame (0.01 rad a pixel)
    const c = Math.cos(pitch), s = Math.sin(pitch);
    const e = [c * Math.cos(yaw), c * Math.sin(yaw), s].map((v, i) => lookAt[i] + distance * v);
    const up = [-s * Math.cos(yaw), -s * Math.sin(yaw), c];
    return `camera=${[...e, ...lookAt, ...up].join(',')}&fov=${fov}&size=${width}x${height}`;
  };
  const frame = async (k, pass) => {
    const response = await fetch(`${url}/frame?${camera(k)}&pass=${pass}`);
    if (!response.ok) throw new Error(`frame: ${response.status} ${await response.text()}`);
    await response.arrayBuffer();
  };
  const rate = async (pass, n) => {
    await frame(0, pass);  // warm
    const start = performance.now();
    for (let k = 1; k <= n; ++k) await frame(k, pass);
    return n / ((performance.now() - start) / 1000);
  };
  const fps = [await rate(0, frames), await rate(1, Math.ceil(frames / 4)), await rate(2, Math.ceil(frames / 8))];

  // A save: the same text written again, as an editor does; then the long
  // poll and the first pass, as the page asks for them.
  const source = fs.readFileSync(script);
  let version = state.version;
  const latencies = [];
  for (let i = 0; i < saves; ++i) {
    const start = performance.now();
    fs.writeFileSync(script, source);
    const next = await (await fetch(`${url}/wait?version=${version}`)).json();
    if (next.version === version) throw new Error('no reload within the long poll');
    version = next.version;
    await frame(i, 0);
    latencies.push(performance.now() - start);
    await new Promise((r) => setTimeout(r, 150));
  }
  latencies.sort((a, b) => a - b);
  const median = latencies[Math.floor(latencies.length / 2)];
  const dragged = await browserDrag(url);
  const name = path.basename(original, '.lua') + (define ? `(${define.split('=')[1]})` : '');
  console.log(`| ${name} | ${primitives} | ${fps.map((f) => f.toFixed(1)).join(' | ')} | ` +
    `${dragged} | ${median.toFixed(0)} |`);
} finally {
  server.kill('SIGINT');
  fs.rmSync(folder, { recursive: true, force: true });
}
