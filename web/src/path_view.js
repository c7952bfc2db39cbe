// The 3D tool path: feed moves as lines coloured by planned speed, rapids dashed, a marker for
// the tool, picking by mouse. Renders only when something changed.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { Line2 } from "three/addons/lines/Line2.js";
import { LineGeometry } from "three/addons/lines/LineGeometry.js";
import { LineMaterial } from "three/addons/lines/LineMaterial.js";
import { speedColor } from "./colors.js";

const RAPID = 0;
const LARGE_PATH_VERTICES = 200000;

export function createPathView(container, path, onPick) {
  const { moveKind, vertexEnd, xyz, speed, hasY } = path;
  const moveCount = moveKind.length;
  const vertexCount = xyz.length / 3;

  // Centre of the bounding box: float32 positions relative to it keep their precision.
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < vertexCount; i++) {
    for (let k = 0; k < 3; k++) {
      const v = xyz[3 * i + k];
      if (v < min[k]) min[k] = v;
      if (v > max[k]) max[k] = v;
    }
  }
  if (vertexCount === 0) min.fill(0), max.fill(0);
  const centre = min.map((m, k) => (m + max[k]) / 2);
  const size = Math.max(1e-3, ...max.map((m, k) => m - min[k]));

  // Every vertex once, relative to the centre, coloured by its planned speed (a 256-entry table:
  // the page stores the speed as a byte). Feed moves index pairs of these vertices, so a vertex
  // shared by two segments is stored once; each pair remembers its move for picking.
  const vertexPos = new Float32Array(vertexCount * 3);
  for (let i = 0; i < vertexCount; i++) {
    for (let k = 0; k < 3; k++) vertexPos[3 * i + k] = xyz[3 * i + k] - centre[k];
  }
  const ramp = new Uint8Array(256 * 3);
  const rgb = [0, 0, 0];
  for (let level = 0; level < 256; level++) {
    speedColor(level / 255, rgb, 0);
    for (let k = 0; k < 3; k++) ramp[3 * level + k] = Math.round(255 * rgb[k]);
  }
  const vertexCol = new Uint8Array(vertexCount * 3);
  for (let i = 0; i < vertexCount; i++) vertexCol.set(ramp.subarray(3 * speed[i], 3 * speed[i] + 3), 3 * i);

  let feedCount = 0;
  let rapidCount = 0;
  let from = 0;
  for (let m = 0; m < moveCount; m++) {
    const n = vertexEnd[m] - from;
    if (moveKind[m] === RAPID) rapidCount += n;
    else feedCount += n;
    from = vertexEnd[m];
  }
  const feedIndex = new Uint32Array(feedCount * 2);
  // The move of the feed segment that starts at a vertex (picking reports that vertex).
  const feedMoveOfStart = new Uint32Array(vertexCount);
  // Rapids stay unindexed: the dashes need each segment's own distances along the line.
  const rapidPos = new Float32Array(rapidCount * 6);
  const rapidMove = new Uint32Array(rapidCount);
  const drawn = new Uint8Array(moveCount);
  const pointMoves = [];
  let f = 0;
  let r = 0;
  from = 0;
  for (let m = 0; m < moveCount; m++) {
    const to = vertexEnd[m];
    if (to === from) pointMoves.push(m);
    else drawn[m] = 1;
    if (moveKind[m] === RAPID) {
      for (let v = from; v < to; v++) {
        rapidPos.set(vertexPos.subarray(3 * v, 3 * v + 6), 6 * r);
        rapidMove[r++] = m;
      }
    } else {
      for (let v = from; v < to; v++) {
        feedIndex[2 * f++] = v;
        feedIndex[2 * f - 1] = v + 1;
        feedMoveOfStart[v] = m;
      }
    }
    from = to;
  }

  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf7f7f4);
  const feedGeometry = new THREE.BufferGeometry();
  feedGeometry.setAttribute("position", new THREE.BufferAttribute(vertexPos, 3));
  feedGeometry.setAttribute("color", new THREE.BufferAttribute(vertexCol, 3, true));
  feedGeometry.setIndex(new THREE.BufferAttribute(feedIndex, 1));
  const feedLines = new THREE.LineSegments(feedGeometry, new THREE.LineBasicMaterial({ vertexColors: true }));
  feedLines.userData.moveOfHit = (hit) => feedMoveOfStart[hit.index];
  scene.add(feedLines);
  const rapidGeometry = new THREE.BufferGeometry();
  rapidGeometry.setAttribute("position", new THREE.BufferAttribute(rapidPos, 3));
  const rapidLines = new THREE.LineSegments(
    rapidGeometry,
    new THREE.LineDashedMaterial({ color: 0x777777, dashSize: size / 150, gapSize: size / 150 }),
  );
  rapidLines.computeLineDistances();
  rapidLines.userData.moveOfHit = (hit) => rapidMove[hit.index / 2];
  scene.add(rapidLines);
  // Moves that go nowhere (a G1 to where the tool stands) are drawn as points.
  const pointPos = new Float32Array(pointMoves.length * 3);
  pointMoves.forEach((m, i) => {
    const v = vertexEnd[m];
    for (let k = 0; k < 3; k++) pointPos[3 * i + k] = vertexCount ? xyz[3 * v + k] - centre[k] : 0;
    drawn[m] = 1;
  });
  const pointGeometry = new THREE.BufferGeometry();
  pointGeometry.setAttribute("position", new THREE.BufferAttribute(pointPos, 3));
  const points = new THREE.Points(pointGeometry, new THREE.PointsMaterial({ color: 0x555555, size: 3, sizeAttenuation: false }));
  const pointMove = Uint32Array.from(pointMoves);
  points.userData.moveOfHit = (hit) => pointMove[hit.index];
  scene.add(points);

  // The selected move, 4 px wide over everything (WebGL draws plain lines 1 px wide).
  const highlightMaterial = new LineMaterial({ color: 0xff00ff, linewidth: 4, depthTest: false });
  const highlight = new Line2(new LineGeometry(), highlightMaterial);
  highlight.visible = false;
  highlight.renderOrder = 2;
  scene.add(highlight);
  const tool = new THREE.Mesh(
    new THREE.SphereGeometry(size / 120, 16, 12),
    new THREE.MeshBasicMaterial({ color: 0x111111, depthTest: false }),
  );
  tool.renderOrder = 3;
  scene.add(tool);

  // Multisampling smooths the lines but costs every fragment several samples: on a large path
  // (drawn on the CPU where there is no GPU) it is most of the time to the first frame.
  const renderer = new THREE.WebGLRenderer({ antialias: vertexCount < LARGE_PATH_VERTICES, preserveDrawingBuffer: true });
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
  function resize() {
    const w = container.clientWidth || 600;
    const h = container.clientHeight || 400;
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
    const hits = raycaster.intersectObjects([feedLines, rapidLines, points], false);
    if (!hits.length) return -1;
    hits.sort((a, b) => a.distanceToRay - b.distanceToRay || a.distance - b.distance);
    const hit = hits[0];
    return hit.object.userData.moveOfHit(hit);
  }

  function moveRange(m) {
    const to = vertexEnd[m];
    const start = m > 0 ? vertexEnd[m - 1] : 0;
    return [start, to];
  }

  function select(m) {
    if (m < 0) {
      highlight.visible = false;
      render();
      return;
    }
    const [a, b] = moveRange(m);
    // A move that goes nowhere is shown as a short stub so it can be seen at all.
    const count = Math.max(2, b - a + 1);
    const pos = new Float32Array(count * 3);
    for (let i = 0; i < count; i++) {
      const v = Math.min(a + i, b);
      for (let k = 0; k < 3; k++) pos[3 * i + k] = (vertexCount ? xyz[3 * v + k] - centre[k] : 0) + (b === a && i === 1 && k === 0 ? size / 200 : 0);
    }
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
    const p = new THREE.Vector3(xyz[3 * v] - centre[0], xyz[3 * v + 1] - centre[1], xyz[3 * v + 2] - centre[2]).project(camera);
    const rect = renderer.domElement.getBoundingClientRect();
    return [rect.left + ((p.x + 1) / 2) * rect.width, rect.top + ((1 - p.y) / 2) * rect.height];
  }

  //! Pixels from the point (client coordinates) to the move's drawn polyline.
  function distanceToMove(m, x, y) {
    const [a, b] = moveRange(m);
    if (!vertexCount) return Infinity;
    let best = Infinity;
    let p = project(a);
    if (a === b) return Math.hypot(p[0] - x, p[1] - y);
    for (let v = a + 1; v <= b; v++) {
      const q = project(v);
      const dx = q[0] - p[0], dy = q[1] - p[1];
      const len2 = dx * dx + dy * dy;
      const t = len2 > 0 ? Math.min(1, Math.max(0, ((x - p[0]) * dx + (y - p[1]) * dy) / len2)) : 0;
      best = Math.min(best, Math.hypot(p[0] + t * dx - x, p[1] + t * dy - y));
      p = q;
    }
    return best;
  }

  //! Client coordinates of the middle of a move's drawn polyline (for tests and for scrolling).
  function screenPoint(m) {
    const [a, b] = moveRange(m);
    const v = Math.floor((a + b) / 2);
    const w = v === b || a === b ? null : v + 1;
    const p = new THREE.Vector3();
    for (let k = 0; k < 3; k++) {
      const here = xyz[3 * v + k] - centre[k];
      p.setComponent(k, w === null ? here : (here + xyz[3 * w + k] - centre[k]) / 2);
    }
    p.project(camera);
    const rect = renderer.domElement.getBoundingClientRect();
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }

  let drawnCount = 0;
  for (let m = 0; m < moveCount; m++) drawnCount += drawn[m];
  resize();
  return { select, placeTool, screenPoint, distanceToMove, pick, drawnSegments: drawnCount, canvas: renderer.domElement, render: renderNow };
}
