// The colour bar under the image: the map from the low to the high end of the range, five ticks
// (logarithmically spaced with a log scale), the quantity's label; categories as labelled swatches.
import type { RGB } from './api';

const css = (c: RGB) => `rgb(${Math.round(c[0] * 255)},${Math.round(c[1] * 255)},${Math.round(c[2] * 255)})`;

export function formatNumber(v: number): string {
  if (!Number.isFinite(v)) return String(v);
  return Math.abs(v) >= 1e5 || (Math.abs(v) < 1e-3 && v !== 0) ? v.toExponential(4) : String(Number(v.toPrecision(6)));
}

export function drawColorbar(canvas: HTMLCanvasElement, opts: {
  map: RGB[]; lo: number; hi: number; log: boolean; label: string; grey: boolean;
  categories?: { name: string; color: RGB }[];
}): void {
  const dpr = window.devicePixelRatio || 1;
  canvas.width = Math.round(canvas.clientWidth * dpr);
  canvas.height = Math.round(canvas.clientHeight * dpr);
  const g = canvas.getContext('2d')!;
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  const W = canvas.clientWidth;
  g.fillStyle = '#1d1f21';
  g.fillRect(0, 0, W, canvas.clientHeight);
  g.font = '11px system-ui, sans-serif';
  g.fillStyle = '#ddd';
  if (opts.categories) {
    const cell = W / Math.max(1, opts.categories.length);
    opts.categories.forEach((c, i) => {
      g.fillStyle = css(c.color);
      g.fillRect(i * cell + 2, 4, cell - 4, 12);
      g.fillStyle = '#ddd';
      g.fillText(c.name, i * cell + 4, 30);
    });
    g.fillText(opts.label, 4, 43);
    return;
  }
  const x0 = 8, x1 = W - 8;
  for (let x = x0; x < x1; ++x) {
    const t = (x - x0 + 0.5) / (x1 - x0);
    const c: RGB = opts.grey ? [t, t, t] : opts.map[Math.min(Math.floor(256 * t), 255)];
    g.fillStyle = css(c);
    g.fillRect(x, 4, 1, 12);
  }
  g.fillStyle = '#ddd';
  for (let i = 0; i < 5; ++i) {
    const s = i / 4;
    const v = opts.log ? Math.pow(10, Math.log10(opts.lo) + s * (Math.log10(opts.hi) - Math.log10(opts.lo))) : opts.lo + s * (opts.hi - opts.lo);
    const x = x0 + s * (x1 - x0);
    g.fillRect(x, 16, 1, 4);
    g.textAlign = i === 0 ? 'left' : i === 4 ? 'right' : 'center';
    g.fillText(formatNumber(v), x, 30);
  }
  g.textAlign = 'left';
  g.fillText(opts.label + (opts.log ? ' (log scale)' : ''), x0, 43);
}
