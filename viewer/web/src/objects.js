// Three.js objects for relpos's objects: features (docs/spec.md §1: point, line, plane,
// cylinder) drawn at a size fitted to the problem, and triangle meshes.
import * as THREE from 'three';

export const colours = {
  fixed: 0x2f6fd6,
  mobile: 0xe07b19,
  obstacle: 0x8a8f98,
  ghost: 0xe07b19,
  free: 0x2faa4f,
  collides: 0xd23a3a,
};

function material(colour, opacity) {
  return new THREE.MeshStandardMaterial({
    color: colour,
    roughness: 0.6,
    metalness: 0.05,
    transparent: opacity < 1,
    opacity,
    side: THREE.DoubleSide,
    depthWrite: opacity >= 1,
  });
}

// Turns an object whose own axis is `from` so that it runs along `to`.
function along(object, from, to) {
  object.quaternion.setFromUnitVectors(from, new THREE.Vector3().fromArray(to).normalize());
}

// One feature in its object's frame. `size`: the problem's length scale.
function feature(f, colour, opacity, size) {
  const group = new THREE.Group();
  group.name = f.name;
  const p = new THREE.Vector3().fromArray(f.point);
  const thin = 0.006 * size;
  if (f.kind === 'point') {
    const ball = new THREE.Mesh(new THREE.SphereGeometry(0.03 * size, 16, 12), material(colour, opacity));
    ball.position.copy(p);
    group.add(ball);
  } else if (f.kind === 'line') {
    const rod = new THREE.Mesh(new THREE.CylinderGeometry(thin, thin, 2.4 * size, 8), material(colour, opacity));
    rod.position.copy(p);
    along(rod, new THREE.Vector3(0, 1, 0), f.direction);
    group.add(rod);
  } else if (f.kind === 'plane') {
    const sheet = new THREE.Mesh(new THREE.PlaneGeometry(1.6 * size, 1.6 * size), material(colour, 0.35 * opacity));
    sheet.position.copy(p);
    along(sheet, new THREE.Vector3(0, 0, 1), f.direction);
    group.add(sheet);
    const normal = new THREE.ArrowHelper(new THREE.Vector3().fromArray(f.direction).normalize(), p, 0.4 * size, colour);
    group.add(normal);
  } else if (f.kind === 'cylinder') {
    const shell = new THREE.Mesh(new THREE.CylinderGeometry(f.radius, f.radius, 1.6 * size, 40, 1, true), material(colour, 0.4 * opacity));
    shell.position.copy(p);
    along(shell, new THREE.Vector3(0, 1, 0), f.direction);
    group.add(shell);
    const axis = new THREE.Mesh(new THREE.CylinderGeometry(thin, thin, 2.0 * size, 8), material(colour, opacity));
    axis.position.copy(p);
    along(axis, new THREE.Vector3(0, 1, 0), f.direction);
    group.add(axis);
  }
  return group;
}

// One geometry per mesh, shared by every copy of its object (the mobile object at each branch's
// pose and at every sample).
const geometries = new WeakMap();

function mesh(m, colour, opacity) {
  let geometry = geometries.get(m);
  if (!geometry) {
    geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(m.positions, 3));
    geometry.setIndex(m.indices);
    geometry.computeVertexNormals();
    geometries.set(m, geometry);
  }
  return new THREE.Mesh(geometry, material(colour, opacity));
}

// The farthest vertex of a mesh from its object's origin.
function meshExtent(m) {
  if (m.extent === undefined) {
    let r2 = 0;
    for (let k = 0; k + 2 < m.positions.length; k += 3) {
      r2 = Math.max(r2, m.positions[k] ** 2 + m.positions[k + 1] ** 2 + m.positions[k + 2] ** 2);
    }
    m.extent = Math.sqrt(r2);
  }
  return m.extent;
}

// An object's features and mesh as one group in the object's frame; its matrix is the pose. An
// object with a mesh has its features drawn to the mesh's size (a gripper's planes as large as
// the gripper, not as the scene).
export function objectGroup(object, colour, opacity, size, withFeatures = true) {
  const group = new THREE.Group();
  group.name = object.name;
  group.matrixAutoUpdate = false;
  const own = object.mesh && meshExtent(object.mesh) > 0 ? Math.min(size, meshExtent(object.mesh)) : size;
  if (withFeatures) for (const f of object.features || []) group.add(feature(f, colour, opacity, own));
  if (object.mesh) {
    const body = mesh(object.mesh, colour, opacity);
    body.userData.isMesh = true;
    group.add(body);
  }
  return group;
}

// Sets every material of a group to a colour and opacity (a branch chosen, a ghost); `meshOnly`:
// the mesh's alone (a collision is the mesh's).
export function paint(group, colour, opacity, meshOnly = false) {
  group.traverse((o) => {
    if (!o.material || (meshOnly && !o.userData.isMesh)) return;
    if (colour !== null && o.material.color && !o.userData.keepColour) o.material.color.setHex(colour);
    o.material.opacity = opacity;
    o.material.transparent = opacity < 1;
    o.material.depthWrite = opacity >= 1;
  });
}

// Places a group at pose X (a Matrix4). Its matrix is set by hand (matrixAutoUpdate off), so
// three.js must be told to recompute its world matrix.
export function setPose(group, X) {
  group.matrix.copy(X);
  group.matrixWorldNeedsUpdate = true;
}
