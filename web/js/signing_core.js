// signing_core.js — the page's handle on the WebAssembly core: it loads the module (SIMD build where
// the browser validates it, else scalar — core_loader.js decides, silently), hands it the avatar, and
// wraps the embind `Player` of src/wasm/player_api.cpp. Every decision (parsing, synthesis, sampling,
// forward kinematics, skinning, export) happens in the core; this file only converts JSON and keeps
// the typed-array views fresh.
//
// Views onto WASM memory: embind's typed_memory_view returns a view over the module's current
// ArrayBuffer; when the heap grows (ALLOW_MEMORY_GROWTH) that buffer is detached and old views read
// nothing. We therefore ask the core for new views after every call that can allocate and whenever
// a view's buffer is no longer the heap's buffer (a view costs no copy).

import { loadCore } from './core_loader.js';

export class SigningCore {
  static async create({ onProgress = () => {} } = {}) {
    const { module, flavour } = await loadCore({ onProgress });
    return new SigningCore(module, flavour);
  }

  constructor(module, flavour) {
    this.module = module;
    this.flavour = flavour;            // 'simd' or 'scalar'
    this.player = new module.Player();
    this.info = null;
    this.views = null;
  }

  // Returns null on success, else the loader's message (wrong file, missing joints...).
  loadAvatar(bytes) {
    const error = this.player.loadAvatar(bytes);
    if (error) return error;
    this.info = JSON.parse(this.player.avatarInfoJson());
    this.info.parents = Int32Array.from(this.info.joints.map((j) => j.parent));
    this.refreshViews();
    return null;
  }

  refreshViews() {
    const p = this.player;
    this.views = {
      positions: p.positions(),
      normals: p.normals(),
      jointPositions: p.jointPositions(),
      anchorPositions: p.anchorPositions(),
      heap: this.module.HEAPU8.buffer,
    };
  }

  // Fresh views if the heap moved since we took them.
  current() {
    if (!this.views || this.views.heap !== this.module.HEAPU8.buffer || this.views.positions.buffer.byteLength === 0) {
      this.refreshViews();
    }
    return this.views;
  }

  indices() {
    // Copied once into the GPU index buffer by the renderer; static for the avatar's lifetime.
    return this.player.indices();
  }

  // Parse only: { ok, format, diagnostics: [{severity, offset, length, line, column, symbol, message}] }
  parse(text, format) {
    return JSON.parse(this.player.parse(text, format));
  }

  // Notation -> the clip the player plays: { ok, diagnostics, errors, duration_s, segments, ... }
  setNotation(text, format, options = {}) {
    const result = JSON.parse(this.player.setNotation(text, format, JSON.stringify(options)));
    this.refreshViews();
    return result;
  }

  // The server's lookup plan -> one phrase clip (signs, fingerspelled letters, pauses).
  setPhrase(plan, options = {}) {
    const result = JSON.parse(this.player.setPhrase(JSON.stringify(plan), JSON.stringify(options)));
    this.refreshViews();
    return result;
  }

  // Sample the clip at t, forward kinematics, skinning into the core's vertex buffers.
  update(time_s) {
    this.player.update(time_s);
    return this.current();
  }

  // HamNoSys symbol names of a notation text's code points (glyphs need a HamNoSys font).
  hamnosysNames(text) {
    return [...text].map((c) => this.player.hamSymbolName(c.codePointAt(0))).filter(Boolean);
  }

  exportBvh() {
    return this.player.exportBvh();
  }

  exportGlb() {
    // A view onto WASM memory: copy it out once, since a Blob must outlive the next heap growth.
    return new Uint8Array(this.player.exportGlb());
  }
}
