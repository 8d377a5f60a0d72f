// shaders.js — the GLSL ES 3.00 programs of the renderer: the calm background gradient, the floor
// with its soft contact shadow, the lit skinned avatar and the debug lines/points.
// Colours are computed in linear space and written as sRGB (glTF 2.0 §3.9.2: baseColorFactor is
// linear), with a gentle filmic curve so highlights on skin roll off instead of clipping.

export const BACKGROUND_VS = `#version 300 es
out vec2 vUv;
void main() {
  // One triangle that covers the screen (no vertex buffer needed).
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  vUv = p;
  gl_Position = vec4(p * 2.0 - 1.0, 1.0, 1.0);
}`;

export const BACKGROUND_FS = `#version 300 es
precision mediump float;
in vec2 vUv;
uniform vec3 uTop;
uniform vec3 uBottom;
out vec4 outColor;
void main() {
  float t = smoothstep(0.0, 1.0, vUv.y);
  // A faint vignette keeps the eye on the signer in the middle.
  float vignette = 1.0 - 0.18 * pow(length(vUv - vec2(0.5, 0.55)), 2.0);
  outColor = vec4(mix(uBottom, uTop, t) * vignette, 1.0);
}`;

export const FLOOR_VS = `#version 300 es
layout(location = 0) in vec2 aCorner;   // [-1, 1]^2
uniform mat4 uViewProj;
uniform float uRadius;
out vec2 vLocal;
void main() {
  vLocal = aCorner * uRadius;
  gl_Position = uViewProj * vec4(vLocal.x, 0.0, vLocal.y, 1.0);
}`;

export const FLOOR_FS = `#version 300 es
precision highp float;
in vec2 vLocal;
uniform float uRadius;
uniform vec2 uShadowCentre;   // floor position under the hips (x, z)
uniform vec2 uShadowSize;     // half extents of the blob, metres
uniform vec3 uFloorColor;
out vec4 outColor;
void main() {
  float r = length(vLocal) / uRadius;
  float disc = 1.0 - smoothstep(0.55, 1.0, r);          // the floor fades into the background
  vec2 d = (vLocal - uShadowCentre) / uShadowSize;
  float shadow = exp(-2.2 * dot(d, d));                  // soft gaussian blob: ambient occlusion
  vec3 colour = uFloorColor * (1.0 - 0.45 * shadow);
  outColor = vec4(colour, disc * 0.9);
}`;

export const AVATAR_VS = `#version 300 es
layout(location = 0) in vec3 aPosition;   // skinned in WebAssembly, model space = world space
layout(location = 1) in vec3 aNormal;
uniform mat4 uViewProj;
out vec3 vPosition;
out vec3 vNormal;
void main() {
  vPosition = aPosition;
  vNormal = aNormal;
  gl_Position = uViewProj * vec4(aPosition, 1.0);
}`;

export const AVATAR_FS = `#version 300 es
precision highp float;
in vec3 vPosition;
in vec3 vNormal;
uniform vec3 uEye;
uniform vec4 uBaseColor;      // linear
uniform float uRoughness;
uniform float uWrap;          // wrap lighting: 0 hard Lambert, ~0.5 soft skin
uniform vec3 uSubsurface;     // tint of light scattered past the terminator (skin)
uniform vec3 uKeyDir;         // towards the light
uniform vec3 uKeyColor;
uniform vec3 uFillDir;
uniform vec3 uFillColor;
uniform vec3 uRimDir;
uniform vec3 uRimColor;
uniform vec3 uSky;
uniform vec3 uGround;
out vec4 outColor;

vec3 filmic(vec3 x) {          // Narkowicz 2015 ACES fit
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 directional(vec3 n, vec3 v, vec3 l, vec3 colour, vec3 albedo, float shininess) {
  float ndl = dot(n, l);
  float wrapped = max((ndl + uWrap) / (1.0 + uWrap), 0.0);
  // Light that wrapped past the terminator is tinted (a cheap stand-in for subsurface scattering).
  vec3 scatter = uSubsurface * max(wrapped - max(ndl, 0.0), 0.0);
  vec3 h = normalize(l + v);
  float ndh = max(dot(n, h), 0.0);
  // Normalised Blinn-Phong with Schlick Fresnel (F0 = 0.04, dielectric).
  float fresnel = 0.04 + 0.96 * pow(1.0 - max(dot(v, h), 0.0), 5.0);
  float spec = (shininess + 8.0) / 25.1327 * pow(ndh, shininess) * fresnel * max(ndl, 0.0);
  return colour * (albedo * (wrapped + scatter) + spec);
}

void main() {
  vec3 n = normalize(vNormal);
  vec3 v = normalize(uEye - vPosition);
  if (dot(n, v) < 0.0) n = -n;   // inside of the mouth / eyelids seen from behind
  vec3 albedo = uBaseColor.rgb;
  float r = clamp(uRoughness, 0.08, 1.0);
  float shininess = 2.0 / (r * r * r * r) - 2.0;
  vec3 hemi = mix(uGround, uSky, 0.5 + 0.5 * n.y);
  vec3 colour = albedo * hemi;
  colour += directional(n, v, normalize(uKeyDir), uKeyColor, albedo, shininess);
  colour += directional(n, v, normalize(uFillDir), uFillColor, albedo, shininess);
  // Rim light separates the silhouette (hands in front of the body) from the background.
  float rim = pow(1.0 - max(dot(n, v), 0.0), 3.0) * max(dot(n, normalize(uRimDir)) * 0.5 + 0.5, 0.0);
  colour += uRimColor * rim;
  outColor = vec4(pow(filmic(colour), vec3(1.0 / 2.2)), uBaseColor.a);
}`;

export const DEBUG_VS = `#version 300 es
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProj;
uniform float uPointSize;
void main() {
  gl_Position = uViewProj * vec4(aPosition, 1.0);
  gl_PointSize = uPointSize;
}`;

export const DEBUG_FS = `#version 300 es
precision mediump float;
uniform vec4 uColor;
out vec4 outColor;
void main() { outColor = uColor; }`;
