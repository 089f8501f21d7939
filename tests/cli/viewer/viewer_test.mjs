// Browser test of `geovis view` (docs/viewer.md): Playwright (web/node_modules/playwright-core)
// drives Debian's chromium headless (WebGL2 through SwiftShader) against the real program.
//   node viewer_test.mjs --geovis build/geovis --source . --out DIR [--screenshots DIR]
// Exit 77 (CTest: skipped) with the reason when chromium or playwright-core is missing.
import { spawn, execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import assert from 'node:assert/strict';
import { pathToFileURL } from 'node:url';

const arg = (name, def) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? process.argv[i + 1] : def;
};
const geovis = arg('geovis');
const source = arg('source');
const out = arg('out');
const shots = arg('screenshots', out);
const chromiumPath = process.env.GEOVIS_CHROMIUM ?? '/usr/bin/chromium';

function skip(why) {
  console.log(`SKIPPED: ${why}`);
  process.exit(77);
}
if (!fs.existsSync(chromiumPath)) skip(`no chromium at ${chromiumPath} (Debian package chromium; scripts/setup.sh installs it)`);
const pw = path.join(source, 'web/node_modules/playwright-core/index.mjs');
if (!fs.existsSync(pw)) skip(`no ${pw} (npm ci in web/ runs when geovis is built with npm present)`);
const { chromium } = await import(pathToFileURL(pw).href);

const t0 = Date.now();
const step = (what) => console.log(`- ${what} [${((Date.now() - t0) / 1000).toFixed(1)} s]`);

// ---- data: two frames of the paper's Fig. 9 disk (inclination 80 and 60 degrees) ----
fs.rmSync(out, { recursive: true, force: true });
fs.mkdirSync(path.join(out, 'frames'), { recursive: true });
fs.mkdirSync(shots, { recursive: true });
const scene = path.join(source, 'examples/fig9_disk_flux.scm');
const render = (name, defines) =>
  execFileSync(geovis, ['render', scene, '-o', path.join(out, 'frames', name), '--data', '--res', '64x40', '-q', ...defines]);
render('frame_0.png', []);
render('frame_1.png', ['--define', 'incl=60']);
for (const f of ['frame_0.png', 'frame_1.png', 'frame_0.pdz', 'frame_1.pdz']) fs.rmSync(path.join(out, 'frames', f));
const data0 = path.join(out, 'frames', 'frame_0.exr');

// `geovis post --csv`: the values of every pixel, read by the program (independent of the page).
const csv = execFileSync(geovis, ['post', data0, '--csv', '-', '--channels', 'x1,z,stop']).toString().trim().split('\n');
const rows = csv.slice(1).map((l) => l.split(',')).map(([x, y, x1, z, stop]) => ({ x: +x, y: +y, x1, z, stop: +stop }));
// A pixel on the disk (stop 0 = hit) near the image centre.
const disk = rows.filter((r) => r.stop === 0 && r.z !== 'nan').sort((a, b) => Math.hypot(a.x - 32, a.y - 20) - Math.hypot(b.x - 32, b.y - 20))[0];
assert.ok(disk, 'the disk is in the picture');

// ---- the server ----
const server = spawn(geovis, ['view', path.join(out, 'frames'), '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
const url = await new Promise((resolve, reject) => {
  let text = '';
  server.stdout.on('data', (d) => {
    text += d;
    const m = text.match(/http:\/\/127\.0\.0\.1:\d+\//);
    if (m) resolve(m[0]);
  });
  server.on('exit', (code) => reject(new Error(`geovis view exited with ${code}: ${text}`)));
});
step(`geovis view serves ${url}`);

const browser = await chromium.launch({
  executablePath: chromiumPath,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
let failed = false;
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 }, deviceScaleFactor: 1 });
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(url);
  await page.waitForFunction(() => window.geovisViewer?.ready || document.getElementById('status').textContent, null, { timeout: 30000 });
  assert.equal(await page.textContent('#status'), '', 'no error on the page');
  step('page loaded (WebGL2)');

  const info = await (await fetch(url + 'api/info')).json();
  const centre = (x, y) => page.evaluate(([x, y]) => window.geovisViewer.pixelClientPosition(x, y), [x, y]);
  const readout = (name) => page.$eval(`#readout tr[data-name="${name}"] td:nth-child(2)`, (td) => td.title);
  const canvasColour = (x, y) => page.evaluate(([x, y]) => {
    const c = document.getElementById('image');
    const [px, py] = window.geovisViewer.pixelClientPosition(x, y);
    const r = c.getBoundingClientRect();
    const g = document.createElement('canvas');
    g.width = c.width; g.height = c.height;
    const ctx = g.getContext('2d');
    ctx.drawImage(c, 0, 0);
    const d = ctx.getImageData(Math.floor((px - r.left) * devicePixelRatio), Math.floor((py - r.top) * devicePixelRatio), 1, 1).data;
    return [d[0], d[1], d[2]];
  }, [x, y]);
  const select = async (id, value) => {
    await page.selectOption(`#${id}`, value);
    await page.waitForTimeout(50);
  };
  /** The colour `geovis post` gives value v: table entry min(floor(256 t), 255) (render/colormap.h). */
  const expectColour = async (x, y, v, map, log) => {
    const lo = Number(await page.inputValue('#range-lo')), hi = Number(await page.inputValue('#range-hi'));
    const t = Math.min(1, Math.max(0, log ? (Math.log10(v) - Math.log10(lo)) / (Math.log10(hi) - Math.log10(lo)) : (v - lo) / (hi - lo)));
    const got = await canvasColour(x, y);
    const entry = (i) => (map === 'grey' ? [t, t, t] : info.colormaps[map][i]).map((c) => Math.round(c * 255));
    const i = Math.min(Math.floor(256 * t), 255);
    const ok = (e) => e.every((c, k) => Math.abs(c - got[k]) <= 1);  // 8-bit rounding of the float colour
    // The GPU computes t in 32-bit floats: at a table boundary (256 t within 1e-3 of an integer) the
    // neighbouring entry is the same colour map evaluated within float precision.
    const nearBoundary = Math.abs(256 * t - Math.round(256 * t)) < 1e-3;
    assert.ok(ok(entry(i)) || (nearBoundary && (ok(entry(Math.max(i - 1, 0))) || ok(entry(Math.min(i + 1, 255))))),
              `${map}: pixel ${x},${y} value ${v} (t = ${t}) is ${got}, expected ${entry(i)}`);
  };

  // ---- hover a known pixel: the read-out is the data file's value ----
  let [px, py] = await centre(disk.x, disk.y);
  await page.mouse.move(px, py);
  assert.equal(await page.textContent('#pixel-xy'), `${disk.x}, ${disk.y}`);
  assert.equal(Number(await readout('x1')), Math.fround(Number(disk.x1)));
  assert.equal(Number(await readout('z')), Math.fround(Number(disk.z)));
  step(`hover pixel ${disk.x},${disk.y}: x1 = ${disk.x1}, z = ${disk.z} as geovis post --csv`);

  // ---- switch channel and colour map; the colour is the colour map's ----
  await select('source', 'channel:z');
  assert.equal(await page.$eval('#readout tr.shown', (tr) => tr.dataset.name), 'z');
  const z = Math.fround(Number(disk.z));
  await expectColour(disk.x, disk.y, z, 'viridis', false);
  await select('colormap', 'inferno');
  await expectColour(disk.x, disk.y, z, 'inferno', false);
  await select('colormap', 'grey');
  await expectColour(disk.x, disk.y, z, 'grey', false);
  await select('colormap', 'viridis');
  await select('scale', 'log');
  await expectColour(disk.x, disk.y, z, 'viridis', true);
  await select('scale', 'linear');
  step('channel z in viridis, inferno, grey, log scale: colours as the colour map tables');
  await page.screenshot({ path: path.join(shots, 'viewer-channel-z.png') });

  // ---- the post shaders on the GPU = geovis post's values (render/post.cpp) ----
  for (const [shader, mass] of [['redshift'], ['stop'], ['disk-flux'], ['disk-flux', 1.5]]) {
    await select('source', `post:${shader}`);
    if (mass) await page.fill('#mass', String(mass)).then(() => page.$eval('#mass', (el) => el.dispatchEvent(new Event('change'))));
    const r = await page.evaluate(async ([shader, mass]) => {
      const gpu = window.geovisViewer.values();
      const cpu = await window.geovisViewer.serverPostValues(shader, mass ?? undefined);
      const f = window.geovisViewer.frame, nc = f.channels.length, cx1 = f.channels.indexOf('x1'), cz = f.channels.indexOf('z');
      const eps = 2 ** -23;
      let values = 0, nanMismatch = 0, worst = 0;
      for (let i = 0; i < cpu.length; ++i) {
        if (Number.isNaN(cpu[i]) || Number.isNaN(gpu[i])) { nanMismatch += Number.isNaN(cpu[i]) !== Number.isNaN(gpu[i]); continue; }
        ++values;
        let bound = 0;  // redshift, stop: the channel itself, exactly
        if (shader === 'disk-flux') {
          // Float32 evaluation of paper eq. 16: the numerator sqrt R - sqrt 3 + sqrt(3/2)/2 log(...)
          // cancels near R = 3, so its error is a few ulp of its terms' magnitudes; then the
          // quotient and (1+z)^4 add a few ulp relative.
          const R = f.data[i * nc + cx1] / (2 * (mass ?? 1)), opz = f.data[i * nc + cz];
          const s32 = Math.sqrt(1.5), s3 = Math.sqrt(3), sR = Math.sqrt(R);
          const lg = Math.log((sR + s32) / (sR - s32) * (s3 - s32) / (s3 + s32));
          const terms = sR + s3 + Math.abs(0.5 * s32 * lg) + Math.abs(0.5 * s32 * (sR + s32) / (sR - s32));
          bound = 16 * eps * terms / ((R - 1.5) * R ** 2.5) / opz ** 4 + 16 * eps * Math.abs(cpu[i]);
        }
        const d = Math.abs(gpu[i] - cpu[i]);
        worst = Math.max(worst, bound > 0 ? d / bound : d === 0 ? 0 : Infinity);
      }
      return { values, nanMismatch, worst, n: cpu.length };
    }, [shader, mass ?? null]);
    assert.equal(r.nanMismatch, 0, `${shader}: pixels without a value agree`);
    assert.ok(r.values > 0, `${shader}: values to compare`);
    assert.ok(r.worst <= 1, `${shader}: GPU and geovis post differ beyond float precision (worst ${r.worst} of the bound)`);
    step(`shader ${shader}${mass ? ` (M = ${mass})` : ''} on the GPU: ${r.values} values as geovis post (worst ${r.worst.toFixed(3)} of the float bound)`);
  }
  await page.fill('#mass', '');
  await page.$eval('#mass', (el) => el.dispatchEvent(new Event('change')));
  await select('scale', 'log');
  await page.screenshot({ path: path.join(shots, 'viewer-disk-flux.png') });
  await select('scale', 'linear');

  // ---- zoom to exact pixels ----
  await page.evaluate(() => window.geovisViewer.zoomTo(8));
  [px, py] = await centre(disk.x, disk.y);
  await page.mouse.move(px + 3.5, py - 3.5);  // still inside the 8x8 screen pixels of the pixel
  assert.equal(await page.textContent('#pixel-xy'), `${disk.x}, ${disk.y}`);
  await page.mouse.move(px + 4.5, py);         // the next column
  assert.equal(await page.textContent('#pixel-xy'), `${disk.x + 1}, ${disk.y}`);
  // Pan: drag the image 16 screen pixels (2 image pixels) to the right.
  await page.mouse.move(px, py);
  await page.mouse.down();
  await page.mouse.move(px + 8, py, { steps: 2 });
  await page.mouse.move(px + 16, py, { steps: 2 });
  await page.mouse.up();
  await page.mouse.move(px, py);
  assert.equal(await page.textContent('#pixel-xy'), `${disk.x - 2}, ${disk.y}`);
  assert.equal(await page.evaluate(() => window.geovisViewer.lastRay), null, 'a drag is no click');
  await page.click('#zoom-fit');
  step('zoom 8x and pan: the read-out follows exact pixel boundaries');

  // ---- click a pixel: its light ray in 3D ----
  await select('source', 'rgb');
  [px, py] = await centre(disk.x, disk.y);
  await page.mouse.click(px, py);
  await page.waitForFunction(() => window.geovisViewer.lastRay, null, { timeout: 30000 });
  await page.waitForTimeout(200);
  const ray = await page.evaluate(() => ({ ...window.geovisViewer.lastRay, drawn: window.geovisViewer.drawnRayPoints }));
  assert.equal(ray.stop, 'hit');
  assert.deepEqual(ray.pixel, [disk.x, disk.y]);
  assert.ok(ray.points.length > 2);
  assert.equal(ray.drawn, ray.points.length, 'every point of the ray is drawn');
  assert.ok(Math.abs(ray.points.at(-1).x[1] - Number(disk.x1)) <= 2e-7 * Number(disk.x1), 'the ray ends at the stored hit');
  const lit = await page.evaluate(() => {
    const c = document.querySelector('#ray-view canvas');
    const g = document.createElement('canvas');
    g.width = c.width; g.height = c.height;
    const ctx = g.getContext('2d');
    ctx.drawImage(c, 0, 0);
    const d = ctx.getImageData(0, 0, g.width, g.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] > 200 && d[i + 1] > 200 && d[i + 2] < 170) ++n;  // the yellow ray (sRGB of (1, 0.85, 0.2))
    return n;
  });
  assert.ok(lit > 30, `the ray is drawn (${lit} ray-coloured pixels)`);
  step(`click ${disk.x},${disk.y}: ray of ${ray.points.length} points drawn, ends on the disk at r = ${ray.points.at(-1).x[1].toFixed(4)}`);
  // For the gallery: the top of the disk's image, light that passed over the hole from the far side.
  const arc = rows.filter((r) => r.stop === 0 && r.x === disk.x).sort((a, b) => a.y - b.y)[0];
  [px, py] = await centre(arc.x, arc.y);
  await page.mouse.click(px, py);
  await page.waitForFunction(([x, y]) => window.geovisViewer.lastRay?.pixel[1] === y && window.geovisViewer.lastRay?.pixel[0] === x,
                             [arc.x, arc.y], { timeout: 30000 });
  await page.waitForTimeout(200);
  await page.screenshot({ path: path.join(shots, 'viewer-ray.png') });

  // ---- frames: slider and play ----
  await page.$eval('#frame', (el) => { el.value = '1'; el.dispatchEvent(new Event('input')); });
  await page.waitForFunction(() => window.geovisViewer.frame.index === 1);
  assert.match(await page.textContent('#frame-name'), /frame_1\.exr/);
  assert.equal((await page.evaluate(() => window.geovisViewer.frame.metadata['geovis:scene.defines'])), 'incl=60');
  await page.click('#play');
  await page.waitForFunction(() => window.geovisViewer.frame.index === 0, null, { timeout: 10000 });
  await page.click('#play');
  step('frame slider and play');
  // The ray of frame 1 (the --define is re-applied).
  await page.$eval('#frame', (el) => { el.value = '1'; el.dispatchEvent(new Event('input')); });
  await page.waitForFunction(() => window.geovisViewer.frame.index === 1);
  const r1 = await (await fetch(`${url}api/ray?frame=1&x=${disk.x}&y=${disk.y}`)).json();
  assert.ok(r1.points && !r1.error, `frame 1 ray: ${r1.error}`);
  assert.equal(r1.observer.x[2], 60 * Math.PI / 180);
  assert.deepEqual(errors, [], 'no script errors');
  step('frame 1 re-traced with its --define');
} catch (e) {
  failed = true;
  console.error(e);
} finally {
  await browser.close();
  server.kill('SIGINT');
  const code = await new Promise((resolve) => server.on('exit', (c) => resolve(c)));
  if (code !== 0) { console.error(`geovis view exited with ${code} after Ctrl-C`); failed = true; }
}
process.exit(failed ? 1 : 0);
