// csgray view's page in a real browser: Debian's chromium, headless,
// driven by puppeteer-core over the DevTools protocol. It starts `csgray
// view` on a script in a temporary folder and checks what a person would:
// the canvas shows the part, a drag turns it, a save (in place, and by
// rename) shows the new part, a broken script shows its error with
// file:line over the last image, a customizer slider renders again, a
// refused value is said under its control, and the keys for the axis
// views look along the axes (the picked face's normal says which).
//
//   node view_test.mjs CSGRAY [SCREENSHOTS_DIR]
//
// With SCREENSHOTS_DIR, it also saves the page as docs/view.md shows it
// (view_*.png). run.sh starts it, or skips it when chromium is missing.
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import puppeteer from 'puppeteer-core';

const csgray = process.argv[2];
const screenshots = process.argv[3] || process.env.CSGRAY_SCREENSHOTS || '';
const chromium = process.env.CHROMIUM || '/usr/bin/chromium';
const timeout = 60_000;

// A plate 40 × 20 × 10 about the origin, whose width is a parameter,
// with two holes through it away from the middle (the picks there hit the
// plate); line 2 makes the plate, so that a broken line 2 names it.
const part = (width = 40, line2 = 'local plate = box{size={width, 20, 10}, center=true}') =>
  `width = ${width} -- [10:100] the width, mm\n${line2}\n` +
  'local hole = cylinder{r=3, h=12, center=true}\n' +
  'return plate - hole:translate(width / 4, 0, 0) - hole:translate(-width / 4, 0, 0)\n';

let folder, script, server, browser, page;

// Starts `csgray view` and resolves with the URL it prints.
function startServer() {
  server = spawn(csgray, ['view', script, '--threads', '2'], { stdio: ['ignore', 'pipe', 'pipe'] });
  let output = '';
  return new Promise((resolve, reject) => {
    const seen = (chunk) => {
      output += chunk;
      const url = /at (http:\/\/127\.0\.0\.1:\d+\/)/.exec(output);
      if (url) resolve(url[1]);
    };
    server.stdout.on('data', seen);
    server.stderr.on('data', seen);
    server.on('exit', (code) => reject(new Error(`csgray view exited (${code}): ${output}`)));
  });
}

before(async () => {
  if (screenshots) fs.mkdirSync(screenshots, { recursive: true });
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'csgray-browser-'));
  script = path.join(folder, 'part.lua');
  fs.writeFileSync(script, part());
  const url = await startServer();
  browser = await puppeteer.launch({
    executablePath: chromium,
    headless: true,
    // As root (CI, containers) chromium refuses its sandbox.
    args: ['--no-sandbox', '--disable-gpu', '--hide-scrollbars'],
  });
  page = await browser.newPage();
  page.setDefaultTimeout(timeout);
  await page.setViewport({ width: 900, height: 540 });
  page.on('pageerror', (e) => console.error('page error:', e.message));
  page.on('console', (m) => m.type() === 'error' && console.error('page console:', m.text()));
  await page.goto(url);
});

after(async () => {
  if (browser) await browser.close();
  if (server && server.exitCode === null) {
    const exited = new Promise((resolve) => server.on('exit', resolve));
    server.kill('SIGINT');
    await exited;
  }
  if (folder) fs.rmSync(folder, { recursive: true, force: true });
});

// ---- What the page shows

// The page's counters: frames drawn, the pass and the script's version of
// the last one, and whether the last pass of the current view is drawn.
const frameState = () =>
  page.evaluate(() => {
    const d = document.getElementById('frame').dataset;
    return { frames: +(d.frames || 0), version: +(d.version || -1), settled: d.settled === '1' };
  });

// Waits until the last pass of the current view is on the canvas, drawn
// after `since` (a frameState) and of a script version above `version`.
async function settled({ since = { frames: 0 }, version = -1 } = {}) {
  await page.waitForFunction(
    (frames, version) => {
      const d = document.getElementById('frame').dataset;
      return d.settled === '1' && +(d.frames || 0) > frames && +(d.version || -1) > version;
    },
    { timeout, polling: 50 },
    since.frames,
    version,
  );
  return frameState();
}

// The canvas's pixels, and how many differ from the background: the first
// pixel of their row, since the part is framed in the middle and a bare
// solid's background is a vertical gradient.
async function pixels() {
  return page.evaluate(() => {
    const canvas = document.getElementById('frame');
    const { data, width, height } = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height);
    const far = (i, j) => Math.abs(data[i] - data[j]) + Math.abs(data[i + 1] - data[j + 1]) +
      Math.abs(data[i + 2] - data[j + 2]) > 24;
    let part = 0, edge = 0;
    for (let i = 0; i < data.length; i += 4) {
      const x = (i / 4) % width, y = Math.floor(i / 4 / width);
      if (!far(i, 4 * y * width)) continue;
      ++part;
      if (x === 0 || y === 0 || x === width - 1 || y === height - 1) ++edge;
    }
    const row = 4 * Math.floor(height / 2) * width;
    const centre = row + 4 * Math.floor(width / 2);
    return { width, height, part, edge, centreIsPart: far(centre, row), sum: Array.from(data) };
  });
}

// Pixels of two pictures of the same size that differ.
function changed(a, b) {
  assert.equal(a.sum.length, b.sum.length);
  let n = 0;
  for (let i = 0; i < a.sum.length; i += 4)
    if (Math.abs(a.sum[i] - b.sum[i]) + Math.abs(a.sum[i + 1] - b.sum[i + 1]) +
        Math.abs(a.sum[i + 2] - b.sum[i + 2]) > 24) ++n;
  return n;
}

const text = (id) => page.$eval('#' + id, (e) => e.textContent);
const shoot = async (name) => {
  if (screenshots) await page.screenshot({ path: path.join(screenshots, `view_${name}.png`) });
};

// Writes the script as an editor does: in place, or by a new file
// renamed over it (vim, most IDEs).
function save(source, { rename = false } = {}) {
  if (!rename) return fs.writeFileSync(script, source);
  const temporary = path.join(folder, '.part.lua.swp');
  fs.writeFileSync(temporary, source);
  fs.renameSync(temporary, script);
}

// Clicks the middle of the canvas, and returns the picked face's normal
// as the panel shows it, once it changed from `before`.
async function pickedNormalAtCentre(before) {
  const box = await (await page.$('#frame')).boundingBox();
  await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
  await page.waitForFunction((b) => document.getElementById('pick-normal').textContent !== b,
    { timeout, polling: 50 }, before);
  return text('pick-normal');
}

// ---- The checks, in order: each starts from the page the last left.

test('the canvas shows the part, rendered to the last pass', async () => {
  await settled();
  const p = await pixels();
  const area = p.width * p.height;
  assert.ok(p.width > 300 && p.height > 300, `canvas ${p.width}x${p.height}`);
  assert.ok(p.centreIsPart, 'the middle of the canvas is the part');
  assert.ok(p.part > 0.05 * area && p.part < 0.9 * area, `${p.part} of ${area} pixels are the part`);
  assert.equal(p.edge, 0, 'framed: no part on the canvas edges');
  assert.match(await text('size'), /^\(40, 20, 10\)$/);
  assert.equal(await page.$eval('#error', (e) => e.hidden), true);
  await shoot('page');
});

test('a drag orbits the view', async () => {
  const before = await frameState();
  const image = await pixels();
  const box = await (await page.$('#frame')).boundingBox();
  const x = box.x + box.width / 2, y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let i = 1; i <= 10; ++i) await page.mouse.move(x + 12 * i, y + 3 * i);
  await page.mouse.up();
  await settled({ since: before });
  const turned = await pixels();
  assert.ok(turned.centreIsPart, 'the orbit is about the part');
  assert.ok(changed(image, turned) > 0.02 * image.width * image.height, 'the picture turned');
});

test('the wheel zooms toward the cursor', async () => {
  let state = await frameState();
  const image = await pixels();
  const box = await (await page.$('#frame')).boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.wheel({ deltaY: -200 });
  state = await settled({ since: state });
  const near = await pixels();
  assert.ok(near.part > image.part * 1.2, `closer: ${image.part} to ${near.part} pixels`);
  await page.mouse.wheel({ deltaY: 200 });
  await settled({ since: state });
  const back = await pixels();
  assert.ok(Math.abs(back.part - image.part) < 0.02 * image.part, 'and back');
});

test('saving the script shows the new part, in place and by rename', async () => {
  let state = await frameState();
  const image = await pixels();
  save(part(80));
  state = await settled({ since: state, version: state.version });
  assert.match(await text('size'), /^\(80, 20, 10\)$/);
  const wider = await pixels();
  assert.ok(wider.part > image.part * 1.2, `the part grew: ${image.part} to ${wider.part} pixels`);
  save(part(25), { rename: true });
  state = await settled({ since: state, version: state.version });
  assert.match(await text('size'), /^\(25, 20, 10\)$/);
  assert.ok((await pixels()).part < wider.part, 'the part shrank');
  save(part(40));
  await settled({ since: state, version: state.version });
  assert.match(await text('size'), /^\(40, 20, 10\)$/);
});

test('a broken script shows its error with file:line over the last image', async () => {
  const state = await frameState();
  const image = await pixels();
  save(part(40, 'local plate = sphere{r=3, h=2}'));
  await page.waitForFunction(() => !document.getElementById('error').hidden, { timeout, polling: 50 });
  const error = await text('error');
  assert.ok(error.includes('part.lua:2:'), `the error names the line: ${error}`);
  await settled({ since: state, version: state.version });
  const kept = await pixels();
  assert.ok(kept.centreIsPart, 'the last good part is still shown');
  assert.ok(changed(image, kept) < 0.01 * image.width * image.height, 'the image is the last good one');
  assert.match(await text('size'), /^\(40, 20, 10\)$/);
  await shoot('error');
  save(part(40));
  await page.waitForFunction(() => document.getElementById('error').hidden, { timeout, polling: 50 });
});

test('a customizer slider runs the script again and renders', async () => {
  let state = await settled();
  const image = await pixels();
  assert.equal(await page.$eval('#customizer', (e) => e.hidden), false);
  const slider = '.parameter[data-name="width"] input[type=range]';
  assert.equal(await page.$eval(slider, (e) => [e.min, e.max, e.value].join()), '10,100,40');
  // As a hand moves it: input events, the last one at 90.
  await page.$eval(slider, (e) => {
    for (const v of [50, 70, 90]) {
      e.value = v;
      e.dispatchEvent(new Event('input', { bubbles: true }));
    }
  });
  state = await settled({ since: state, version: state.version });
  assert.match(await text('size'), /^\(90, 20, 10\)$/);
  assert.equal(await page.$eval('.parameter[data-name="width"] input[type=number]', (e) => e.value), '90');
  const grown = await pixels();
  assert.ok(grown.part > image.part * 1.2, 'the part grew');
  assert.ok(grown.edge > 0, 'the camera stayed: the longer part leaves the canvas');
  // f fits it again (keys go to the page once the focus left the boxes).
  await page.$eval(slider, (e) => e.blur());
  await page.keyboard.press('f');
  state = await settled({ since: state });
  assert.equal((await pixels()).edge, 0, 'fitted: no part on the canvas edges');
  await shoot('customizer');
  // A value the annotation refuses is said under its control; nothing changes.
  const number = '.parameter[data-name="width"] input[type=number]';
  await page.$eval(number, (e) => {
    e.value = 500;
    e.dispatchEvent(new Event('change', { bubbles: true }));
  });
  await page.waitForFunction(
    () => document.querySelector('.parameter[data-name="width"] .refused').textContent !== '',
    { timeout, polling: 50 });
  assert.match(await page.$eval('.parameter[data-name="width"] .refused', (e) => e.textContent),
    /width must be from 10 to 100 \(.*part\.lua:1\)/);
  assert.match(await text('size'), /^\(90, 20, 10\)$/);
  assert.equal(await page.$eval(number, (e) => e.value), '90', 'the box shows the value in force');
  // "default" gives the value back to the script.
  await page.click('.parameter[data-name="width"] button');
  await settled({ since: state, version: state.version });
  assert.match(await text('size'), /^\(40, 20, 10\)$/);
  assert.equal(await page.$eval(slider, (e) => e.value), '40');
});

test('the keys for the axis views look along the axes', async () => {
  // Keys go to the page wherever the focus is, but not into a text box.
  await page.$eval('#frame', (e) => e.blur());
  let normal = await text('pick-normal');
  const views = [['1', '(0, -1, 0)'], ['5', '(0, 0, 1)'], ['4', '(1, 0, 0)'], ['3', '(-1, 0, 0)'],
    ['2', '(0, 1, 0)'], ['6', '(0, 0, -1)']];
  for (const [key, expected] of views) {
    const state = await frameState();
    await page.keyboard.press(key);
    await settled({ since: state });
    // A click at the middle picks the face the view looks at.
    normal = await pickedNormalAtCentre(normal);
    assert.equal(normal, expected, `key ${key}`);
  }
  let state = await frameState();
  await page.keyboard.press('o');
  state = await settled({ since: state });
  assert.equal(await text('projection'), 'orthographic');
  await page.keyboard.press('0');
  await settled({ since: state });
});

test('a double-click centres the view on the picked point', async () => {
  let state = await settled();
  const box = await (await page.$('#frame')).boundingBox();
  const x = box.x + box.width / 2 + 60, y = box.y + box.height / 2 + 25;
  const before = await text('pick-point');
  await page.mouse.click(x, y, { clickCount: 1 });
  await page.mouse.click(x, y, { clickCount: 2 });
  await page.waitForFunction((b) => document.getElementById('pick-point').textContent !== b,
    { timeout, polling: 50 }, before);
  const picked = (await text('pick-point')).slice(1, -1).split(', ').map(Number);
  state = await settled({ since: state });
  // The point now lies under the middle of the canvas: asked as the page
  // asks, for the view it shows.
  const hit = await page.evaluate(async () => {
    const c = document.getElementById('frame');
    return (await fetch(`/pick?${frameKey()}&x=${c.width / 2}&y=${c.height / 2}`)).json();
  });
  assert.ok(hit.hit);
  const centre = hit.point;
  const distance = Math.hypot(...picked.map((v, i) => v - centre[i]));
  assert.ok(distance < 0.5, `picked ${picked}, now at the middle ${centre}`);
});

test('a section shows the cut in its colour, and picks it', async () => {
  let state = await frameState();
  await page.keyboard.press('f');  // the middle of the canvas on the plate's centre
  state = await settled({ since: state });
  await page.keyboard.press('1');  // from the front, along +y
  state = await settled({ since: state });
  await page.select('#section-axis', 'y');
  await page.$eval('#section-flip', (e) => { e.checked = true; });
  await page.$eval('#section-on', (e) => {
    e.checked = true;
    e.dispatchEvent(new Event('input', { bubbles: true }));
  });
  state = await settled({ since: state });
  assert.match(await text('section-where'), /^y = 0$/);
  // The middle of the plate, cut at y = 0: the section's red.
  const [r, g, b] = await page.evaluate(() => {
    const c = document.getElementById('frame');
    return Array.from(c.getContext('2d').getImageData(c.width / 2, c.height / 2, 1, 1).data);
  });
  assert.ok(r > g + 60 && r > b + 60, `the middle is red: ${r}, ${g}, ${b}`);
  const normal = await pickedNormalAtCentre(await text('pick-normal'));
  assert.equal(normal, '(0, -1, 0)');
  assert.equal(await text('pick-kind'), 'section');
  await shoot('section');
  await page.$eval('#section-on', (e) => {
    e.checked = false;
    e.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await settled({ since: state });
});

test('check shows the warnings at their points, export offers the file', async () => {
  // The cut's top and bottom lie in the box's: two coincident faces.
  let state = await frameState();
  save('return box{size={20, 20, 10}, center=true} - box{size={6, 6, 10}, center=true}\n');
  state = await settled({ since: state, version: state.version });
  await page.keyboard.press('0');
  state = await settled({ since: state });
  await page.click('#check');
  await page.waitForFunction(() => /^check: (ok|FAILED)/.test(document.getElementById('job-line').textContent),
    { timeout, polling: 100 });
  assert.match(await text('job-line'), /^check: ok, [1-9]\d* warnings?$/);
  const markers = await page.$$eval('.marker', (all) => all.map((m) => {
    const r = m.getBoundingClientRect();
    return { x: r.x + r.width / 2, y: r.y + r.height / 2, title: m.title };
  }));
  assert.ok(markers.length > 0, 'markers on the image');
  const box = await (await page.$('#frame')).boundingBox();
  for (const m of markers) {
    assert.match(m.title, /^coincident faces: /);
    // On the part, which is framed in the middle of the canvas.
    assert.ok(Math.abs(m.x - (box.x + box.width / 2)) < box.width / 3, `marker at ${m.x}`);
    assert.ok(Math.abs(m.y - (box.y + box.height / 2)) < box.height / 3, `marker at ${m.y}`);
  }
  // Seen from above, a point on the bottom face is behind the part: faded.
  await page.waitForFunction(() => document.querySelector('.marker.hidden') !== null,
    { timeout, polling: 100 });
  assert.match(await page.$eval('.marker.hidden', (m) => m.title), /, -5\) \(behind the part\)$/);
  await shoot('check');
  await page.click('#export-stl');
  await page.waitForFunction(() => /^part\.stl: \d+ bytes$/.test(document.getElementById('job-line').textContent),
    { timeout, polling: 100 });
  assert.equal((await page.$$('.marker')).length, 0, 'the markers went with the check');
  assert.deepEqual(fs.readdirSync(folder).sort(), ['part.lua'], 'nothing written beside the script');
});

test('the switches show and hide the script\'s ghosts and highlights', async () => {
  let state = await frameState();
  assert.equal(await page.$eval('#modifiers', (e) => e.hidden), true, 'no switches without marks');
  save('return box{size={20, 20, 10}, center=true} + sphere(8):translate(0, 0, 10):ghost()\n');
  state = await settled({ since: state, version: state.version });
  assert.equal(await page.$eval('#modifiers', (e) => e.hidden), false);
  assert.equal(await page.$eval('#show-ghosts-label', (e) => e.hidden), false);
  assert.equal(await page.$eval('#show-highlights-label', (e) => e.hidden), true);
  const shown = await pixels();
  await page.click('#show-ghosts');
  state = await settled({ since: state });
  const hidden = await pixels();
  assert.ok(changed(shown, hidden) > 0.01 * shown.width * shown.height, 'the ghost is gone');
  assert.ok(hidden.part < shown.part, `fewer pixels differ from the background: ${hidden.part} < ${shown.part}`);
});
