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

//! Geometry for pathMaterial: positions, 8-bit colours (RGBA per vertex, or one RGB for all)
//! and the distance along the line (absent unless dashed: read as 0). Four bytes a colour, not
//! three: WebGL over Vulkan (ANGLE, SwiftShader) has no 3-byte vertex format and would convert
//! every colour on the CPU when the buffer is given to the GPU.
export function pathGeometry(positions, colors, lineDistances) {
  const count = positions.length / 3;
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(positions, 3));
  let rgba = colors;
  if (colors.length === 3) {
    rgba = new Uint8Array(count * 4).fill(255);
    for (let i = 0; i < count; i++) rgba.set(colors, 4 * i);
  }
  geometry.setAttribute("color", new THREE.BufferAttribute(rgba, 4, true));
  // Without distances the attribute is left out: the shader then reads 0, and the GPU is not
  // given megabytes of zeros.
  if (lineDistances) geometry.setAttribute("lineDistance", new THREE.BufferAttribute(lineDistances, 1));
  return geometry;
}
