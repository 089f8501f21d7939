// `geovis view`: the page. Loads the frames' channels from the server, shows one channel or post
// shader (computed on the GPU, image_view.ts) with a colour map, reads out every channel under the
// mouse, and on a click asks the server for the pixel's light ray and draws it (ray_view.ts).
import './style.css';
import { fetchFrame, fetchInfo, fetchPostValues, fetchRay, type Frame, type Info, type Ray, type RGB } from './api';
import { drawColorbar, formatNumber } from './colorbar';
import { ImageView, type ValueSource } from './image_view';
import { shaderChannels } from './post_shaders';
import { RayView } from './ray_view';

const $ = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;

const ui = {
  source: $<HTMLSelectElement>('source'),
  colormap: $<HTMLSelectElement>('colormap'),
  mass: $<HTMLInputElement>('mass'),
  massLabel: $<HTMLLabelElement>('mass-label'),
  scale: $<HTMLSelectElement>('scale'),
  lo: $<HTMLInputElement>('range-lo'),
  hi: $<HTMLInputElement>('range-hi'),
  auto: $<HTMLButtonElement>('range-auto'),
  fit: $<HTMLButtonElement>('zoom-fit'),
  one: $<HTMLButtonElement>('zoom-one'),
  play: $<HTMLButtonElement>('play'),
  frame: $<HTMLInputElement>('frame'),
  frameName: $<HTMLSpanElement>('frame-name'),
  frames: $<HTMLSpanElement>('frames'),
  canvas: $<HTMLCanvasElement>('image'),
  colorbar: $<HTMLCanvasElement>('colorbar'),
  status: $<HTMLDivElement>('status'),
  pixel: $<HTMLSpanElement>('pixel-xy'),
  readout: $<HTMLTableElement>('readout'),
  rayTitle: $<HTMLSpanElement>('ray-title'),
  rayInfo: $<HTMLPreElement>('ray-info'),
};

let info: Info;
let frame: Frame;
let view: ImageView;
let rays: RayView;
let lastRay: Ray | null = null;
let autoRange = true;
let hovered: [number, number] | null = null;

function showError(e: unknown): void {
  ui.status.textContent = e instanceof Error ? e.message : String(e);
}

/** The selected source: "rgb", "channel:NAME" or "post:NAME". */
function sourceKind(): { kind: 'rgb' | 'channel' | 'post'; name: string } {
  const v = ui.source.value;
  if (v === 'rgb') return { kind: 'rgb', name: 'rgb' };
  const [kind, ...rest] = v.split(':');
  return { kind: kind as 'channel' | 'post', name: rest.join(':') };
}

function valueSource(): ValueSource {
  const s = sourceKind();
  // disk-flux: M from the field (geovis post --mass), else the header's metric.mass, else 1 (render/post.h).
  const mass = Number(ui.mass.value || frame.metadata['geovis:metric.mass'] || '1');
  if (s.kind === 'post') {
    const ch = shaderChannels[s.name];
    return s.name === 'disk-flux' ? { mode: 1, a: ch[0], b: ch[1], mass } : { mode: 0, a: ch[0], mass };
  }
  return { mode: 0, a: s.kind === 'channel' ? s.name : frame.channels[0], mass };
}

function isCategorical(): boolean {
  const s = sourceKind();
  return s.name === 'stop';
}

function label(): string {
  const s = sourceKind();
  if (s.kind === 'post') return frame.shaders.find((x) => x.name === s.name)?.label ?? s.name;
  return s.kind === 'rgb' ? 'rendered colour' : `channel ${s.name}`;
}

/** Finite min/max of the values (positive ones for a log scale), as geovis post picks its range. */
function dataRange(values: Float32Array, log: boolean): [number, number] {
  let lo = Infinity, hi = -Infinity;
  for (const v of values) if (Number.isFinite(v) && (!log || v > 0)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
  if (!(lo <= hi)) return [0, 1];
  if (lo === hi) hi = lo + (lo === 0 ? 1 : Math.abs(lo) * 1e-6);
  return [lo, hi];
}

function fillSources(): void {
  const keep = ui.source.value;
  ui.source.innerHTML = '';
  const add = (value: string, text: string, disabled = false, title = '') => {
    const o = new Option(text, value);
    o.disabled = disabled;
    o.title = title;
    ui.source.add(o);
  };
  if (['R', 'G', 'B'].every((c) => frame.channels.includes(c))) add('rgb', 'image (R, G, B)');
  for (const c of frame.channels) add(`channel:${c}`, `channel ${c}`);
  for (const s of frame.shaders) add(`post:${s.name}`, `shader ${s.name}`, !s.available, s.why ?? s.label ?? '');
  const values = Array.from(ui.source.options).filter((o) => !o.disabled).map((o) => o.value);
  ui.source.value = values.includes(keep) ? keep : values[0];
}

function defaultColormap(): string {
  const s = sourceKind();
  if (s.kind === 'post') return frame.shaders.find((x) => x.name === s.name)?.colormap ?? 'viridis';
  return 'viridis';
}

/** Recompute the values on the GPU and redraw. */
function update(resetRange: boolean): void {
  const s = sourceKind();
  const log = ui.scale.value === 'log';
  ui.massLabel.style.display = s.name === 'disk-flux' ? '' : 'none';
  ui.status.textContent = '';
  // The rendered colour has no range or colour map.
  for (const el of [ui.colormap, ui.scale, ui.lo, ui.hi, ui.auto]) el.disabled = s.kind === 'rgb';
  if (s.kind === 'rgb') {
    view.setDisplay({ mode: 'rgb', map: [], lo: 0, hi: 1, log: false });
    drawColorbar(ui.colorbar, { map: [], lo: 0, hi: 1, log: false, label: label(), grey: false, categories: [] });
    showReadout();
    return;
  }
  const src = valueSource();
  if (!(src.mass > 0)) {
    showError(`disk-flux: the mass must be positive, found ${ui.mass.value}`);
    return;
  }
  view.computeValues(src);
  if (resetRange || autoRange) {
    const [lo, hi] = dataRange(view.values, log);
    ui.lo.value = String(lo);
    ui.hi.value = String(hi);
    autoRange = true;
  }
  const lo = Number(ui.lo.value), hi = Number(ui.hi.value);
  ui.status.textContent = '';
  if (!(lo < hi)) showError(`range: expected MIN < MAX, found ${ui.lo.value}, ${ui.hi.value}`);
  else if (log && !(lo > 0)) showError(`log scale: the range must be positive, found ${lo} to ${hi}`);
  const categorical = isCategorical();
  const cmap = ui.colormap.value;
  const mode = categorical ? 'categories' : cmap === 'grey' ? 'grey' : 'colormap';
  const map: RGB[] = categorical ? info.categories : info.colormaps[cmap] ?? [];
  view.setDisplay({ mode, map, lo, hi, log });
  drawColorbar(ui.colorbar, {
    map, lo, hi, log, label: label(), grey: cmap === 'grey',
    categories: categorical
      ? [...new Set(Array.from(view.values).filter(Number.isFinite))].sort((a, b) => a - b)
          .map((c) => ({ name: info.stop_names[c] ?? String(c), color: info.categories[c & 7] }))
      : undefined,
  });
  showReadout();
}

function showReadout(): void {
  const p = hovered;
  ui.pixel.textContent = p ? `${p[0]}, ${p[1]}` : '–';
  ui.readout.innerHTML = '';
  if (!p) return;
  const nc = frame.channels.length, base = (p[1] * frame.width + p[0]) * nc;
  const s = sourceKind();
  const row = (name: string, value: number, cls = '') => {
    const tr = ui.readout.insertRow();
    tr.className = cls;
    tr.dataset.name = name;
    tr.insertCell().textContent = name;
    let text = Number.isNaN(value) ? 'nan' : formatNumber(value);
    if (name === 'stop' && Number.isFinite(value)) text += ` (${info.stop_names[value] ?? '?'})`;
    const td = tr.insertCell();
    td.textContent = text;
    td.title = String(value);  // the float32 value in full
  };
  if (s.kind === 'post') row(`shader ${s.name}`, view.values[p[1] * frame.width + p[0]], 'shown');
  frame.channels.forEach((c, i) => row(c, frame.data[base + i], s.kind === 'channel' && s.name === c ? 'shown' : ''));
}

async function loadFrame(index: number): Promise<void> {
  frame = await fetchFrame(index);
  view.setFrame(frame);
  ui.mass.placeholder = frame.metadata['geovis:metric.mass'] || '1';  // what an empty field means
  ui.frame.value = String(index);
  ui.frameName.textContent = `${info.frames[index].name} (${index + 1}/${info.frames.length})`;
  fillSources();
  ui.colormap.value = ui.colormap.value || defaultColormap();
  update(false);
}

function showRay(ray: Ray): void {
  lastRay = ray;
  rays.show(ray);
  const n = ray.points?.length ?? 0;
  ui.rayTitle.textContent = `pixel ${ray.pixel[0]}, ${ray.pixel[1]}: ${ray.stop ?? 'no ray'}` +
    (ray.hit ? ` (object ${ray.object_id})` : '');
  const lines = [
    `${ray.metric} ${JSON.stringify(ray.params)}`,
    `${n} points, lambda = ${ray.lambda !== undefined ? formatNumber(ray.lambda) : '–'}`,
    ray.surface ? `${ray.surface.kind}: |p| = ${formatNumber(ray.surface.radius)} (${ray.surface.formula})` : '',
    `${ray.objects.length} object outline(s)`,
    ray.geodesic ? `\nthe same ray:\n${ray.geodesic.command}` : '',
    ray.geodesic?.differences.length ? `differs: ${ray.geodesic.differences.join('; ')}` : '',
  ];
  ui.rayInfo.textContent = lines.filter(Boolean).join('\n');
}

function setupInteraction(): void {
  let drag: { x: number; y: number; moved: boolean } | null = null;
  const local = (e: MouseEvent) => {
    const r = ui.canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  };
  ui.canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    const [x, y] = local(e);
    view.zoom(e.deltaY < 0 ? Math.SQRT2 : Math.SQRT1_2, x, y);
  }, { passive: false });
  ui.canvas.addEventListener('mousedown', (e) => { drag = { x: e.clientX, y: e.clientY, moved: false }; });
  window.addEventListener('mouseup', (e) => {
    if (drag && !drag.moved && e.target === ui.canvas) {
      const [x, y] = local(e);
      const p = view.pixelAt(x, y);
      if (p) {
        ui.rayTitle.textContent = `pixel ${p[0]}, ${p[1]}: tracing…`;
        fetchRay(frame.index, p[0], p[1]).then(showRay).catch((err) => {
          ui.rayTitle.textContent = `pixel ${p[0]}, ${p[1]}`;
          showError(err);
        });
      }
    }
    drag = null;
  });
  ui.canvas.addEventListener('mousemove', (e) => {
    if (drag && (e.buttons & 1)) {
      const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
      if (drag.moved || Math.abs(dx) + Math.abs(dy) > 3) {
        drag.moved = true;
        view.pan(dx, dy);
        drag.x = e.clientX;
        drag.y = e.clientY;
      }
    }
    const [x, y] = local(e);
    hovered = view.pixelAt(x, y);
    showReadout();
  });
  ui.fit.onclick = () => view.fit();
  ui.one.onclick = () => {
    const r = ui.canvas.getBoundingClientRect();
    view.zoom(1 / view.scale, r.width / 2, r.height / 2);
  };
  ui.source.onchange = () => {
    ui.colormap.value = defaultColormap();
    update(true);
  };
  ui.colormap.onchange = () => update(false);
  ui.mass.onchange = () => update(true);
  ui.scale.onchange = () => update(true);
  ui.lo.onchange = ui.hi.onchange = () => { autoRange = false; update(false); };
  ui.auto.onclick = () => update(true);
  ui.frame.oninput = () => loadFrame(Number(ui.frame.value)).catch(showError);
  let playing: number | null = null;
  ui.play.onclick = () => {
    if (playing !== null) {
      clearTimeout(playing);
      playing = null;
      ui.play.textContent = '▶';
      return;
    }
    ui.play.textContent = '⏸';
    const next = () => {
      loadFrame((frame.index + 1) % info.frames.length)
        .then(() => { if (playing !== null) playing = window.setTimeout(next, 200); })
        .catch(showError);
    };
    playing = window.setTimeout(next, 0);
  };
}

/** What the browser tests use (tests/cli/viewer/*.mjs). */
const testApi = {
  ready: false,
  get frame() { return frame; },
  get lastRay() { return lastRay; },
  get drawnRayPoints() { return rays.drawnPoints; },
  values: () => Array.from(view.values),
  /** Client (page) coordinates of the centre of image pixel (x, y). */
  pixelClientPosition(x: number, y: number): [number, number] {
    const r = ui.canvas.getBoundingClientRect();
    const [cx, cy] = view.pixelCentre(x, y);
    return [r.left + cx, r.top + cy];
  },
  zoomTo(scale: number) { view.zoom(scale / view.scale, 0, 0); },
  serverPostValues: async (shader: string, mass?: number) => Array.from(await fetchPostValues(frame.index, shader, mass)),
};
(window as unknown as { geovisViewer: typeof testApi }).geovisViewer = testApi;

async function main(): Promise<void> {
  view = new ImageView(ui.canvas);
  rays = new RayView($('ray-view'));
  info = await fetchInfo();
  for (const name of [...Object.keys(info.colormaps), 'grey']) ui.colormap.add(new Option(name, name));
  ui.frame.max = String(info.frames.length - 1);
  if (info.frames.length < 2) ui.frames.style.display = 'none';
  setupInteraction();
  await loadFrame(0);
  ui.colormap.value = defaultColormap();
  update(true);
  testApi.ready = true;
}

main().catch(showError);
