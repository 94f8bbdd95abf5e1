// Keyframe handles in the 3-D view: spheres at the path's keyframes, dragged in the
// vertical plane of the flight (y = 0); a keyframe of the speed form (V, z) moves in z only.
import * as THREE from "three";

export class Handles {
  constructor(viewer, onMove) {
    this.viewer = viewer;
    this.onMove = onMove;
    this.group = new THREE.Group();
    viewer.scene.add(this.group);
    this.items = [];
    this.ray = new THREE.Raycaster();
    this.plane = new THREE.Plane(new THREE.Vector3(0, 1, 0), 0);
    this.drag = null;
    const c = viewer.canvas;
    c.addEventListener("pointerdown", (e) => this._down(e));
    c.addEventListener("pointermove", (e) => this._move(e));
    c.addEventListener("pointerup", (e) => this._up(e));
  }

  // points: [{index, x, z, xFree}] in scene units (semispans).
  set(points) {
    for (const m of this.items) this.group.remove(m);
    this.items = points.map((p) => {
      const m = new THREE.Mesh(
        new THREE.SphereGeometry(0.18, 16, 12),
        new THREE.MeshLambertMaterial({ color: p.xFree ? 0xe0218a : 0x8a21e0 }),
      );
      m.position.set(p.x, 0, p.z);
      m.userData = p;
      this.group.add(m);
      return m;
    });
    this.viewer._render();
  }

  _pointer(e) {
    const r = this.viewer.canvas.getBoundingClientRect();
    return new THREE.Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
  }

  _down(e) {
    this.ray.setFromCamera(this._pointer(e), this.viewer.camera);
    const hit = this.ray.intersectObjects(this.items)[0];
    if (!hit) return;
    this.drag = hit.object;
    this.viewer.orbit.enabled = false;
    this.viewer.canvas.setPointerCapture(e.pointerId);
  }

  _move(e) {
    if (!this.drag) return;
    this.ray.setFromCamera(this._pointer(e), this.viewer.camera);
    const p = new THREE.Vector3();
    if (!this.ray.ray.intersectPlane(this.plane, p)) return;
    if (this.drag.userData.xFree) this.drag.position.x = p.x;
    this.drag.position.z = Math.max(0, p.z);
    this.viewer._render();
  }

  _up() {
    if (!this.drag) return;
    const d = this.drag;
    this.drag = null;
    this.viewer.orbit.enabled = true;
    this.onMove(d.userData.index, d.position.x, d.position.z);
  }
}
