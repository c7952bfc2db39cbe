// The typed arrays the path view draws and picks from, made from the page's moves and vertices
// in one pass each (no per-move objects: a million moves stay a few arrays).
import { speedColor } from "./colors.js";

const RAPID = 0;

//! moveKind, vertexEnd: per move; xyz: the vertices (3 per vertex); speed: a byte per vertex;
//! pointOffset, pointSpeed: where each move with an empty polyline is drawn, in move order, as
//! its offset from the vertex it ends at (3 per such move), and the speed byte there (absent:
//! at that vertex, with its speed).
export function pathArrays({ moveKind, vertexEnd, xyz, speed, pointOffset, pointSpeed }) {
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
  // shared by two segments is stored once.
  const vertexPos = new Float32Array(vertexCount * 3);
  for (let i = 0; i < vertexCount * 3; i += 3) {
    vertexPos[i] = xyz[i] - centre[0];
    vertexPos[i + 1] = xyz[i + 1] - centre[1];
    vertexPos[i + 2] = xyz[i + 2] - centre[2];
  }
  const ramp = new Uint8Array(256 * 3);
  const rgb = [0, 0, 0];
  for (let level = 0; level < 256; level++) {
    speedColor(level / 255, rgb, 0);
    for (let k = 0; k < 3; k++) ramp[3 * level + k] = Math.round(255 * rgb[k]);
  }
  // RGBA: see pathGeometry.
  const vertexCol = new Uint8Array(vertexCount * 4).fill(255);
  for (let i = 0; i < vertexCount; i++) {
    const at = 3 * speed[i];
    vertexCol[4 * i] = ramp[at];
    vertexCol[4 * i + 1] = ramp[at + 1];
    vertexCol[4 * i + 2] = ramp[at + 2];
  }

  let feedCount = 0;
  let rapidCount = 0;
  let pointCount = 0;
  let from = 0;
  for (let m = 0; m < moveCount; m++) {
    const n = vertexEnd[m] - from;
    if (n === 0) pointCount++;
    else if (moveKind[m] === RAPID) rapidCount += n;
    else feedCount += n;
    from = vertexEnd[m];
  }
  const feedIndex = new Uint32Array(feedCount * 2);
  // The move of the feed segment that starts at a vertex (picking reports that vertex).
  const feedMoveOfStart = new Uint32Array(vertexCount);
  // Rapids stay unindexed: the dashes need each segment's own distances along the line.
  const rapidPos = new Float32Array(rapidCount * 6);
  const rapidDistance = new Float32Array(rapidCount * 2);
  const rapidMove = new Uint32Array(rapidCount);
  const pointMove = new Uint32Array(pointCount);
  const pointPos = new Float32Array(pointCount * 3);
  const pointCol = new Uint8Array(pointCount * 4).fill(255);
  // Per move: its index among the point moves, or -1.
  const pointOfMove = new Int32Array(moveCount).fill(-1);
  let f = 0;
  let r = 0;
  let p = 0;
  from = 0;
  for (let m = 0; m < moveCount; m++) {
    const to = vertexEnd[m];
    if (to === from) {
      // A move with no polyline of its own: a dot where the page says it is.
      const placed = pointOffset && pointSpeed && pointOffset.length >= 3 * (p + 1);
      for (let k = 0; k < 3; k++) {
        const vertex = vertexCount ? xyz[3 * to + k] : 0;
        pointPos[3 * p + k] = vertex + (placed ? pointOffset[3 * p + k] : 0) - centre[k];
      }
      const level = placed ? pointSpeed[p] : vertexCount ? speed[to] : 0;
      pointCol.set(ramp.subarray(3 * level, 3 * level + 3), 4 * p);
      pointOfMove[m] = p;
      pointMove[p++] = m;
    } else if (moveKind[m] === RAPID) {
      for (let v = from; v < to; v++) {
        rapidPos.set(vertexPos.subarray(3 * v, 3 * v + 6), 6 * r);
        const dx = vertexPos[3 * v + 3] - vertexPos[3 * v];
        const dy = vertexPos[3 * v + 4] - vertexPos[3 * v + 1];
        const dz = vertexPos[3 * v + 5] - vertexPos[3 * v + 2];
        rapidDistance[2 * r + 1] = Math.hypot(dx, dy, dz);
        rapidMove[r++] = m;
      }
    } else {
      for (let v = from; v < to; v++) {
        feedIndex[2 * f] = v;
        feedIndex[2 * f + 1] = v + 1;
        f++;
        feedMoveOfStart[v] = m;
      }
    }
    from = to;
  }
  return {
    moveCount, vertexCount, centre, size, vertexPos, vertexCol, feedIndex, feedMoveOfStart,
    rapidPos, rapidDistance, rapidMove, pointMove, pointPos, pointCol, pointOfMove,
  };
}
