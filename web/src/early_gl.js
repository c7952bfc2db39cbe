// The page's script runs before the browser has read the (large) data that follows it: it
// makes the WebGL renderer and draws the path's one shader program once, so the GPU process
// (on a machine without a GPU: SwiftShader, compiling on the CPU) does that work while the main
// thread is still reading the data, instead of after it.
import * as THREE from "three";
import { pathGeometry, pathMaterial } from "./path_material.js";

// Multisampling smooths the lines but costs every fragment several samples: on a large path
// (drawn on the CPU where there is no GPU) it would be most of the time to the first frame.
const LARGE_PATH_VERTICES = 200000;

let early = null;

//! Starts the renderer for a page whose path has `vertices` vertices.
export function startRenderer(vertices) {
  const renderer = new THREE.WebGLRenderer({ antialias: vertices < LARGE_PATH_VERTICES, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(8, 8, false);
  // One line, one dashed line, one dot: the states the first real frame needs.
  const scene = new THREE.Scene();
  const two = () => new Float32Array([0, 0, 0, 1, 1, 0]);
  scene.add(new THREE.LineSegments(pathGeometry(two(), Uint8Array.from([0, 0, 0])), pathMaterial()));
  scene.add(new THREE.LineSegments(pathGeometry(two(), Uint8Array.from([0, 0, 0]), new Float32Array([0, 1.4])), pathMaterial({ dashSize: 0.1 })));
  const dot = new THREE.Points(pathGeometry(new Float32Array(3), Uint8Array.from([0, 0, 0])), pathMaterial({ pointSize: 8, round: true, ring: true, onTop: true }));
  scene.add(dot);
  const camera = new THREE.OrthographicCamera(-2, 2, 2, -2, -2, 2);
  // Compiling and linking are commands the GPU process runs on its own; the first draw (which
  // builds the pipeline) waits for them, so it goes into a task of its own that the browser
  // runs between chunks of the data.
  renderer.compile(scene, camera);
  renderer.getContext().flush();
  setTimeout(() => {
    renderer.render(scene, camera);
    renderer.getContext().flush();
  }, 0);
  early = { renderer, vertices };
  return renderer;
}

//! The renderer started for this page, if it was (and for the same size class).
export function takeRenderer(vertices) {
  if (!early || early.vertices < LARGE_PATH_VERTICES !== vertices < LARGE_PATH_VERTICES) {
    return new THREE.WebGLRenderer({ antialias: vertices < LARGE_PATH_VERTICES, preserveDrawingBuffer: true });
  }
  const { renderer } = early;
  early = null;
  return renderer;
}
