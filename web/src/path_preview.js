// The first frame of a large path: the feed lines thinned so that every point of them stays
// within PREVIEW_TOLERANCE_PX screen pixels of the full drawing in the opening view, and the
// dots that lie that close to a drawn line left out. Without a GPU (SwiftShader) drawing a
// million segments and dots is most of the time a large page needs to open; the thinned path
// looks the same in the opening view, and the full one replaces it as soon as the page is
// ready (picking always uses the full path, so every move stays clickable throughout).

//! Screen pixels the preview may differ from the full path by, in the opening view.
export const PREVIEW_TOLERANCE_PX = 1;
//! A path with more feed segments and dots than this opens with a preview.
export const PREVIEW_FROM = 100000;
// A chord spans at most this many segments: keeps the chord test's cost bounded (it checks
// every point under the chord, so a longer span costs its square).
const MAX_SPAN = 64;

//! Squared distance from the point (x, y, z) to the segment a–b (vertex indices into pos).
function distance2ToSegment(x, y, z, pos, a, b) {
  const ax = pos[3 * a], ay = pos[3 * a + 1], az = pos[3 * a + 2];
  const dx = pos[3 * b] - ax, dy = pos[3 * b + 1] - ay, dz = pos[3 * b + 2] - az;
  const px = x - ax, py = y - ay, pz = z - az;
  const len2 = dx * dx + dy * dy + dz * dz;
  const t = len2 > 0 ? Math.min(1, Math.max(0, (px * dx + py * dy + pz * dz) / len2)) : 0;
  const ex = px - t * dx, ey = py - t * dy, ez = pz - t * dz;
  return ex * ex + ey * ey + ez * ez;
}

//! Every vertex strictly between a and c within the tolerance of the chord a–c.
function chordHolds(pos, a, c, tolerance2) {
  for (let p = a + 1; p < c; p++) {
    if (distance2ToSegment(pos[3 * p], pos[3 * p + 1], pos[3 * p + 2], pos, a, c) > tolerance2) return false;
  }
  return true;
}

//! World units that one screen pixel covers at most in the opening view: at the nearest depth
//! any drawn point can have (the camera looks at the centre from `distance`, every point lies
//! within `radius` of the centre).
export function worldPerPixel(distance, radius, fovDeg, heightPx, near) {
  const depth = Math.max(distance - radius, near);
  return (2 * depth * Math.tan((fovDeg * Math.PI) / 360)) / heightPx;
}

//! The preview of pathArrays `a` (vertexEnd: per move, as the page stores it) at `tolerance`
//! world units: feed lines as kept vertices (positions, colours, index pairs) and the dots that
//! stay. A line moves by at most a quarter of the tolerance; a dot is left out only when it
//! lies within three quarters of it from a segment of the full path near its move's vertex,
//! so within the tolerance of the drawn preview.
export function previewArrays(a, vertexEnd, tolerance) {
  const { vertexPos, vertexCol, feedIndex, rapidMove, pointPos, pointCol, pointMove } = a;
  const line2 = (tolerance / 4) ** 2;
  const dot2 = ((3 * tolerance) / 4) ** 2;
  const kept = [];
  const pairs = [];
  // Feed segments come in vertex order; a run is a stretch of consecutive segments.
  let i = 0;
  while (i < feedIndex.length) {
    const start = feedIndex[i];
    let end = feedIndex[i + 1];
    i += 2;
    while (i < feedIndex.length && feedIndex[i] === end) {
      end = feedIndex[i + 1];
      i += 2;
    }
    let anchor = start;
    let keptAt = kept.length;
    kept.push(start);
    for (let v = start + 1; v <= end; v++) {
      const last = v === end;
      if (last || v + 1 - anchor > MAX_SPAN || !chordHolds(vertexPos, anchor, v + 1, line2)) {
        kept.push(v);
        pairs.push(keptAt, kept.length - 1);
        keptAt = kept.length - 1;
        anchor = v;
      }
    }
  }
  const pos = new Float32Array(3 * kept.length);
  const col = new Uint8Array(4 * kept.length);
  kept.forEach((v, k) => {
    pos.set(vertexPos.subarray(3 * v, 3 * v + 3), 3 * k);
    col.set(vertexCol.subarray(4 * v, 4 * v + 4), 4 * k);
  });

  // Segments of the full path that the preview draws (within its tolerance): drawn[u] when
  // the segment from vertex u to u + 1 is a feed or rapid segment.
  const drawn = new Uint8Array(vertexPos.length / 3);
  for (let k = 0; k < feedIndex.length; k += 2) drawn[feedIndex[k]] = 1;
  for (let r = 0; r < rapidMove.length; r++) {
    const m = rapidMove[r];
    if (r > 0 && rapidMove[r - 1] === m) continue; // a move's segments follow each other
    for (let u = m > 0 ? vertexEnd[m - 1] : 0; u < vertexEnd[m]; u++) drawn[u] = 1;
  }
  // Within dot2 of a drawn segment among the MAX_SPAN on either side of vertex v, nearest
  // first (a run of dots sits along the polyline of the move before or after it). The segment
  // the previous dot was near is tried first: the next dot of a run is mostly near it too.
  const segmentCount = vertexPos.length / 3 - 1;
  let hint = -1;
  const near = (x, y, z, u) => u >= 0 && u < segmentCount && drawn[u] && distance2ToSegment(x, y, z, vertexPos, u, u + 1) <= dot2;
  function nearDrawn(x, y, z, v) {
    if (hint >= v - MAX_SPAN && hint < v + MAX_SPAN) {
      for (const u of [hint, hint - 1, hint + 1]) if (near(x, y, z, u)) return (hint = u), true;
    }
    for (let k = 0; k < MAX_SPAN; k++) {
      if (near(x, y, z, v - 1 - k)) return (hint = v - 1 - k), true;
      if (near(x, y, z, v + k)) return (hint = v + k), true;
    }
    return false;
  }
  const dots = [];
  for (let p = 0; p < pointMove.length; p++) {
    const v = vertexEnd[pointMove[p]];
    const x = pointPos[3 * p], y = pointPos[3 * p + 1], z = pointPos[3 * p + 2];
    if (!nearDrawn(x, y, z, v)) dots.push(p);
  }
  const dotPos = new Float32Array(3 * dots.length);
  const dotCol = new Uint8Array(4 * dots.length);
  dots.forEach((p, k) => {
    dotPos.set(pointPos.subarray(3 * p, 3 * p + 3), 3 * k);
    dotCol.set(pointCol.subarray(4 * p, 4 * p + 4), 4 * k);
  });
  return { pos, col, index: Uint32Array.from(pairs), dotPos, dotCol, segments: pairs.length / 2, dots: dots.length };
}
