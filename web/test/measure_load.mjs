// Time until a report page is interactive in Debian's chromium: from the start of navigation
// until the page has built everything and drawn its first frame (window.nckitReport.ready),
// and until its full path is drawn (drawn_ms; later than ready on a page that opens with a
// preview of its path).
// Usage: node web/test/measure_load.mjs PAGE.html [RUNS]   → one JSON line
import { launch, openPage } from "./browser.mjs";
import { cpuBetween, treeCpu } from "./process_cpu.mjs";

const [file, runsText] = process.argv.slice(2);
const runs = Number(runsText || 3);
const browser = await launch();
const times = [];
const cpu = [];
const browserCpu = [];
const drawn = [];
const drawnCpu = [];
let info = null;
try {
  for (let i = 0; i < runs; i++) {
    const before = treeCpu(browser.process().pid);
    const { page, errors, readyMs } = await openPage(browser, file);
    // CPU seconds of all of chromium's processes (page, GPU, browser) until the page was ready.
    browserCpu.push(Math.round(1000 * cpuBetween(before, treeCpu(browser.process().pid))));
    if (errors.length) throw new Error(errors.join(" | "));
    times.push(readyMs);
    // Until the GPU has drawn everything asked of it by the next animation frame (reading a
    // pixel of the 3D view waits for that): the same moment on a page whose ready does not
    // wait for the GPU, and on a page that opened with a preview, the full path drawn.
    const t1 = Date.now();
    await page.evaluate(async () => {
      await new Promise((resolve) => requestAnimationFrame(resolve));
      const canvas = window.nckitReport.canvas;
      const gl = canvas && (canvas.getContext("webgl2") || canvas.getContext("webgl"));
      if (gl) gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    });
    drawn.push(readyMs + Date.now() - t1);
    drawnCpu.push(Math.round(1000 * cpuBetween(before, treeCpu(browser.process().pid))));
    // Time the page's main thread spent in tasks (chromium's TaskDuration; waits included).
    const metrics = await page.metrics();
    cpu.push(Math.round(metrics.TaskDuration * 1000));
    info = await page.evaluate(() => ({
      moves: window.nckitReport.moves,
      drawnSegments: window.nckitReport.drawnSegments,
      startMs: Math.round(window.nckitReport.startMs),
      parsedMs: Math.round(window.nckitReport.parsedMs),
      payloadMs: Math.round(window.nckitReport.payloadMs),
      payloadTimings: window.nckitReport.payloadTimings,
      builtMs: Math.round(window.nckitReport.builtMs),
      buildMs: Math.round(window.nckitReport.buildMs),
      timings: window.nckitReport.timings,
      preview: window.nckitReport.preview || null,
      fullPathShown: window.nckitReport.fullPathShown ? window.nckitReport.fullPathShown() : true,
    }));
    // A click on the path is answered (picking over every drawn segment).
    const t0 = Date.now();
    await page.evaluate(() => {
      const r = window.nckitReport;
      const p = r.segmentScreenPoint(Math.floor(r.moves / 2));
      r.canvas.dispatchEvent(new PointerEvent("pointerdown", { clientX: p.x, clientY: p.y, bubbles: true }));
      r.canvas.dispatchEvent(new PointerEvent("pointerup", { clientX: p.x, clientY: p.y, bubbles: true }));
    });
    info.clickMs = Date.now() - t0;
    await page.close();
  }
} finally {
  await browser.close();
}
times.sort((a, b) => a - b);
cpu.sort((a, b) => a - b);
browserCpu.sort((a, b) => a - b);
drawn.sort((a, b) => a - b);
drawnCpu.sort((a, b) => a - b);
console.log(JSON.stringify({ browser_cpu_ms: browserCpu, drawn_cpu_ms: drawnCpu, drawn_ms: drawn, main_thread_ms: cpu, ready_ms: times, best_ms: times[0], median_ms: times[Math.floor(times.length / 2)], ...info }));
