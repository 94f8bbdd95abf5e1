// The flight viewer: one flight's scene in 3-D (three.js) with orbit/zoom/pan, a
// timeline (play/pause, scrub, playback speed), camera presets and linked plots.
// Hooks for tests and scripts (docs/studio.md): ready, duration, time, seek(t),
// birdScreenPosition(), cameraMatrices(), play(), pause().
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import "uplot/dist/uPlot.min.css";
import "./viewer.css";
import { buildBodies, buildPaths, buildWorld, pointAt, poseBodies, trackPosition } from "./bird3d.js";
import { buildPlots } from "./plots.js";

export const CAMERAS = ["follow", "side", "chase", "top", "overview"];

function el(tag, attrs = {}, parent = null, text = "") {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text) e.textContent = text;
  if (parent) parent.appendChild(e);
  return e;
}

function speedChoices(tb) {
  const real = tb.label === "real time";
  const list = real
    ? [["1", "real time"], ["0.5", "1/2 slow motion"], ["0.25", "1/4"], ["0.125", "1/8"], ["0.0625", "1/16"]]
    : [["1", `1x (${tb.label})`], ["0.5", "0.5x"], ["0.25", "0.25x"], ["2", "2x"], ["4", "4x"]];
  return list;
}

export class Viewer {
  constructor(root, data, { width = 640, height = 400, title = null } = {}) {
    this.data = data;
    this.duration = data.duration;
    this.time = 0;
    this.speed = 1;
    this.playing = false;
    this.ready = false;
    this.cameraName = "follow";
    this.root = el("div", { class: "bv" }, root);
    const s = data;
    el(
      "div",
      { class: "bv-title" },
      this.root,
      title ||
        `${s.title}: bird ${s.bird}, model ${s.model}, ${s.open_loop ? "open" : "closed"} loop, ` +
          `${s.duration.toFixed(2)} ${s.units.time}`,
    );
    const main = el("div", { class: "bv-main" }, this.root);
    const wrap = el("div", { class: "bv-canvas" }, main);
    this.canvas = el("canvas", { width, height }, wrap);
    this.canvas.style.width = `${width}px`;
    this.canvas.style.height = `${height}px`;
    this.width = width;
    this.height = height;
    this._controls(el("div", { class: "bv-controls" }, this.root));
    this.plotBox = el("div", { class: "bv-plots" }, main);

    this.renderer = new THREE.WebGLRenderer({ canvas: this.canvas, antialias: false, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2)); // no MSAA: software GL
    this.renderer.setSize(width, height, false);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(45, width / height, 0.05, 2000);
    this.camera.up.set(0, 0, 1); // MuJoCo world: z up
    buildWorld(this.scene, data);
    this.bodies = buildBodies(this.scene, data);
    buildPaths(this.scene, data);
    this.torso = Object.values(this.bodies).find((b) => b.group.name === "torso")?.group;
    this.orbit = new OrbitControls(this.camera, this.canvas);
    this.orbit.addEventListener("change", () => this._render());
    this._bird = new THREE.Vector3();
    this.setCamera("follow");
    this.plots = buildPlots(this.plotBox, data, this);
    this.seek(0);
    this.ready = true;
  }

  _controls(bar) {
    this.playButton = el("button", { class: "bv-play", type: "button" }, bar, "play");
    this.playButton.addEventListener("click", () => (this.playing ? this.pause() : this.play()));
    this.slider = el("input", { class: "bv-scrub", type: "range", min: 0, max: 1000, value: 0 }, bar);
    this.slider.addEventListener("input", () => this.seek((this.slider.value / 1000) * this.duration));
    this.clock = el("span", { class: "bv-clock" }, bar);
    const speed = el("select", { class: "bv-speed", title: "playback speed" }, bar);
    for (const [v, label] of speedChoices(this.data.time_base)) el("option", { value: v }, speed, label);
    speed.addEventListener("change", () => (this.speed = Number(speed.value)));
    const cam = el("select", { class: "bv-camera", title: "camera" }, bar);
    for (const c of CAMERAS) el("option", { value: c }, cam, `camera: ${c}`);
    cam.addEventListener("change", () => this.setCamera(cam.value));
    this.cameraSelect = cam;
  }

  _index(t) {
    const n = this.data.t.length;
    const u = (Math.min(Math.max(t, 0), this.duration) / this.duration) * (n - 1);
    const f = Math.min(Math.floor(u), n - 2);
    return [f, u - f];
  }

  // Bird position at time t from the log's track (scene units).
  birdAt(t, out = new THREE.Vector3()) {
    const [f, w] = this._index(t);
    return trackPosition(this.data, f, w, out);
  }

  // What the cameras aim at: the bird, or a flock's centre (scene.flock, birdsim view).
  aimAt(t, out = new THREE.Vector3()) {
    if (!this.data.flock) return this.birdAt(t, out);
    const [f, w] = this._index(t);
    return pointAt(this.data.flock.centre, f, w, out);
  }

  setCamera(name) {
    if (!CAMERAS.includes(name)) throw new Error(`camera ${name} is unknown; allowed: ${CAMERAS.join(", ")}`);
    this.cameraName = name;
    if (this.cameraSelect) this.cameraSelect.value = name;
    const b = this.aimAt(this.time);
    const flock = this.data.flock;
    const D = flock ? flock.camera_distance : 4.5; // a flock: its diameter fills the view
    const offsets = {
      follow: [-0.45 * D, -D, 0.3 * D],
      side: [0, -D, 0.05 * D],
      chase: [-D, -0.05 * D, 0.3 * D],
      top: [0, -0.01, 1.3 * D],
    };
    if (name === "overview") {
      const box = new THREE.Box3().setFromArray(flock ? flock.centre : this.data.track.pos);
      if (flock) box.expandByScalar(flock.radius);
      box.expandByPoint(new THREE.Vector3(box.min.x, box.min.y, 0));
      const c = box.getCenter(new THREE.Vector3());
      const r = Math.max(4, box.getSize(new THREE.Vector3()).length() / 2);
      this.orbit.target.copy(c);
      this.camera.position.set(c.x - 0.3 * r, c.y - 2.4 * r, c.z + 0.8 * r);
    } else {
      const o = offsets[name];
      this.orbit.target.copy(b);
      this.camera.position.set(b.x + o[0], b.y + o[1], b.z + o[2]);
    }
    this.orbit.update();
    this._render();
  }

  _follow() {
    if (this.cameraName === "overview") return;
    const b = this.aimAt(this.time, this._bird);
    const offset = this.camera.position.clone().sub(this.orbit.target);
    this.orbit.target.copy(b);
    this.camera.position.copy(b).add(offset);
    this.camera.updateMatrixWorld();
  }

  _render() {
    this.renderer.render(this.scene, this.camera);
  }

  // Draw the flight at time t (seconds of the log's time unit from the start).
  seek(t) {
    this.time = Math.min(Math.max(Number(t) || 0, 0), this.duration);
    const [f, w] = this._index(this.time);
    poseBodies(this.bodies, f, w);
    this._follow();
    this.orbit.update();
    this._render();
    this.slider.value = String(Math.round((this.time / this.duration) * 1000));
    const tb = this.data.time_base;
    this.clock.textContent = `t = ${this.time.toFixed(2)} ${this.data.units.time} (${(this.time / tb.period).toFixed(2)} wingbeats)`;
    this.plots?.redraw();
    return this.time;
  }

  play() {
    if (this.playing) return;
    if (this.time >= this.duration) this.seek(0);
    this.playing = true;
    this.playButton.textContent = "pause";
    let last = performance.now();
    const step = (now) => {
      if (!this.playing) return;
      const dt = ((now - last) / 1000) * this.speed * this.data.time_base.log_time_per_second;
      last = now;
      this.seek(this.time + dt);
      if (this.time >= this.duration) return this.pause();
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  }

  pause() {
    this.playing = false;
    this.playButton.textContent = "play";
  }

  // Pixel position (x right, y down, CSS pixels of the canvas) of a scene point.
  project(p) {
    this.camera.updateMatrixWorld();
    const v = new THREE.Vector3(p[0], p[1], p[2]).project(this.camera);
    return { x: ((v.x + 1) / 2) * this.width, y: ((1 - v.y) / 2) * this.height };
  }

  // Pixel position of the bird's body (the torso as drawn, i.e. the replayed MJCF).
  birdScreenPosition() {
    const p = this.torso ? this.torso.position : this.birdAt(this.time);
    return this.project([p.x, p.y, p.z]);
  }

  // The camera as matrices (column-major, three.js order) and the canvas size.
  cameraMatrices() {
    this.camera.updateMatrixWorld();
    return {
      view: Array.from(this.camera.matrixWorldInverse.elements),
      projection: Array.from(this.camera.projectionMatrix.elements),
      width: this.width,
      height: this.height,
    };
  }

  dispose() {
    this.pause();
    this.orbit.dispose();
    this.renderer.dispose();
    this.root.remove();
  }
}

// Register a viewer as the page's window.birdsimViewer (the latest) and in the list.
export function publish(viewer) {
  window.birdsimViewers = window.birdsimViewers || [];
  window.birdsimViewers.push(viewer);
  window.birdsimViewer = viewer;
  return viewer;
}
