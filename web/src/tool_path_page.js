// The program page: figures, the 3D path with its legend and time slider, the code pane, where
// the feed was not reached, and the axis charts. Selection links the path, the code and the
// slider both ways.
import { createPathView } from "./path_view.js";
import { createCodePane } from "./code_pane.js";
import { axisCharts, speedChart } from "./charts.js";
import { cssColor } from "./colors.js";
import { el, figureTable } from "./dom.js";

const KINDS = ["rapid", "feed", "arc", "thread"];
const SLOWDOWNS = ["", "corner", "arc limit", "short segment", "exact stop", "axis limit"];

export function buildToolPathPage(root, header, blob) {
  const timings = {};
  let mark = performance.now();
  const lap = (name) => {
    const now = performance.now();
    timings[name] = Math.round(now - mark);
    mark = now;
  };
  const tp = header.tool_path;
  const moveKind = blob("move_kind");
  const moveLine = blob("move_line");
  const moveFile = blob("move_file");
  const vertexEnd = blob("move_vertex_end");
  // Each move's start and end time are needed only once a move is selected: unpacked then
  // (two million numbers on a large program, a good part of the unpacking).
  const start = (m) => blob("move_start_s")[m];
  const end = (m) => blob("move_end_s")[m];
  const feed = blob("move_feed_mm_s");
  const peak = blob("move_peak_mm_s");
  const slow = blob("move_slowdown");
  const xyz = blob("vertex_xyz");
  const speed = blob("vertex_speed");
  const pointOffset = header.blobs.point_offset_xyz ? blob("point_offset_xyz") : null;
  const pointSpeed = header.blobs.point_speed ? blob("point_speed") : null;
  const axes = tp.samples.axes;
  const samples = { t: blob("sample_t"), speed: blob("sample_speed"), pos: {}, vel: {}, acc: {}, jerk: {} };
  for (const a of axes) {
    samples.pos[a] = blob("sample_pos_" + a);
    samples.vel[a] = blob("sample_vel_" + a);
    samples.acc[a] = blob("sample_acc_" + a);
    samples.jerk[a] = blob("sample_jerk_" + a);
  }
  const sources = tp.files.map((_, i) => blob.bytes("source_" + i));
  const moveCount = moveKind.length;
  lap("unpack");

  // First move of each source line, per file: an array indexed by line (-1: no move).
  const lineCount = tp.files.map((_, i) => 0);
  for (let m = 0; m < moveCount; m++) if (moveLine[m] > lineCount[moveFile[m]]) lineCount[moveFile[m]] = moveLine[m];
  const firstMoveOfLine = lineCount.map((n) => new Int32Array(n + 1).fill(-1));
  for (let m = moveCount - 1; m >= 0; m--) firstMoveOfLine[moveFile[m]][moveLine[m]] = m;
  const firstMove = firstMoveOfLine.map((table) => ({
    get: (line) => (line < table.length && table[line] >= 0 ? table[line] : undefined),
  }));

  const figures = [
    ["cycle time", `<span id="cycle-time" data-seconds="${tp.cycle_time_s}">${tp.cycle_time_s.toFixed(6)}</span> s`],
    ["moves", String(tp.moves)],
    ["machine", `${tp.machine.name || "built-in mill"} (${tp.machine.profile})`],
    ["drawn points", `${tp.vertices} of ${tp.points_before_decimation + (tp.vertices ? 1 : 0)} planned (tolerance ${tp.tolerance_mm} mm)`],
  ];
  root.appendChild(figureTable(figures, true));

  const main = el("div", "main-grid");
  const viewBox = el("div", "view-box");
  const view3d = el("div", "view3d");
  const legend = el("div", "legend");
  const slider = el("input", "time-slider");
  slider.type = "range";
  slider.min = "0";
  slider.max = String(Math.max(0, samples.t.length - 1));
  slider.value = "0";
  const timeLabel = el("div", "time-label");
  const info = el("div", "move-info");
  viewBox.append(view3d, legend, slider, timeLabel, info);
  const codeBox = el("div", "code-box");
  main.append(viewBox, codeBox);
  root.appendChild(main);

  const top = tp.top_speed_mm_s * 60;
  legend.innerHTML =
    `<div class="legend-bar" style="background:linear-gradient(to right,${[0, 0.15, 0.35, 0.55, 0.75, 0.9, 1].map(cssColor).join(",")})"></div>` +
    `<div class="legend-labels"><span>0</span><span>planned speed, mm/min</span><span>${top.toFixed(0)}</span></div>` +
    `<div class="legend-note">dashed grey: rapids · magenta: selected move · black dot: the tool at the slider's time</div>`;

  let selected = -1;
  lap("figures");
  const path = createPathView(view3d, { moveKind, vertexEnd, xyz, speed, pointOffset, pointSpeed, hasY: axes.includes("Y") }, (m) => select(m, true));
  lap("path");
  const code = createCodePane(codeBox, tp.files, sources, (file, line) => {
    const m = firstMove[file].get(line);
    select(m === undefined ? -1 : m, false, [file, line]);
  });

  lap("code");

  function select(m, fromPath, lineOnly) {
    selected = m;
    path.select(m);
    if (m >= 0) {
      code.mark(moveFile[m], moveLine[m]);
      const reason = slow[m] ? ` · feed not reached: <b>${SLOWDOWNS[slow[m]]}</b>` : "";
      info.innerHTML =
        `move ${m + 1}: ${KINDS[moveKind[m]]}, line ${moveLine[m]} · ` +
        (moveKind[m] === 0 ? "" : `F ${(feed[m] * 60).toFixed(1)} mm/min, `) +
        `planned peak ${(peak[m] * 60).toFixed(1)} mm/min · t ${start(m).toFixed(4)}–${end(m).toFixed(4)} s${reason}`;
      if (fromPath) setTime(indexAt(start(m)), true);
    } else if (lineOnly) {
      code.mark(lineOnly[0], lineOnly[1]);
      info.textContent = `line ${lineOnly[1]}: no move`;
    }
    state.selectedMove = m;
    state.selectedLine = m >= 0 ? moveLine[m] : lineOnly ? lineOnly[1] : 0;
  }

  function indexAt(t) {
    let lo = 0, hi = samples.t.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (samples.t[mid] <= t) lo = mid;
      else hi = mid - 1;
    }
    return lo;
  }

  function setTime(i, keepSelection) {
    if (!samples.t.length) return;
    slider.value = String(i);
    const p = axes.map((a) => samples.pos[a][i]);
    const get = (a) => (axes.includes(a) ? samples.pos[a][i] : 0);
    path.placeTool(get("X"), get("Y"), get("Z"));
    timeLabel.textContent =
      `t = ${samples.t[i].toFixed(4)} s of ${tp.cycle_time_s.toFixed(4)} s · ` +
      axes.map((a, k) => `${a} ${p[k].toFixed(3)}`).join("  ") +
      ` · speed ${(samples.speed[i] * 60).toFixed(1)} mm/min`;
    state.sliderTime = samples.t[i];
    state.toolAt = { index: i, t: samples.t[i], position: Object.fromEntries(axes.map((a, k) => [a, p[k]])) };
    if (!keepSelection) {
      // The move running at that time.
      let lo = 0, hi = moveCount - 1;
      while (lo < hi) {
        const mid = (lo + hi + 1) >> 1;
        if (start(mid) <= samples.t[i]) lo = mid;
        else hi = mid - 1;
      }
      if (moveCount) select(lo, false);
    }
  }
  slider.addEventListener("input", () => setTime(Number(slider.value), false));

  // Where the feed was not reached.
  const slowBox = el("section", "slowdowns");
  slowBox.appendChild(el("h2", null, "Where the programmed feed was not reached"));
  const counts = Object.entries(tp.slowdowns);
  slowBox.appendChild(
    counts.length
      ? figureTable(counts.map(([k, v]) => [k, `${v.moves} move(s), ${v.time_s.toFixed(4)} s`]))
      : el("p", null, "Every feed move reached its programmed feed (within 1 %)."),
  );
  const table = el("table", "slow-table");
  table.innerHTML = "<thead><tr><th>line</th><th>move</th><th>F mm/min</th><th>planned peak mm/min</th><th>why</th></tr></thead>";
  const body = el("tbody");
  let listed = 0;
  for (let m = 0; m < moveCount && listed < 500; m++) {
    if (!slow[m]) continue;
    const row = el("tr");
    row.innerHTML = `<td>${moveLine[m]}</td><td>${m + 1}</td><td>${(feed[m] * 60).toFixed(1)}</td><td>${(peak[m] * 60).toFixed(1)}</td><td>${SLOWDOWNS[slow[m]]}</td>`;
    row.addEventListener("click", () => select(m, true));
    body.appendChild(row);
    listed++;
  }
  table.appendChild(body);
  if (listed) slowBox.appendChild(table);
  if (listed === 500) slowBox.appendChild(el("p", null, "(the first 500 are listed)"));
  root.appendChild(slowBox);

  // Peaks against limits.
  const peakBox = el("section");
  peakBox.appendChild(el("h2", null, "Each axis's peaks against its limits"));
  const pt = el("table", "peak-table");
  pt.innerHTML =
    "<thead><tr><th>axis</th><th>max |v|</th><th>limit</th><th>max |a|</th><th>limit</th><th>max |j|</th><th>limit</th></tr></thead>";
  const pb = el("tbody");
  tp.machine.axes.forEach((ax) => {
    const p = tp.peaks[ax.name];
    const u = ax.rotary ? "deg" : "mm";
    const row = el("tr");
    row.innerHTML = `<td>${ax.name}</td><td>${p.max_velocity.toFixed(3)} ${u}/s</td><td>${ax.max_velocity}</td><td>${p.max_acceleration.toFixed(3)} ${u}/s²</td><td>${ax.max_acceleration}</td><td>${p.max_jerk.toFixed(1)} ${u}/s³</td><td>${ax.max_jerk}</td>`;
    pb.appendChild(row);
  });
  pt.appendChild(pb);
  peakBox.appendChild(pt);
  root.appendChild(peakBox);

  lap("tables");
  // The charts lie below the first screen: they are drawn once they come within 200 px of
  // it. Without a GPU their canvases are rasterised by SwiftShader in the GPU process, whose
  // queue the 3D view's first frame shares: drawn at load they held that frame back by 1-2 s
  // on every page, large or small.
  const chartBox = el("section", "charts");
  chartBox.appendChild(el("h2", null, "Planned motion against time"));
  const chartSpace = el("div", "chart-space");
  chartBox.appendChild(chartSpace);
  root.appendChild(chartBox);
  let chartCount = 0;
  function drawCharts() {
    if (chartCount) return;
    chartSpace.remove();
    speedChart(chartBox, samples);
    chartCount = 1 + axisCharts(chartBox, samples, axes, tp.machine.axes, (i) => setTime(i, false)).length;
  }
  const chartWatch = new IntersectionObserver(
    (entries) => {
      if (!entries.some((e) => e.isIntersecting)) return;
      chartWatch.disconnect();
      drawCharts();
    },
    { rootMargin: "200px 0px" },
  );
  chartWatch.observe(chartBox);

  lap("charts");
  const state = {
    timings,
    moves: moveCount,
    drawnSegments: path.drawnSegments,
    selectedMove: -1,
    selectedLine: 0,
    sliderTime: 0,
    cycleTimeText: () => document.getElementById("cycle-time").textContent,
    segmentScreenPoint: (m) => path.screenPoint(m),
    distanceToMove: (m, x, y) => path.distanceToMove(m, x, y),
    setSlider: (i) => setTime(i, false),
    samplePeriod: tp.samples.period_s,
    lineOfMove: (m) => [moveFile[m], moveLine[m]],
    firstMoveOf: (file, line) => {
      const m = firstMove[file].get(line);
      return m === undefined ? -1 : m;
    },
    showLine: (file, line) => code.reveal(file, line),
    markedLine: () => {
      const row = document.querySelector(".code-line.selected");
      return row ? Number(row.dataset.line) : 0;
    },
    sampleCount: samples.t.length,
    canvas: path.canvas,
    renderNow: () => path.render(),
    warmUp: () => path.warmUp(),
    finishFrame: () => path.finishFrame(),
    preview: path.preview,
    drawFullPath: () => path.drawFullPath(),
    fullPathShown: () => path.fullPathShown(),
    showPreview: (on) => path.showPreview(on),
    dotMoves: () => Array.from(path.dotMoves),
    dotsRimmed: path.dotsRimmed,
    chartsDrawn: () => chartCount,
    select: (m) => select(m, true),
  };
  setTime(0, true);
  return state;
}
