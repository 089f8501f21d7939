// The light ray of a pixel in 3D (three.js): the ray's points in the metric's pseudo-Cartesian
// coordinates (paper §2.3), the horizon or throat, the objects' bounding boxes, the observer.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { Ray } from './api';

export class RayView {
  private renderer: THREE.WebGLRenderer;
  private scene = new THREE.Scene();
  private camera = new THREE.PerspectiveCamera(45, 1, 0.01, 1e7);
  private controls: OrbitControls;
  private content = new THREE.Group();
  /** Number of line vertices drawn for the last ray (tests read it). */
  drawnPoints = 0;

  constructor(private host: HTMLElement) {
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    host.appendChild(this.renderer.domElement);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.render());
    this.scene.add(this.content);
    this.scene.add(new THREE.AmbientLight(0xffffff, 0.6));
    const sun = new THREE.DirectionalLight(0xffffff, 0.8);
    sun.position.set(1, -2, 3);
    this.scene.add(sun);
    new ResizeObserver(() => this.resize()).observe(host);
    this.resize();
  }

  private resize(): void {
    const w = this.host.clientWidth, h = this.host.clientHeight;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / Math.max(1, h);
    this.camera.updateProjectionMatrix();
    this.render();
  }

  render(): void {
    this.renderer.render(this.scene, this.camera);
  }

  show(ray: Ray): void {
    this.content.clear();
    const box = new THREE.Box3();
    const obs = new THREE.Vector3(...ray.observer.p);
    box.expandByPoint(obs);
    const pts = (ray.points ?? []).map((p) => new THREE.Vector3(...p.p));
    // Colour along the ray: the chart (wormhole sides) picks the hue, brightness fades with lambda.
    if (pts.length > 1) {
      const geom = new THREE.BufferGeometry().setFromPoints(pts);
      const colors = new Float32Array(pts.length * 3);
      (ray.points ?? []).forEach((p, i) => {
        const c = p.chart === 0 ? new THREE.Color(1.0, 0.85, 0.2) : new THREE.Color(0.3, 0.8, 1.0);
        colors.set([c.r, c.g, c.b], 3 * i);
      });
      geom.setAttribute('color', new THREE.BufferAttribute(colors, 3));
      this.content.add(new THREE.Line(geom, new THREE.LineBasicMaterial({ vertexColors: true })));
      const dots = new THREE.Points(geom, new THREE.PointsMaterial({ size: 3, sizeAttenuation: false, vertexColors: true }));
      this.content.add(dots);
      for (const p of pts) box.expandByPoint(p);
    }
    this.drawnPoints = pts.length;
    const size = box.getSize(new THREE.Vector3()).length() || 1;
    const marker = (pos: THREE.Vector3, color: number) => {
      const m = new THREE.Mesh(new THREE.SphereGeometry(size * 0.012, 12, 8), new THREE.MeshBasicMaterial({ color }));
      m.position.copy(pos);
      this.content.add(m);
    };
    marker(obs, 0x66ff66);
    if (ray.hit && pts.length) marker(pts[pts.length - 1], 0xff5555);
    if (ray.surface) {
      const r = Math.max(ray.surface.radius, size * 0.01);
      const s = new THREE.Mesh(new THREE.SphereGeometry(r, 48, 24),
        new THREE.MeshPhongMaterial({ color: ray.surface.kind === 'horizon' ? 0x202020 : 0x6060a0, transparent: true, opacity: 0.85 }));
      s.rotation.x = Math.PI / 2;
      this.content.add(s);
      this.content.add(new THREE.LineSegments(new THREE.WireframeGeometry(new THREE.SphereGeometry(r, 16, 8)),
        new THREE.LineBasicMaterial({ color: 0x888888 })));
      box.expandByPoint(new THREE.Vector3(r, r, r)).expandByPoint(new THREE.Vector3(-r, -r, -r));
    }
    for (const o of ray.objects) {
      const b = new THREE.Box3(new THREE.Vector3(...o.lo), new THREE.Vector3(...o.hi));
      this.content.add(new THREE.Box3Helper(b, new THREE.Color(0x5fa8ff)));
      box.union(b);
    }
    this.content.add(new THREE.AxesHelper(size * 0.15));
    // Look at everything from the side of the ray (perpendicular to observer -> end), a bit above.
    const centre = box.getCenter(new THREE.Vector3());
    const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-6);
    const along = (pts.length ? pts[pts.length - 1] : centre).clone().sub(obs);
    const up = new THREE.Vector3(0, 0, 1);
    const dir = along.clone().cross(up);
    if (dir.lengthSq() < 1e-12 * Math.max(1, along.lengthSq())) dir.set(1, -1, 0);
    dir.normalize().addScaledVector(up, 0.7).normalize();
    this.camera.position.copy(centre).addScaledVector(dir, radius * 2.6);
    this.camera.near = radius * 1e-3;
    this.camera.far = radius * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(centre);
    this.controls.update();
    this.render();
  }
}
