// nckit's report page: reads the inline data and builds the page. window.nckitReport exposes
// what the page shows (for the browser tests and for scripting it from the console).
import "uplot/dist/uPlot.min.css";
import "./style.css";
import { readPayload, unpackHere } from "./payload.js";
import { startPayload } from "./payload_worker.js";
import { buildToolPathPage } from "./tool_path_page.js";
import { xyChart } from "./charts.js";
import { el, figureTable } from "./dom.js";
import { startRenderer } from "./early_gl.js";

async function start(t0, payload) {
  const parsedMs = performance.now() - t0;
  const root = document.getElementById("app");
  const { header, blob, bytes, timings } = readPayload(await payload.finish(unpackHere));
  const payloadMs = performance.now() - t0;
  root.appendChild(el("h1", null, header.title));
  let state = {};
  if (header.figures.length) root.appendChild(figureTable(header.figures));
  if (header.charts.length) {
    const box = el("section", "charts process-charts");
    root.appendChild(box);
    for (const chart of header.charts) xyChart(box, chart, blob);
  }
  if (header.tool_path) {
    const section = el("section", "tool-path");
    if (header.kind !== "program") section.appendChild(el("h2", null, "Tool path of the program"));
    root.appendChild(section);
    state = buildToolPathPage(section, header, blob);
  }
  const footer = el("footer", null, "nckit report · data " + (bytes / 1e6).toFixed(2) + " MB unpacked");
  root.appendChild(footer);
  // Ready once the first frame is drawn. A page with a 3D view: its first animation frame
  // draws the path (the view asked for that frame before this), then a wait until the GPU has
  // carried that out, which on a million moves may trail the page's own work by seconds. Other
  // pages: two animation frames.
  const builtMs = performance.now() - t0;
  performance.mark("built");
  const frame = () => new Promise((resolve) => requestAnimationFrame(resolve));
  await frame();
  if (state.finishFrame) state.finishFrame();
  else await frame();
  performance.mark("ready");
  // startMs: from the start of navigation to this script; parsedMs: from there until the
  // browser has read the data after it; payloadMs: until base64 and gzip of the data are
  // undone; builtMs: until the page's parts are made; buildMs: from this script's start until
  // the first frame is drawn.
  window.nckitReport = Object.assign(state, {
    ready: true,
    kind: header.kind,
    charts: header.charts.length,
    startMs: t0,
    parsedMs,
    payloadMs,
    payloadTimings: timings,
    builtMs,
    buildMs: performance.now() - t0,
  });
  // A large path's first frame was its preview: the full path is drawn with the next frame,
  // while the page already answers input.
  if (state.drawFullPath) state.drawFullPath();
  if (state.warmUp) await state.warmUp();
}

// The script comes before the data in the page: begin the WebGL work now, unpack the data as
// the browser reads it.
const t0 = performance.now();
// The data's pieces go to the worker as the browser reads them (each piece is followed by a
// call of this).
const payload = startPayload();
self.nckitData = () => payload.take();
const vertices = Number(document.getElementById("app").dataset.vertices || -1);
if (vertices >= 0) {
  try {
    startRenderer(vertices);
  } catch (error) {
    console.warn("nckit report: WebGL could not start early:", error);
  }
}
const parsed = document.readyState === "loading" ? new Promise((r) => document.addEventListener("DOMContentLoaded", r, { once: true })) : Promise.resolve();
parsed.then(() => start(t0, payload)).catch((error) => {
  console.error(error);
  document.getElementById("app").appendChild(el("pre", "error", "nckit report: " + (error && error.stack ? error.stack : error)));
});
