// The flight's 3-D objects from the scene JSON (birdsim/studio/scene.py): every geom of
// the MuJoCo model drawn at its body's pose, the world, the reference path, the trail.
// Scene units: MuJoCo world (semispans, x forward, y left, z up).
import * as THREE from "three";

function material(rgba, opts = {}) {
  // Lambert, not the physically based material: software WebGL (SwiftShader) draws it
  // several times faster, and matte plumage needs no more
  return new THREE.MeshLambertMaterial({
    color: new THREE.Color(rgba[0], rgba[1], rgba[2]),
    transparent: rgba[3] < 1,
    opacity: rgba[3],
    side: THREE.DoubleSide,
    ...opts,
  });
}

function meshGeometry(mesh) {
  const g = new THREE.BufferGeometry();
  g.setAttribute("position", new THREE.Float32BufferAttribute(mesh.vert, 3));
  g.setIndex(mesh.face);
  const flat = g.toNonIndexed();
  flat.computeVertexNormals();
  return flat;
}

// A three.js object for one MuJoCo geom, in its body's frame.
function geomObject(geom, meshes) {
  const s = geom.size;
  let g;
  const zAxis = new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(1, 0, 0), Math.PI / 2);
  switch (geom.type) {
    case "sphere":
      g = new THREE.SphereGeometry(s[0], 20, 14);
      break;
    case "ellipsoid":
      g = new THREE.SphereGeometry(1, 24, 16);
      g.scale(s[0], s[1], s[2]);
      break;
    case "box":
      g = new THREE.BoxGeometry(2 * s[0], 2 * s[1], 2 * s[2]);
      break;
    case "cylinder":
      g = new THREE.CylinderGeometry(s[0], s[0], 2 * s[1], 20);
      g.applyQuaternion(zAxis); // three.js cylinders run along y, MuJoCo's along z
      break;
    case "capsule":
      g = new THREE.CapsuleGeometry(s[0], 2 * s[1], 6, 16);
      g.applyQuaternion(zAxis);
      break;
    case "plane":
      return null; // the floor is drawn by the world
    case "mesh":
      g = meshGeometry(meshes[String(geom.mesh)]);
      break;
    default:
      return null;
  }
  const obj = new THREE.Mesh(g, material(geom.rgba));
  obj.position.set(geom.pos[0], geom.pos[1], geom.pos[2]);
  const q = geom.quat; // MuJoCo (w, x, y, z)
  obj.quaternion.set(q[1], q[2], q[3], q[0]);
  return obj;
}

function line(points, color, opacity = 1) {
  const g = new THREE.BufferGeometry();
  g.setAttribute("position", new THREE.Float32BufferAttribute(points, 3));
  const m = new THREE.LineBasicMaterial({ color, transparent: opacity < 1, opacity });
  return new THREE.Line(g, m);
}

function floorColour(data) {
  const plane = data.geoms.find((g) => g.type === "plane");
  return plane ? new THREE.Color(plane.rgba[0], plane.rgba[1], plane.rgba[2]) : new THREE.Color(0x8fa878);
}

// The world: sky, lights, a floor with a grid (1 semispan squares), the arena's geoms.
export function buildWorld(scene, data) {
  scene.background = new THREE.Color(0xbfd8ee);
  scene.fog = new THREE.Fog(0xbfd8ee, 25, 90); // the far floor fades (no grid moire at the horizon)
  scene.add(new THREE.HemisphereLight(0xffffff, 0x667755, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(-3, -5, 10);
  scene.add(sun);
  const pos = data.track.pos;
  let xmin = Infinity;
  let xmax = -Infinity;
  for (let i = 0; i < pos.length; i += 3) {
    xmin = Math.min(xmin, pos[i]);
    xmax = Math.max(xmax, pos[i]);
  }
  const size = Math.max(40, Math.ceil((xmax - xmin + 30) / 10) * 10);
  const floor = new THREE.Mesh(
    new THREE.PlaneGeometry(size, size),
    new THREE.MeshLambertMaterial({ color: floorColour(data) }),
  );
  floor.position.set((xmin + xmax) / 2, 0, -0.001);
  scene.add(floor);
  const grid = new THREE.GridHelper(size, size / 2, 0x6f8460, 0x7f9670); // 2-semispan squares
  grid.rotation.x = Math.PI / 2; // GridHelper lies in x-z; our floor is x-y
  grid.position.set(floor.position.x, 0, 0.003);
  scene.add(grid);
}

// The bodies (THREE.Group per MuJoCo body) carrying every drawn geom.
export function buildBodies(scene, data) {
  const bodies = {};
  for (const [id, b] of Object.entries(data.bodies)) {
    const group = new THREE.Group();
    group.name = b.name;
    scene.add(group);
    bodies[id] = { group, pose: b };
  }
  for (const geom of data.geoms) {
    const obj = geomObject(geom, data.meshes);
    if (obj) bodies[String(geom.body)].group.add(obj);
  }
  return bodies;
}

// The reference path (orange) and the flown track (blue, thin).
export function buildPaths(scene, data) {
  scene.add(line(data.reference, 0xff8c1a));
  scene.add(line(data.track.pos, 0x1f4fbf, 0.55));
}

const qa = new THREE.Quaternion();
const qb = new THREE.Quaternion();

// Place every moving body at time index f + w (linear in position, slerp in attitude).
export function poseBodies(bodies, f, w) {
  for (const { group, pose } of Object.values(bodies)) {
    const n = pose.frames;
    const i = Math.min(f, n - 1);
    const j = Math.min(f + 1, n - 1);
    const p = pose.pos;
    const q = pose.quat;
    group.position.set(
      p[3 * i] * (1 - w) + p[3 * j] * w,
      p[3 * i + 1] * (1 - w) + p[3 * j + 1] * w,
      p[3 * i + 2] * (1 - w) + p[3 * j + 2] * w,
    );
    qa.set(q[4 * i + 1], q[4 * i + 2], q[4 * i + 3], q[4 * i]);
    qb.set(q[4 * j + 1], q[4 * j + 2], q[4 * j + 3], q[4 * j]);
    group.quaternion.slerpQuaternions(qa, qb, w);
  }
}

// The torso's position from the log's own track at time index f + w (scene units).
export function trackPosition(data, f, w, out) {
  return pointAt(data.track.pos, f, w, out);
}

// A point of a per-frame list of points (flat x, y, z) at time index f + w.
export function pointAt(p, f, w, out) {
  const n = p.length / 3;
  const i = Math.min(f, n - 1);
  const j = Math.min(f + 1, n - 1);
  return out.set(
    p[3 * i] * (1 - w) + p[3 * j] * w,
    p[3 * i + 1] * (1 - w) + p[3 * j + 1] * w,
    p[3 * i + 2] * (1 - w) + p[3 * j + 2] * w,
  );
}
