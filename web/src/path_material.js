// One small shader program for everything the path view draws before the first click: feed
// lines coloured per vertex, dashed rapids, the dots of moves that have no length of their own
// (in the speed colour with a dark rim) and the tool. Without a GPU, WebGL compiles every program on the CPU (SwiftShader) and that
// costs far more than drawing a million segments, so the first frame compiles this one only;
// three.js's stock materials would need one program each.
import * as THREE from "three";

const vertexShader = `
precision highp float;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
uniform float pointSize;
attribute vec3 position;
attribute vec3 color;
attribute float lineDistance;
varying vec3 vColor;
varying float vDistance;
void main() {
  vColor = color;
  vDistance = lineDistance;
  gl_PointSize = pointSize;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}`;

const fragmentShader = `
precision highp float;
uniform float dashSize;
uniform float roundDot;
uniform float ring;
varying vec3 vColor;
varying float vDistance;
void main() {
  if (dashSize > 0.0 && mod(vDistance, 2.0 * dashSize) > dashSize) discard;
  float r = roundDot > 0.0 ? length(gl_PointCoord - vec2(0.5)) : 0.0;
  if (r > 0.5) discard;
  gl_FragColor = vec4(ring > 0.0 && r > 0.3 ? vec3(0.08) : vColor, 1.0);
}`;

//! A material of the shared program. dashSize > 0: dashes and gaps of that length (world
//! units, along the geometry's lineDistance); pointSize: pixels, for THREE.Points.
//! round: a round dot, not a square; ring: with a dark rim.
export function pathMaterial({ dashSize = 0, pointSize = 1, round = false, ring = false, onTop = false } = {}) {
  return new THREE.RawShaderMaterial({
    vertexShader,
    fragmentShader,
    uniforms: {
      dashSize: { value: dashSize },
      pointSize: { value: pointSize },
      roundDot: { value: round ? 1 : 0 },
      ring: { value: ring ? 1 : 0 },
    },
    depthTest: !onTop,
  });
}

//! Geometry for pathMaterial: positions, 8-bit colours (one per vertex or one for all) and the
//! distance along the line (zeros unless dashed).
export function pathGeometry(positions, colors, lineDistances) {
  const count = positions.length / 3;
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(positions, 3));
  let rgb = colors;
  if (colors.length === 3 && count !== 1) {
    rgb = new Uint8Array(count * 3);
    for (let i = 0; i < count; i++) rgb.set(colors, 3 * i);
  }
  geometry.setAttribute("color", new THREE.BufferAttribute(rgb, 3, true));
  geometry.setAttribute("lineDistance", new THREE.BufferAttribute(lineDistances || new Float32Array(count), 1));
  return geometry;
}
