/**
 * Keyboard camera moves (the trackball only follows the pointer): each
 * moves `camera` (and, for a pan, `target`) in place; the view then looks
 * at the target again.
 */
import { type PerspectiveCamera, Quaternion, Vector3 } from 'three';

/** Turns the camera about `target` by `yawDeg` around its up axis and `pitchDeg` around its right axis. */
export function orbitCamera(camera: PerspectiveCamera, target: Vector3, yawDeg: number, pitchDeg: number): void {
  const eye = new Vector3().subVectors(camera.position, target);
  const right = new Vector3().crossVectors(camera.up, eye).normalize();
  const yaw = new Quaternion().setFromAxisAngle(camera.up, (yawDeg * Math.PI) / 180);
  const pitch = new Quaternion().setFromAxisAngle(right, (pitchDeg * Math.PI) / 180);
  const turn = yaw.multiply(pitch);
  eye.applyQuaternion(turn);
  camera.up.applyQuaternion(turn);
  camera.position.copy(target).add(eye);
}

/** Moves the camera towards `target` (factor < 1) or away from it (factor > 1). */
export function zoomCamera(camera: PerspectiveCamera, target: Vector3, factor: number): void {
  const eye = new Vector3().subVectors(camera.position, target).multiplyScalar(factor);
  camera.position.copy(target).add(eye);
}

/** Slides camera and `target` sideways by fractions of the view's height. */
export function panCamera(camera: PerspectiveCamera, target: Vector3, dx: number, dy: number): void {
  const distance = camera.position.distanceTo(target);
  const height = 2 * distance * Math.tan(((camera.fov / 2) * Math.PI) / 180);
  const eye = new Vector3().subVectors(camera.position, target);
  const right = new Vector3().crossVectors(camera.up, eye).normalize();
  const shift = right.multiplyScalar(dx * height).addScaledVector(camera.up, dy * height);
  camera.position.add(shift);
  target.add(shift);
}
