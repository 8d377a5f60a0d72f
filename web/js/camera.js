// camera.js — the orbit camera around the signer: yaw/pitch/distance about a target point, panning
// the target, presets (front, three-quarter, side, hands close-up), and the mouse, touch and keyboard
// gestures that drive it. Motion towards a preset is eased so a jump never disorients the viewer.
//
// Conventions (glTF): +Y up, the avatar faces +Z, so the "front" view looks from +Z towards -Z.
// Limits: pitch is kept within ±80° (at ±90° the up vector and view direction coincide and lookAt
// degenerates); distance 0.25–8 m (closer clips into the hands, farther makes the signer a speck).

import { lookAt, perspective, multiply } from './mat4.js';

const PITCH_LIMIT_RAD = (80 * Math.PI) / 180;
const MIN_DISTANCE_M = 0.25;
const MAX_DISTANCE_M = 8;
const FOV_Y_RAD = (35 * Math.PI) / 180;  // a portrait lens: little perspective distortion of hands

export class OrbitCamera {
  constructor() {
    // Framing defaults for a 1.7 m adult; fitTo() rescales them to the loaded avatar.
    this.bodyHeight_m = 1.7;
    this.handsCentre = null;  // set by the app from the core's joint positions (close-up preset)
    this.current = { yaw: 0, pitch: 0.05, distance: 2.6, target: [0, 1.2, 0] };
    this.goal = null;         // when set, current eases towards it
    this.view = new Float32Array(16);
    this.projection = new Float32Array(16);
    this.viewProjection = new Float32Array(16);
    this.eye = [0, 0, 0];
    this.aspect = 1;
  }

  fitTo(height_m) {
    if (!(height_m > 0.3 && height_m < 4)) return;
    this.bodyHeight_m = height_m;
    this.applyPreset('front', false);
  }

  presetPose(name) {
    const h = this.bodyHeight_m;
    // The signing space spans from above the head to the waist: frame chest height.
    const torso = [0, 0.72 * h, 0];
    switch (name) {
      case 'three-quarter':
        return { yaw: Math.PI / 5, pitch: 0.12, distance: 1.4 * h, target: [0, 0.62 * h, 0] };
      case 'side':
        // The whole figure, slightly from above: the floor and its shadow ground the signer.
        return { yaw: Math.PI / 2, pitch: 0.12, distance: 1.75 * h, target: [0, 0.55 * h, 0] };
      case 'hands': {
        const c = this.handsCentre || [0, 0.68 * h, 0.2 * h / 1.7];
        return { yaw: Math.PI / 10, pitch: 0.15, distance: 0.42 * h, target: [c[0], c[1], c[2]] };
      }
      case 'front':
      default:
        // Signing space: from above the head to mid-thigh, so the hands read at any window size.
        return { yaw: 0, pitch: 0.06, distance: 1.2 * h, target: [0, 0.68 * h, 0] };
    }
  }

  applyPreset(name, animate = true) {
    const pose = this.presetPose(name);
    if (animate) {
      this.goal = pose;
    } else {
      this.current = pose;
      this.goal = null;
    }
  }

  orbit(dYaw_rad, dPitch_rad) {
    this.goal = null;
    this.current.yaw += dYaw_rad;
    this.current.pitch = Math.max(-PITCH_LIMIT_RAD, Math.min(PITCH_LIMIT_RAD, this.current.pitch + dPitch_rad));
  }

  zoom(factor) {
    this.goal = null;
    this.current.distance = Math.max(MIN_DISTANCE_M, Math.min(MAX_DISTANCE_M, this.current.distance * factor));
  }

  // Pan in the view plane by a fraction of the visible height, so it feels the same at any zoom.
  pan(dx_fraction, dy_fraction) {
    this.goal = null;
    const c = this.current;
    const visibleHeight_m = 2 * c.distance * Math.tan(FOV_Y_RAD / 2);
    const right = [Math.cos(c.yaw), 0, -Math.sin(c.yaw)];
    const up = [-Math.sin(c.pitch) * Math.sin(c.yaw), Math.cos(c.pitch), -Math.sin(c.pitch) * Math.cos(c.yaw)];
    const dx = -dx_fraction * visibleHeight_m, dy = dy_fraction * visibleHeight_m;
    c.target = [
      c.target[0] + right[0] * dx + up[0] * dy,
      c.target[1] + right[1] * dx + up[1] * dy,
      c.target[2] + right[2] * dx + up[2] * dy,
    ];
  }

  // Advance easing (critically damped feel: close 1 - e^(-dt/τ) of the gap per frame, τ = 0.12 s).
  update(dt_s) {
    if (!this.goal) return;
    const a = 1 - Math.exp(-dt_s / 0.12);
    const c = this.current, g = this.goal;
    let dYaw = g.yaw - c.yaw;
    dYaw = Math.atan2(Math.sin(dYaw), Math.cos(dYaw));  // the short way round
    c.yaw += dYaw * a;
    c.pitch += (g.pitch - c.pitch) * a;
    c.distance += (g.distance - c.distance) * a;
    c.target = c.target.map((v, i) => v + (g.target[i] - v) * a);
    if (Math.abs(dYaw) < 1e-4 && Math.abs(g.distance - c.distance) < 1e-4) this.goal = null;
  }

  matrices(aspect) {
    const c = this.current;
    this.aspect = aspect;
    this.eye = [
      c.target[0] + c.distance * Math.cos(c.pitch) * Math.sin(c.yaw),
      c.target[1] + c.distance * Math.sin(c.pitch),
      c.target[2] + c.distance * Math.cos(c.pitch) * Math.cos(c.yaw),
    ];
    lookAt(this.view, this.eye, c.target, [0, 1, 0]);
    perspective(this.projection, FOV_Y_RAD, aspect, 0.05, 30);
    multiply(this.viewProjection, this.projection, this.view);
    return this;
  }
}

// Mouse: left-drag orbits, right-drag or shift-drag pans, wheel zooms. Touch: one finger orbits, two
// fingers pinch-zoom and pan. Keyboard (canvas focused): arrows orbit, shift+arrows pan, +/- zoom,
// 1–4 presets.
export function attachCameraControls(element, camera, onPreset) {
  let drag = null;
  const pointers = new Map();
  let pinch = null;

  element.addEventListener('contextmenu', (e) => e.preventDefault());
  element.addEventListener('pointerdown', (e) => {
    element.setPointerCapture(e.pointerId);
    pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    if (pointers.size === 1) {
      drag = { x: e.clientX, y: e.clientY, pan: e.button === 2 || e.shiftKey };
    } else if (pointers.size === 2) {
      drag = null;
      pinch = pinchState(pointers);
    }
  });
  element.addEventListener('pointermove', (e) => {
    if (!pointers.has(e.pointerId)) return;
    pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    const h = element.clientHeight || 1;
    if (pinch && pointers.size === 2) {
      const now = pinchState(pointers);
      if (now.spread > 0 && pinch.spread > 0) camera.zoom(pinch.spread / now.spread);
      camera.pan((now.cx - pinch.cx) / h, (now.cy - pinch.cy) / h);
      pinch = now;
    } else if (drag) {
      const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
      drag.x = e.clientX;
      drag.y = e.clientY;
      if (drag.pan) camera.pan(dx / h, dy / h);
      else camera.orbit((-dx / h) * Math.PI, (dy / h) * Math.PI * 0.7);
    }
  });
  const end = (e) => {
    pointers.delete(e.pointerId);
    if (pointers.size < 2) pinch = null;
    if (pointers.size === 0) drag = null;
  };
  element.addEventListener('pointerup', end);
  element.addEventListener('pointercancel', end);
  element.addEventListener('wheel', (e) => {
    e.preventDefault();
    camera.zoom(Math.exp(e.deltaY * 0.0015));
  }, { passive: false });
  element.addEventListener('keydown', (e) => {
    const step = 0.08;
    let handled = true;
    if (e.key === 'ArrowLeft') e.shiftKey ? camera.pan(-step, 0) : camera.orbit(step * 2, 0);
    else if (e.key === 'ArrowRight') e.shiftKey ? camera.pan(step, 0) : camera.orbit(-step * 2, 0);
    else if (e.key === 'ArrowUp') e.shiftKey ? camera.pan(0, -step) : camera.orbit(0, step);
    else if (e.key === 'ArrowDown') e.shiftKey ? camera.pan(0, step) : camera.orbit(0, -step);
    else if (e.key === '+' || e.key === '=') camera.zoom(0.9);
    else if (e.key === '-' || e.key === '_') camera.zoom(1 / 0.9);
    else if (e.key === '1') onPreset('front');
    else if (e.key === '2') onPreset('three-quarter');
    else if (e.key === '3') onPreset('side');
    else if (e.key === '4') onPreset('hands');
    else handled = false;
    if (handled) e.preventDefault();
  });
}

function pinchState(pointers) {
  const [a, b] = [...pointers.values()];
  return { cx: (a.x + b.x) / 2, cy: (a.y + b.y) / 2, spread: Math.hypot(a.x - b.x, a.y - b.y) };
}
