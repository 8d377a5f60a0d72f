// renderer.js — WebGL2 drawing of what the core computed: the skinned avatar (vertex buffers skinned
// in WebAssembly memory and uploaded with bufferSubData straight from a Float32Array view onto the
// WASM heap — no JS copy per frame), the background gradient, the floor with a soft shadow, and the
// debug skeleton/anchors. It does not animate, skin or decide anything: the core does.
//
// Limits: indices are 32-bit (core in WebGL2, needed above 65,535 vertices); one draw call per
// glTF primitive/material; canvas backing store capped at 2× CSS pixels (a 3× phone would quadruple
// fill cost on SwiftShader and mobile GPUs for no visible gain with MSAA on).

import * as S from './shaders.js';

const MAX_PIXEL_RATIO = 2;
// Frames the GPU may be behind before the page stops sending new ones. Past that, uploading the
// next pose makes the main thread wait for the GPU process (bufferSubData and the command-buffer
// flush block once their buffers are full): on SwiftShader under load that wait was the whole
// tail of the per-frame time. One: measured over 5 cold loads each at load 7-9, with two the
// upload's p95 was 1.4-1.9 ms (frame work p95 1.7-2.6 ms), with one 0.3 ms (frame work 1.0 ms),
// while the frames drawn were 142 against 142 and 171 (5 x 5 s; SwiftShader is the limit). A
// frame the GPU finishes within the frame interval is not skipped: Chrome re-reads a fence's
// status (a query, no round trip) at the first getSyncParameter of the next task, which is the
// next frame's gpuCaughtUp.
const MAX_FRAMES_IN_FLIGHT = 1;
// Vertex buffer sets written in turn (setMesh). A pose is uploaded only when fewer than
// MAX_FRAMES_IN_FLIGHT frames are unfinished (gpuCaughtUp): those draw from the sets written
// before, so the next set in turn is free. Fences finish in order.
const VERTEX_SLOTS = MAX_FRAMES_IN_FLIGHT;

export class WebGL2Unavailable extends Error {}

export class Renderer {
  constructor(canvas) {
    this.canvas = canvas;
    // The drawing buffer is sized before the context exists: a context made at the canvas's
    // default 300×150 and resized at the first draw allocates its (multisampled) framebuffer twice,
    // and the resize makes the main thread wait for the GPU process (slow on SwiftShader).
    this.pixelRatio = 1;
    this.resize();
    // index.html may have made this context already (to start it early), with these attributes:
    // keep the two lists the same.
    const gl = canvas.getContext('webgl2', {
      antialias: true,                 // MSAA on the default framebuffer
      alpha: false,
      depth: true,
      premultipliedAlpha: false,
      preserveDrawingBuffer: true,     // screenshots, pixel tests and MediaRecorder read the canvas
      powerPreference: 'high-performance',
    });
    if (!gl) throw new WebGL2Unavailable('WebGL2 is not available in this browser');
    this.gl = gl;
    // Compile and link are only requested here: asking for a status would make the main thread wait
    // for the GPU process to finish them (SwiftShader compiles on the CPU, slowly). The programs
    // build while the core and the avatar download; each is checked when first drawn, or earlier
    // through programsReady() where KHR_parallel_shader_compile tells without waiting.
    this.parallelCompile = gl.getExtension('KHR_parallel_shader_compile');
    this.background = startProgram(gl, S.BACKGROUND_VS, S.BACKGROUND_FS);
    this.floor = startProgram(gl, S.FLOOR_VS, S.FLOOR_FS);
    this.avatar = startProgram(gl, S.AVATAR_VS, S.AVATAR_FS);
    // The skeleton overlay's program is not needed for the first frame: it is compiled once that
    // frame is drawn (startDeferredPrograms), so it does not share the GPU process with the three
    // the first frame waits for (measured: programs still linking when the avatar was loaded).
    this.debug = null;
    this.emptyVao = gl.createVertexArray();
    this.floorVao = gl.createVertexArray();
    gl.bindVertexArray(this.floorVao);
    const quad = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, quad);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 1, -1, -1, 1, 1, 1]), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    this.debugVao = gl.createVertexArray();
    gl.bindVertexArray(this.debugVao);
    this.debugBuffer = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, this.debugBuffer);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
    gl.bindVertexArray(null);
    this.mesh = null;
    this.shadowCentre = [0, 0];
    this.bodyHeight_m = 1.7;
    this.fences = [];   // one per drawn frame not yet finished by the GPU, oldest first
    // Send the queued compiles to the GPU process now, so they build while the page downloads
    // (otherwise they wait in the command buffer until the next flush).
    gl.flush();
  }

  // True when every program has linked. Where KHR_parallel_shader_compile exists this asks without
  // waiting; elsewhere it is false until finishPrograms() has run (so nothing waits by accident).
  programsReady() {
    const all = this.firstFramePrograms();
    if (all.every((p) => p.u)) return true;
    const done = this.parallelCompile?.COMPLETION_STATUS_KHR;
    return !!done && all.every((p) => p.u || this.gl.getProgramParameter(p.program, done));
  }

  // Waits for every program (if still building) and checks it: throws the compile or link error.
  finishPrograms() {
    for (const p of this.firstFramePrograms()) finishProgram(this.gl, p);
  }

  firstFramePrograms() {
    return [this.background, this.floor, this.avatar];
  }

  // Starts compiling what the first frame did not need (the skeleton overlay); at the latest when
  // the overlay is first drawn.
  startDeferredPrograms() {
    if (this.debug) return;
    this.debug = startProgram(this.gl, S.DEBUG_VS, S.DEBUG_FS);
    this.gl.flush();
  }

  // False while the GPU is still working through MAX_FRAMES_IN_FLIGHT earlier frames: then the
  // caller skips this frame (the clock runs on; the next drawn frame shows the pose of its time).
  // Asking a fence's status never waits.
  gpuCaughtUp() {
    const gl = this.gl;
    while (this.fences.length && gl.getSyncParameter(this.fences[0], gl.SYNC_STATUS) === gl.SIGNALED) {
      gl.deleteSync(this.fences.shift());
    }
    return this.fences.length < MAX_FRAMES_IN_FLIGHT;
  }

  // Static data, uploaded once per avatar: indices and materials; the vertex buffers are allocated
  // here and refilled every frame by upload(). Two sets of them (VERTEX_SLOTS), written in turn:
  // a pose is never written into the buffers the frame still in flight draws from, which could
  // make the upload wait for the GPU (ANGLE/SwiftShader copies or stalls on an in-use buffer).
  setMesh({ vertexCount, indices, primitives, materials }) {
    const gl = this.gl;
    if (this.mesh) {
      for (const slot of this.mesh.slots) {
        gl.deleteVertexArray(slot.vao);
        gl.deleteBuffer(slot.positions);
        gl.deleteBuffer(slot.normals);
      }
      gl.deleteBuffer(this.mesh.indices);
    }
    const indexBuffer = gl.createBuffer();
    const slots = [];
    for (let i = 0; i < VERTEX_SLOTS; i++) {
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      const positions = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, positions);
      gl.bufferData(gl.ARRAY_BUFFER, vertexCount * 12, gl.DYNAMIC_DRAW);
      gl.enableVertexAttribArray(0);
      gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
      const normals = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, normals);
      gl.bufferData(gl.ARRAY_BUFFER, vertexCount * 12, gl.DYNAMIC_DRAW);
      gl.enableVertexAttribArray(1);
      gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 0, 0);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, indexBuffer);   // part of the VAO's state
      if (i === 0) gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
      slots.push({ vao, positions, normals });
    }
    gl.bindVertexArray(null);
    const drawn = primitives.length ? primitives : [{ first_index: 0, index_count: indices.length, material: 0 }];
    this.mesh = {
      slots, current: 0, indices: indexBuffer, vertexCount,
      primitives: drawn.map((p) => ({ ...p, look: lookOf(materials[p.material]) })),
    };
  }

  // Per pose: the core's skinned positions/normals, as views onto WASM memory (no copy), into the
  // slot after the one last drawn; later frames draw from it until the next pose.
  upload(positionsView, normalsView) {
    if (!this.mesh) return;
    const gl = this.gl;
    const mesh = this.mesh;
    mesh.current = (mesh.current + 1) % mesh.slots.length;
    const slot = mesh.slots[mesh.current];
    gl.bindBuffer(gl.ARRAY_BUFFER, slot.positions);
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, positionsView);
    gl.bindBuffer(gl.ARRAY_BUFFER, slot.normals);
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, normalsView);
  }

  // Debug overlay data: joint model positions (xyz per joint) with parent indices, and anchor points.
  setDebugGeometry(jointPositions, parents, anchorPositions) {
    const lines = [];
    for (let j = 0; j < parents.length; j++) {
      const p = parents[j];
      if (p < 0) continue;
      lines.push(jointPositions[p * 3], jointPositions[p * 3 + 1], jointPositions[p * 3 + 2],
        jointPositions[j * 3], jointPositions[j * 3 + 1], jointPositions[j * 3 + 2]);
    }
    this.debugLines = new Float32Array(lines);
    this.debugJoints = jointPositions;
    this.debugAnchors = anchorPositions;
  }

  resize() {
    const ratio = Math.min(window.devicePixelRatio || 1, MAX_PIXEL_RATIO);
    const width = Math.max(1, Math.round(this.canvas.clientWidth * ratio));
    const height = Math.max(1, Math.round(this.canvas.clientHeight * ratio));
    if (this.canvas.width !== width || this.canvas.height !== height) {
      this.canvas.width = width;
      this.canvas.height = height;
    }
    this.pixelRatio = ratio;
    return width / height;
  }

  draw(camera, { showDebug = false } = {}) {
    const gl = this.gl;
    const aspect = this.resize();
    camera.matrices(aspect);
    gl.viewport(0, 0, this.canvas.width, this.canvas.height);
    gl.clearColor(0.9, 0.92, 0.95, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);

    // Background: no depth.
    gl.disable(gl.DEPTH_TEST);
    gl.depthMask(false);
    finishProgram(gl, this.background);
    gl.useProgram(this.background.program);
    gl.uniform3f(this.background.u.uTop, 0.93, 0.945, 0.965);
    gl.uniform3f(this.background.u.uBottom, 0.74, 0.78, 0.83);
    gl.bindVertexArray(this.emptyVao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);

    // Floor with the blob shadow, blended, depth-tested against nothing yet but written for order.
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
    finishProgram(gl, this.floor);
    gl.useProgram(this.floor.program);
    gl.uniformMatrix4fv(this.floor.u.uViewProj, false, camera.viewProjection);
    gl.uniform1f(this.floor.u.uRadius, 1.6 * this.bodyHeight_m);
    gl.uniform2f(this.floor.u.uShadowCentre, this.shadowCentre[0], this.shadowCentre[1]);
    gl.uniform2f(this.floor.u.uShadowSize, 0.2 * this.bodyHeight_m, 0.13 * this.bodyHeight_m);
    gl.uniform3f(this.floor.u.uFloorColor, 0.86, 0.87, 0.88);
    gl.bindVertexArray(this.floorVao);
    gl.drawArrays(gl.TRIANGLE_STRIP, 0, 4);
    gl.disable(gl.BLEND);

    gl.enable(gl.DEPTH_TEST);
    gl.depthMask(true);
    gl.depthFunc(gl.LEQUAL);
    if (this.mesh) this.drawAvatar(camera);
    if (showDebug) this.drawDebug(camera);
    gl.bindVertexArray(null);
    const fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    if (fence) this.fences.push(fence);
  }

  drawAvatar(camera) {
    const gl = this.gl;
    const { u } = finishProgram(gl, this.avatar);
    gl.useProgram(this.avatar.program);
    gl.uniformMatrix4fv(u.uViewProj, false, camera.viewProjection);
    gl.uniform3fv(u.uEye, camera.eye);
    // Three-point portrait lighting: warm key from the signer's upper right-front, cool fill from
    // the other side, rim from behind; hemisphere ambient sky/ground.
    gl.uniform3f(u.uKeyDir, -0.45, 0.75, 0.6);
    gl.uniform3f(u.uKeyColor, 1.55, 1.45, 1.32);
    gl.uniform3f(u.uFillDir, 0.6, 0.25, 0.55);
    gl.uniform3f(u.uFillColor, 0.38, 0.42, 0.5);
    gl.uniform3f(u.uRimDir, 0.2, 0.5, -1.0);
    gl.uniform3f(u.uRimColor, 0.22, 0.24, 0.28);
    gl.uniform3f(u.uSky, 0.46, 0.5, 0.56);
    gl.uniform3f(u.uGround, 0.26, 0.24, 0.22);
    // No back-face culling: the face has open surfaces (mouth, eyelids) seen from both sides.
    gl.disable(gl.CULL_FACE);
    gl.bindVertexArray(this.mesh.slots[this.mesh.current].vao);
    for (const p of this.mesh.primitives) {
      const look = p.look;
      gl.uniform4fv(u.uBaseColor, look.baseColor);
      gl.uniform1f(u.uRoughness, look.roughness);
      gl.uniform1f(u.uWrap, look.wrap);
      gl.uniform3fv(u.uSubsurface, look.subsurface);
      gl.drawElements(gl.TRIANGLES, p.index_count, gl.UNSIGNED_INT, p.first_index * 4);
    }
  }

  drawDebug(camera) {
    const gl = this.gl;
    if (!this.debugLines) return;
    this.startDeferredPrograms();
    const { u } = finishProgram(gl, this.debug);
    gl.disable(gl.DEPTH_TEST);   // the skeleton is inside the body: draw it on top
    gl.useProgram(this.debug.program);
    gl.uniformMatrix4fv(u.uViewProj, false, camera.viewProjection);
    gl.bindVertexArray(this.debugVao);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.debugBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, this.debugLines, gl.STREAM_DRAW);
    gl.uniform4f(u.uColor, 0.05, 0.55, 0.35, 1);
    gl.drawArrays(gl.LINES, 0, this.debugLines.length / 3);
    gl.uniform1f(u.uPointSize, 4 * this.pixelRatio);
    gl.bufferData(gl.ARRAY_BUFFER, this.debugJoints, gl.STREAM_DRAW);
    gl.drawArrays(gl.POINTS, 0, this.debugJoints.length / 3);
    if (this.debugAnchors && this.debugAnchors.length) {
      gl.uniform4f(u.uColor, 0.85, 0.25, 0.55, 1);
      gl.uniform1f(u.uPointSize, 5 * this.pixelRatio);
      gl.bufferData(gl.ARRAY_BUFFER, this.debugAnchors, gl.STREAM_DRAW);
      gl.drawArrays(gl.POINTS, 0, this.debugAnchors.length / 3);
    }
    gl.enable(gl.DEPTH_TEST);
  }
}

// Skin gets wrap lighting and a warm scatter tint; cloth and hair a harder Lambert.
function lookOf(material) {
  const m = material || {};
  const baseColor = m.base_color || [0.8, 0.8, 0.8, 1];
  const name = (m.name || '').toLowerCase();
  const isSkin = /skin|face|hand|body|lip/.test(name);
  return {
    baseColor: new Float32Array(baseColor),
    roughness: m.roughness ?? 0.6,
    wrap: isSkin ? 0.5 : 0.2,
    subsurface: new Float32Array(isSkin ? [0.45, 0.12, 0.06] : [0, 0, 0]),
  };
}

// Queues a program's compile and link without waiting for either (see the constructor).
function startProgram(gl, vsSource, fsSource) {
  const shader = (type, source) => {
    const sh = gl.createShader(type);
    gl.shaderSource(sh, source);
    gl.compileShader(sh);
    return sh;
  };
  const vs = shader(gl.VERTEX_SHADER, vsSource);
  const fs = shader(gl.FRAGMENT_SHADER, fsSource);
  const p = gl.createProgram();
  gl.attachShader(p, vs);
  gl.attachShader(p, fs);
  gl.linkProgram(p);
  return { program: p, vs, fs, u: null };
}

// Checks a started program once (the first status query waits for its link) and finds its
// uniforms; later calls return at once. A failed compile names its stage and the driver's log.
function finishProgram(gl, entry) {
  if (entry.u) return entry;
  const p = entry.program;
  if (!gl.getProgramParameter(p, gl.LINK_STATUS)) {
    for (const [sh, stage] of [[entry.vs, 'vertex'], [entry.fs, 'fragment']]) {
      if (!gl.getShaderParameter(sh, gl.COMPILE_STATUS)) throw new Error(`${stage} shader compile failed: ${gl.getShaderInfoLog(sh)}`);
    }
    throw new Error(`program link failed: ${gl.getProgramInfoLog(p)}`);
  }
  const u = {};
  const count = gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS);
  for (let i = 0; i < count; i++) {
    const info = gl.getActiveUniform(p, i);
    u[info.name] = gl.getUniformLocation(p, info.name);
  }
  gl.deleteShader(entry.vs);   // linked: the program keeps what it needs
  gl.deleteShader(entry.fs);
  entry.u = u;
  return entry;
}
