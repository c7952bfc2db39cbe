// The 3D tool path: feed moves as lines coloured by planned speed, rapids dashed, a marker for
// the tool, picking by mouse. Renders only when something changed.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { Line2 } from "three/addons/lines/Line2.js";
import { LineGeometry } from "three/addons/lines/LineGeometry.js";
import { LineMaterial } from "three/addons/lines/LineMaterial.js";
import { pathArrays } from "./path_arrays.js";
import { pathGeometry, pathMaterial } from "./path_material.js";
import { takeRenderer } from "./early_gl.js";
import { PREVIEW_FROM, PREVIEW_TOLERANCE_PX, previewArrays, worldPerPixel } from "./path_preview.js";

const MANY_DOTS = 10000;
const RAPID_COLOR = [119, 119, 119];

export function createPathView(container, path, onPick) {
  const { vertexEnd, hasY } = path;
  const a = pathArrays(path);
  const { moveCount, vertexCount, centre, size, pointMove, pointOfMove } = a;

  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf7f7f4);
  const feedGeometry = pathGeometry(a.vertexPos, a.vertexCol);
  feedGeometry.setIndex(new THREE.BufferAttribute(a.feedIndex, 1));
  const feedLines = new THREE.LineSegments(feedGeometry, pathMaterial());
  feedLines.userData.moveOfHit = (hit) => a.feedMoveOfStart[hit.index];
  scene.add(feedLines);
  const rapidLines = new THREE.LineSegments(
    pathGeometry(a.rapidPos, Uint8Array.from(RAPID_COLOR), a.rapidDistance),
    pathMaterial({ dashSize: size / 150 }),
  );
  rapidLines.userData.moveOfHit = (hit) => a.rapidMove[hit.index / 2];
  scene.add(rapidLines);
  // Moves with no length of their own (a G1 to where the tool stands, or a short move whose
  // whole length went into the transitions of its two corners) are dots, drawn over the lines
  // so they can be seen and clicked: in the planned speed's colour with a dark rim, or where
  // there are so many that rims would hide the path (a fine raster), small and rimless.
  // Many dots are one pixel each: WebGL on the CPU (SwiftShader) spends on a 3-pixel dot about
  // three times what it spends on a 1-pixel one, and 600,000 of them were most of a frame.
  const fewDots = pointMove.length <= MANY_DOTS;
  const points = new THREE.Points(
    pathGeometry(a.pointPos, a.pointCol),
    pathMaterial({ pointSize: fewDots ? 8 : 1, round: fewDots, ring: fewDots, onTop: true }),
  );
  points.renderOrder = 1;
  points.userData.moveOfHit = (hit) => pointMove[hit.index];
  scene.add(points);
  // The selected dot: a larger magenta one over it.
  const pointMark = new THREE.Points(pathGeometry(new Float32Array(3), Uint8Array.from([255, 0, 255])), pathMaterial({ pointSize: 13, round: true, onTop: true }));
  pointMark.visible = false;
  pointMark.renderOrder = 4; // over the tool, which the selection moves onto it
  scene.add(pointMark);

  // The selected move, 4 px wide over everything (WebGL draws plain lines 1 px wide).
  const highlightMaterial = new LineMaterial({ color: 0xff00ff, linewidth: 4, depthTest: false });
  const highlight = new Line2(new LineGeometry(), highlightMaterial);
  highlight.visible = false;
  highlight.renderOrder = 2;
  scene.add(highlight);
  const tool = new THREE.Points(pathGeometry(new Float32Array(3), Uint8Array.from([17, 17, 17])), pathMaterial({ pointSize: 11, round: true, onTop: true }));
  tool.renderOrder = 3;
  scene.add(tool);
  // Every vertex lies within half the size of the centre along each axis (a dot a little off
  // its vertex: within the whole size). Given, the spheres that culling and picking test first
  // need no pass over a million vertices.
  for (const object of [feedLines, rapidLines, points]) object.geometry.boundingSphere = new THREE.Sphere(new THREE.Vector3(), size);

  const renderer = takeRenderer(vertexCount);
  renderer.setPixelRatio(1);
  container.appendChild(renderer.domElement);
  const camera = new THREE.PerspectiveCamera(35, 1, size / 1000, size * 100);
  const distance = size * 1.75;
  if (hasY) {
    camera.up.set(0, 0, 1);
    camera.position.set(0.55 * distance, -0.8 * distance, 0.75 * distance);
  } else {
    // A lathe: X (radius) up the screen, Z across, as turning drawings show it.
    camera.up.set(1, 0, 0);
    camera.position.set(0, -distance, 0);
  }
  // A large path opens with its preview (path_preview.js) drawn in place of the full lines and
  // dots; drawFullPath() swaps them once the page is ready.
  let preview = null;
  if (a.feedIndex.length / 2 + pointMove.length > PREVIEW_FROM) {
    const tolerance = PREVIEW_TOLERANCE_PX * worldPerPixel(distance, size, camera.fov, container.clientHeight || 400, camera.near);
    const t0 = performance.now();
    const p = previewArrays(a, vertexEnd, tolerance);
    const ms = Math.round(performance.now() - t0);
    const lines = new THREE.LineSegments(pathGeometry(p.pos, p.col), pathMaterial());
    lines.geometry.setIndex(new THREE.BufferAttribute(p.index, 1));
    const dots = new THREE.Points(pathGeometry(p.dotPos, p.dotCol), pathMaterial({ pointSize: 1, onTop: true }));
    dots.renderOrder = 1;
    for (const object of [lines, dots]) {
      object.geometry.boundingSphere = new THREE.Sphere(new THREE.Vector3(), size);
      object.layers.set(1); // drawn, never picked (the raycaster tests layer 0)
      scene.add(object);
    }
    camera.layers.enable(1);
    feedLines.visible = false;
    points.visible = false;
    preview = { objects: [lines, dots], tolerance, segments: p.segments, dots: p.dots, ms, shown: true };
  }
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.addEventListener("change", () => render());

  let pending = false;
  function render() {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => {
      pending = false;
      renderer.render(scene, camera);
    });
  }
  function renderNow() {
    renderer.render(scene, camera);
  }
  let shownSize = "";
  function resize() {
    const w = container.clientWidth || 600;
    const h = container.clientHeight || 400;
    // The observer's first call repeats the size set below: drawing again would double the
    // first frame's cost.
    if (shownSize === w + "x" + h) return;
    shownSize = w + "x" + h;
    renderer.setSize(w, h, false);
    renderer.domElement.style.width = w + "px";
    renderer.domElement.style.height = h + "px";
    camera.aspect = w / h;
    highlightMaterial.resolution.set(w, h);
    camera.updateProjectionMatrix();
    // Drawn with the next frame, once: the first layout and the observer's first call both
    // come here, and on a million moves a frame is the costliest thing the page does.
    render();
  }
  new ResizeObserver(resize).observe(container);

  // Picking: the nearest line within a few pixels of the pointer.
  const raycaster = new THREE.Raycaster();
  let downAt = null;
  renderer.domElement.addEventListener("pointerdown", (e) => (downAt = [e.clientX, e.clientY]));
  renderer.domElement.addEventListener("pointerup", (e) => {
    if (!downAt || Math.hypot(e.clientX - downAt[0], e.clientY - downAt[1]) > 4) return;
    const m = pick(e.clientX, e.clientY);
    if (m >= 0) onPick(m);
  });
  function pick(clientX, clientY) {
    const rect = renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    // 5 pixels at the target's distance
    const worldPerPixel = (2 * camera.position.distanceTo(controls.target) * Math.tan((camera.fov * Math.PI) / 360)) / rect.height;
    raycaster.params.Line.threshold = 5 * worldPerPixel;
    raycaster.params.Points.threshold = 5 * worldPerPixel;
    // A dot is a small target on top of the lines through it: within its own radius it wins.
    const dots = raycaster.intersectObject(points, false).filter((h) => h.distanceToRay <= 4 * worldPerPixel * (h.distance / camera.position.distanceTo(controls.target)));
    if (dots.length) {
      dots.sort((p, q) => p.distanceToRay - q.distanceToRay);
      return pointMove[dots[0].index];
    }
    const hits = raycaster.intersectObjects([feedLines, rapidLines, points], false);
    if (!hits.length) return -1;
    hits.sort((p, q) => p.distanceToRay - q.distanceToRay || p.distance - q.distance);
    const hit = hits[0];
    return hit.object.userData.moveOfHit(hit);
  }

  //! Returns once the GPU has run every command given so far (reading a pixel waits for them).
  function finishFrame() {
    const gl = renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
  }

  //! Draws the preview (on) or the full path (off) with the next frame; the page shows the
  //! preview only until it is ready (the browser test compares the two).
  function showPreview(on) {
    if (!preview) return;
    for (const object of preview.objects) object.visible = on;
    feedLines.visible = !on;
    points.visible = !on;
    preview.shown = on;
    render();
  }

  //! Compiles the selection's wide-line shader while the page waits for input, so the first
  //! click does not wait for it (the first frame did not need it).
  function warmUp() {
    return renderer.compileAsync(highlight, camera, scene);
  }

  function moveRange(m) {
    const to = vertexEnd[m];
    const start = m > 0 ? vertexEnd[m - 1] : 0;
    return [start, to];
  }

  function select(m) {
    highlight.visible = false;
    pointMark.visible = false;
    if (m < 0) {
      render();
      return;
    }
    const p = pointOfMove[m];
    if (p >= 0) {
      pointMark.geometry.attributes.position.array.set(a.pointPos.subarray(3 * p, 3 * p + 3));
      pointMark.geometry.attributes.position.needsUpdate = true;
      pointMark.geometry.computeBoundingSphere();
      pointMark.visible = true;
      render();
      return;
    }
    const [from, to] = moveRange(m);
    const pos = a.vertexPos.slice(3 * from, 3 * to + 3);
    highlight.geometry.dispose();
    highlight.geometry = new LineGeometry();
    highlight.geometry.setPositions(pos);
    highlight.visible = true;
    render();
  }

  function placeTool(x, y, z) {
    tool.position.set(x - centre[0], y - centre[1], z - centre[2]);
    render();
  }

  function project(v) {
    const p = new THREE.Vector3(a.vertexPos[3 * v], a.vertexPos[3 * v + 1], a.vertexPos[3 * v + 2]).project(camera);
    const rect = renderer.domElement.getBoundingClientRect();
    return [rect.left + ((p.x + 1) / 2) * rect.width, rect.top + ((1 - p.y) / 2) * rect.height];
  }

  function toClient(p) {
    p.project(camera);
    const rect = renderer.domElement.getBoundingClientRect();
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }

  //! Pixels from the point (client coordinates) to the move's drawn polyline or dot.
  function distanceToMove(m, x, y) {
    if (pointOfMove[m] >= 0) {
      const q = screenPoint(m);
      return Math.hypot(q.x - x, q.y - y);
    }
    const [from, to] = moveRange(m);
    let best = Infinity;
    let p = project(from);
    for (let v = from + 1; v <= to; v++) {
      const q = project(v);
      const dx = q[0] - p[0], dy = q[1] - p[1];
      const len2 = dx * dx + dy * dy;
      const t = len2 > 0 ? Math.min(1, Math.max(0, ((x - p[0]) * dx + (y - p[1]) * dy) / len2)) : 0;
      best = Math.min(best, Math.hypot(p[0] + t * dx - x, p[1] + t * dy - y));
      p = q;
    }
    return best;
  }

  //! Client coordinates of the middle of a move's drawn polyline, or of its dot (for tests and
  //! for scrolling).
  function screenPoint(m) {
    const i = pointOfMove[m];
    if (i >= 0) return toClient(new THREE.Vector3().fromArray(a.pointPos, 3 * i));
    const [from, to] = moveRange(m);
    const v = Math.floor((from + to) / 2);
    const w = Math.min(v + 1, to);
    const p = new THREE.Vector3().fromArray(a.vertexPos, 3 * v).add(new THREE.Vector3().fromArray(a.vertexPos, 3 * w)).multiplyScalar(0.5);
    return toClient(p);
  }

  // Moves the GPU is given something of: a feed segment, a rapid segment or a dot.
  const drawn = new Uint8Array(moveCount);
  for (let i = 1; i < a.feedIndex.length; i += 2) drawn[a.feedMoveOfStart[a.feedIndex[i - 1]]] = 1;
  for (const m of a.rapidMove) drawn[m] = 1;
  for (const m of pointMove) drawn[m] = 1;
  let drawnCount = 0;
  for (let m = 0; m < moveCount; m++) drawnCount += drawn[m];
  resize();
  const previewInfo = preview && { tolerancePx: PREVIEW_TOLERANCE_PX, toleranceMm: preview.tolerance, segments: preview.segments, dots: preview.dots, ms: preview.ms };
  return { preview: previewInfo, drawFullPath: () => showPreview(false), showPreview, fullPathShown: () => !preview || !preview.shown, select, placeTool, screenPoint, distanceToMove, pick, warmUp, finishFrame, dotMoves: pointMove, dotsRimmed: fewDots, drawnSegments: drawnCount, canvas: renderer.domElement, render: renderNow };
}
