// The server's routes (src/cli/view_server.h).

export type RGB = [number, number, number];

export interface Info {
  frames: { index: number; name: string }[];
  colormaps: Record<string, RGB[]>;
  categories: RGB[];
  stop_names: string[];
}

export interface PostShaderInfo {
  name: string;
  available: boolean;
  label?: string;
  colormap?: string;
  categorical?: boolean;
  why?: string;
}

export interface FrameInfo {
  width: number;
  height: number;
  channels: string[];
  metadata: Record<string, string>;
  shaders: PostShaderInfo[];
}

export interface Frame extends FrameInfo {
  index: number;
  /** width*height*channels.length, row 0 = top, interleaved */
  data: Float32Array;
}

export interface RayPoint {
  lambda: number;
  x: number[];
  k: number[];
  p: [number, number, number];
  chart: number;
}

export interface Ray {
  frame: number;
  pixel: [number, number];
  traced: boolean;
  metric: string;
  coords: string[];
  params: Record<string, number>;
  observer: { x: number[]; p: [number, number, number] };
  surface: { kind: string; radius: number; formula: string } | null;
  objects: { id: string; chart: number; lo: [number, number, number]; hi: [number, number, number] }[];
  points?: RayPoint[];
  stop?: string;
  hit?: boolean;
  object_id?: number;
  lambda?: number;
  geodesic?: { command: string; differences: string[]; note: string };
  stored?: Record<string, number | null>;
  error?: string;
}

async function json<T>(url: string): Promise<T> {
  const r = await fetch(url);
  const body = await r.json();
  if (!r.ok) throw new Error(body.error ?? `${url}: HTTP ${r.status}`);
  return body as T;
}

export const fetchInfo = () => json<Info>('/api/info');

export async function fetchFrame(index: number): Promise<Frame> {
  const info = await json<FrameInfo>(`/api/frame/${index}`);
  const r = await fetch(`/api/frame/${index}/data`);
  if (!r.ok) throw new Error((await r.json()).error ?? `frame ${index}: HTTP ${r.status}`);
  const data = new Float32Array(await r.arrayBuffer());
  return { ...info, index, data };
}

/** The values of `geovis post --shader NAME` computed by the server (for comparison with the GPU). */
export async function fetchPostValues(frame: number, shader: string, mass?: number): Promise<Float32Array> {
  const m = mass !== undefined ? `&mass=${mass}` : '';
  const r = await fetch(`/api/post?frame=${frame}&shader=${encodeURIComponent(shader)}${m}`);
  if (!r.ok) throw new Error((await r.json()).error ?? `post: HTTP ${r.status}`);
  return new Float32Array(await r.arrayBuffer());
}

export const fetchRay = (frame: number, x: number, y: number) => json<Ray>(`/api/ray?frame=${frame}&x=${x}&y=${y}`);
