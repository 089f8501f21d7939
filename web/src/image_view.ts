// The image panel: WebGL2 draws one value per pixel (a channel, or a post shader computed on the
// GPU: post_shaders.ts) through a colour map, with zoom and pan to exact pixels (texelFetch of
// whole pixels, no filtering).
import type { Frame, RGB } from './api';
import { valueFragmentShader } from './post_shaders';

const vertexShader = `#version 300 es
in vec2 aPos;
void main() { gl_Position = vec4(aPos, 0.0, 1.0); }
`;

// Colour of each canvas pixel: the image pixel under it (view transform), its value, the map.
// The colour map index is min(floor(256 t), 255) for t clamped to [0, 1], as render/colormap.cpp.
const displayFragmentShader = `#version 300 es
precision highp float;
precision highp int;
uniform highp sampler2D uValue;   // R32F values (value pass)
uniform highp sampler2D uRGB;     // RGB32F rendered colour (mode 3)
uniform highp sampler2D uMap;     // RGBA32F, 256 x 1 colour map, or 8 x 1 categories
uniform vec2 uOffset;             // canvas position (device pixels, top-left origin) of image pixel (0, 0)
uniform float uScale;             // device pixels per image pixel
uniform float uCanvasHeight;
uniform ivec2 uSize;
uniform int uMode;                // 0 colour map, 1 grey, 2 categories, 3 the rendered RGB
uniform float uLo, uHi;
uniform bool uLog;
out vec4 outColor;

bool isNaN(float v) { return (floatBitsToUint(v) & 0x7fffffffu) > 0x7f800000u; }

void main() {
  vec2 f = vec2(gl_FragCoord.x, uCanvasHeight - gl_FragCoord.y);
  ivec2 p = ivec2(floor((f - uOffset) / uScale));
  if (p.x < 0 || p.y < 0 || p.x >= uSize.x || p.y >= uSize.y) { outColor = vec4(0.2, 0.2, 0.2, 1.0); return; }
  if (uMode == 3) { outColor = vec4(clamp(texelFetch(uRGB, p, 0).rgb, 0.0, 1.0), 1.0); return; }
  float v = texelFetch(uValue, p, 0).r;
  if (isNaN(v) || isinf(v)) { outColor = vec4(0.0, 0.0, 0.0, 1.0); return; }
  if (uMode == 2) { outColor = vec4(texelFetch(uMap, ivec2(int(v) & 7, 0), 0).rgb, 1.0); return; }
  float t = uLog ? (v > 0.0 ? (log(v) - log(uLo)) / (log(uHi) - log(uLo)) : 0.0) : (v - uLo) / (uHi - uLo);
  t = clamp(t, 0.0, 1.0);
  if (uMode == 1) { outColor = vec4(t, t, t, 1.0); return; }
  outColor = vec4(texelFetch(uMap, ivec2(min(int(floor(256.0 * t)), 255), 0), 0).rgb, 1.0);
}
`;

function compile(gl: WebGL2RenderingContext, type: number, src: string): WebGLShader {
  const s = gl.createShader(type)!;
  gl.shaderSource(s, src);
  gl.compileShader(s);
  if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error('shader: ' + gl.getShaderInfoLog(s));
  return s;
}

function program(gl: WebGL2RenderingContext, fs: string): WebGLProgram {
  const p = gl.createProgram()!;
  gl.attachShader(p, compile(gl, gl.VERTEX_SHADER, vertexShader));
  gl.attachShader(p, compile(gl, gl.FRAGMENT_SHADER, fs));
  gl.bindAttribLocation(p, 0, 'aPos');
  gl.linkProgram(p);
  if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error('program: ' + gl.getProgramInfoLog(p));
  return p;
}

export interface DisplaySettings {
  mode: 'colormap' | 'grey' | 'categories' | 'rgb';
  map: RGB[];  // 256 entries, or the 8 categories
  lo: number;
  hi: number;
  log: boolean;
}

/** What the value pass computes: channel `a`, or disk-flux of channels a = x1, b = z. */
export interface ValueSource {
  mode: 0 | 1;
  a: string;
  b?: string;
  mass: number;
}

export class ImageView {
  readonly canvas: HTMLCanvasElement;
  private gl: WebGL2RenderingContext;
  private valueProg: WebGLProgram;
  private displayProg: WebGLProgram;
  private frame: Frame | null = null;
  private channelTex = new Map<string, WebGLTexture>();
  private rgbTex: WebGLTexture | null = null;
  private valueTex: WebGLTexture | null = null;
  private valueFbo: WebGLFramebuffer | null = null;
  private mapTex: WebGLTexture;
  /** The values of the last value pass, row 0 = top (read back from the GPU). */
  values: Float32Array = new Float32Array(0);
  settings: DisplaySettings = { mode: 'grey', map: [], lo: 0, hi: 1, log: false };
  /** Canvas position (CSS pixels) of image pixel (0, 0) and CSS pixels per image pixel. */
  offset = { x: 0, y: 0 };
  scale = 1;

  constructor(canvas: HTMLCanvasElement) {
    this.canvas = canvas;
    const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: true });
    if (!gl) throw new Error('this browser has no WebGL2');
    if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('WebGL2 without EXT_color_buffer_float (float render targets)');
    this.gl = gl;
    this.valueProg = program(gl, valueFragmentShader);
    this.displayProg = program(gl, displayFragmentShader);
    const buf = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, buf);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 3, -1, -1, 3]), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    this.mapTex = gl.createTexture()!;
    new ResizeObserver(() => this.draw()).observe(canvas);
  }

  private floatTexture(w: number, h: number, internal: number, format: number, data: Float32Array | null): WebGLTexture {
    const gl = this.gl;
    const t = gl.createTexture()!;
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.texImage2D(gl.TEXTURE_2D, 0, internal, w, h, 0, format, gl.FLOAT, data);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    return t;
  }

  setFrame(frame: Frame): void {
    const gl = this.gl;
    const sizeChanged = !this.frame || this.frame.width !== frame.width || this.frame.height !== frame.height;
    for (const t of this.channelTex.values()) gl.deleteTexture(t);
    this.channelTex.clear();
    if (this.rgbTex) gl.deleteTexture(this.rgbTex);
    this.rgbTex = null;
    this.frame = frame;
    if (sizeChanged) {
      if (this.valueTex) gl.deleteTexture(this.valueTex);
      if (this.valueFbo) gl.deleteFramebuffer(this.valueFbo);
      this.valueTex = this.floatTexture(frame.width, frame.height, gl.R32F, gl.RED, null);
      this.valueFbo = gl.createFramebuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, this.valueFbo);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.valueTex, 0);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      this.fit();
    }
  }

  /** One channel as a W x H texture (uploaded on first use). */
  private channel(name: string): WebGLTexture {
    const f = this.frame!;
    let t = this.channelTex.get(name);
    if (t) return t;
    const c = f.channels.indexOf(name);
    if (c < 0) throw new Error(`the data file has no channel "${name}"`);
    const n = f.width * f.height, nc = f.channels.length;
    const plane = new Float32Array(n);
    for (let i = 0; i < n; ++i) plane[i] = f.data[i * nc + c];
    t = this.floatTexture(f.width, f.height, this.gl.R32F, this.gl.RED, plane);
    this.channelTex.set(name, t);
    return t;
  }

  private rgb(): WebGLTexture {
    const f = this.frame!;
    if (this.rgbTex) return this.rgbTex;
    const n = f.width * f.height, nc = f.channels.length;
    const r = f.channels.indexOf('R'), g = f.channels.indexOf('G'), b = f.channels.indexOf('B');
    const plane = new Float32Array(n * 3);
    for (let i = 0; i < n; ++i) {
      plane[3 * i] = f.data[i * nc + r];
      plane[3 * i + 1] = f.data[i * nc + g];
      plane[3 * i + 2] = f.data[i * nc + b];
    }
    this.rgbTex = this.floatTexture(f.width, f.height, this.gl.RGB32F, this.gl.RGB, plane);
    return this.rgbTex;
  }

  /** Runs the value pass on the GPU and reads the values back (this.values). */
  computeValues(src: ValueSource): Float32Array {
    const gl = this.gl, f = this.frame!;
    gl.useProgram(this.valueProg);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.channel(src.a));
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, src.b ? this.channel(src.b) : this.channel(src.a));
    gl.uniform1i(gl.getUniformLocation(this.valueProg, 'uA'), 0);
    gl.uniform1i(gl.getUniformLocation(this.valueProg, 'uB'), 1);
    gl.uniform1i(gl.getUniformLocation(this.valueProg, 'uMode'), src.mode);
    gl.uniform1f(gl.getUniformLocation(this.valueProg, 'uMass'), src.mass);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.valueFbo);
    gl.viewport(0, 0, f.width, f.height);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    // Framebuffer row y holds image row y (gl_FragCoord.y = y + 0.5): read back row 0 = top.
    const rgba = new Float32Array(f.width * f.height * 4);
    gl.readPixels(0, 0, f.width, f.height, gl.RGBA, gl.FLOAT, rgba);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    this.values = new Float32Array(f.width * f.height);
    for (let i = 0; i < this.values.length; ++i) this.values[i] = rgba[4 * i];
    return this.values;
  }

  setDisplay(s: DisplaySettings): void {
    this.settings = s;
    const gl = this.gl;
    const table = new Float32Array(s.map.length * 4);
    s.map.forEach((c, i) => table.set([c[0], c[1], c[2], 1], 4 * i));
    gl.bindTexture(gl.TEXTURE_2D, this.mapTex);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, Math.max(1, s.map.length), 1, 0, gl.RGBA, gl.FLOAT,
                  s.map.length ? table : new Float32Array(4));
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    this.draw();
  }

  /** Whole image in view, integer or 1/integer screen pixels per image pixel where possible. */
  fit(): void {
    if (!this.frame) return;
    const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
    let s = Math.min(w / this.frame.width, h / this.frame.height);
    if (s >= 1) s = Math.floor(s);
    this.scale = s > 0 ? s : 1;
    this.offset = { x: Math.round((w - this.frame.width * this.scale) / 2), y: Math.round((h - this.frame.height * this.scale) / 2) };
    this.draw();
  }

  /** Zoom by `factor` keeping the image point under canvas position (cx, cy) in place. */
  zoom(factor: number, cx: number, cy: number): void {
    const s = Math.min(256, Math.max(1 / 16, this.scale * factor));
    this.offset = { x: cx - ((cx - this.offset.x) * s) / this.scale, y: cy - ((cy - this.offset.y) * s) / this.scale };
    this.scale = s;
    this.draw();
  }

  pan(dx: number, dy: number): void {
    this.offset = { x: this.offset.x + dx, y: this.offset.y + dy };
    this.draw();
  }

  /** The image pixel under canvas position (CSS pixels), or null. */
  pixelAt(cx: number, cy: number): [number, number] | null {
    if (!this.frame) return null;
    const x = Math.floor((cx - this.offset.x) / this.scale), y = Math.floor((cy - this.offset.y) / this.scale);
    return x >= 0 && y >= 0 && x < this.frame.width && y < this.frame.height ? [x, y] : null;
  }

  /** Canvas position (CSS pixels) of the centre of image pixel (x, y). */
  pixelCentre(x: number, y: number): [number, number] {
    return [this.offset.x + (x + 0.5) * this.scale, this.offset.y + (y + 0.5) * this.scale];
  }

  draw(): void {
    const gl = this.gl, f = this.frame;
    const dpr = window.devicePixelRatio || 1;
    const w = Math.max(1, Math.round(this.canvas.clientWidth * dpr)), h = Math.max(1, Math.round(this.canvas.clientHeight * dpr));
    if (this.canvas.width !== w || this.canvas.height !== h) {
      this.canvas.width = w;
      this.canvas.height = h;
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, w, h);
    gl.clearColor(0.2, 0.2, 0.2, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    if (!f || !this.valueTex) return;
    const s = this.settings, p = this.displayProg;
    gl.useProgram(p);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.valueTex);
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, this.mapTex);
    gl.activeTexture(gl.TEXTURE2);
    gl.bindTexture(gl.TEXTURE_2D, s.mode === 'rgb' ? this.rgb() : this.valueTex);
    gl.uniform1i(gl.getUniformLocation(p, 'uValue'), 0);
    gl.uniform1i(gl.getUniformLocation(p, 'uMap'), 1);
    gl.uniform1i(gl.getUniformLocation(p, 'uRGB'), 2);
    gl.uniform2f(gl.getUniformLocation(p, 'uOffset'), this.offset.x * dpr, this.offset.y * dpr);
    gl.uniform1f(gl.getUniformLocation(p, 'uScale'), this.scale * dpr);
    gl.uniform1f(gl.getUniformLocation(p, 'uCanvasHeight'), h);
    gl.uniform2i(gl.getUniformLocation(p, 'uSize'), f.width, f.height);
    const mode = { colormap: 0, grey: 1, categories: 2, rgb: 3 }[s.mode];
    gl.uniform1i(gl.getUniformLocation(p, 'uMode'), mode);
    gl.uniform1f(gl.getUniformLocation(p, 'uLo'), s.lo);
    gl.uniform1f(gl.getUniformLocation(p, 'uHi'), s.hi);
    gl.uniform1i(gl.getUniformLocation(p, 'uLog'), s.log ? 1 : 0);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }
}
