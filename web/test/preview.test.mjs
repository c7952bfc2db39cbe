// Browser test of a large page's first frame (docs/report.md, "a preview within 1 px"): a
// page of 120,000 moves (rows of Z waves) opens with a preview of its path, every inked pixel of the preview lies
// within 2 px (1 px of tolerance, 1 px of rasterising) of an inked pixel of the full path and
// the other way round, the full path replaces it at once, every move is drawn, and a click
// picks a move from the full path.
// Usage (from the source folder; CTest passes these): node web/test/preview.test.mjs --nckit BIN --dir OUTDIR
import { execFileSync } from "node:child_process";
import { mkdirSync } from "node:fs";
import { resolve } from "node:path";
import { launch, openPage } from "./browser.mjs";
import { decode } from "./pixels.mjs";

const args = process.argv.slice(2);
const opt = (name) => args[args.indexOf(name) + 1];
const nckit = resolve(opt("--nckit"));
const dir = resolve(opt("--dir"));
const program = "tests/report/programs/fine_raster.ngc";
mkdirSync(dir, { recursive: true });
let failures = 0;
const check = (ok, what) => {
  console.log(`${ok ? "ok  " : "FAIL"} preview: ${what}`);
  if (!ok) failures++;
};

//! Inked (not background) pixels of a canvas screenshot, as a 0/1 array.
function inked(png, tolerance = 24) {
  const d = png.data;
  const out = new Uint8Array(png.width * png.height);
  for (let i = 0; i < out.length; i++) {
    out[i] = Math.max(Math.abs(d[4 * i] - d[0]), Math.abs(d[4 * i + 1] - d[1]), Math.abs(d[4 * i + 2] - d[2])) > tolerance ? 1 : 0;
  }
  return out;
}

//! Fraction of a's inked pixels with no inked pixel of b within r pixels.
function strayFraction(a, b, width, height, r) {
  let stray = 0;
  let total = 0;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      if (!a[y * width + x]) continue;
      total++;
      let near = false;
      for (let dy = -r; dy <= r && !near; dy++) {
        for (let dx = -r; dx <= r && !near; dx++) {
          const px = x + dx, py = y + dy;
          near = px >= 0 && py >= 0 && px < width && py < height && b[py * width + px] === 1;
        }
      }
      if (!near) stray++;
    }
  }
  return total ? stray / total : 1;
}

const page = `${dir}/fine_raster.html`;
execFileSync(nckit, ["report", program, "-o", page], { stdio: ["ignore", "ignore", "inherit"] });
const plan = JSON.parse(execFileSync(nckit, ["plan", program, "--json"], { encoding: "utf8" }));
const browser = await launch();
try {
  const { page: tab, errors, readyMs } = await openPage(browser, page);
  check(errors.length === 0, `loads with no console error (${readyMs} ms)${errors.length ? ": " + errors.join(" | ") : ""}`);
  const state = await tab.evaluate(() => ({ preview: window.nckitReport.preview, moves: window.nckitReport.moves, drawn: window.nckitReport.drawnSegments }));
  const p = state.preview;
  check(p && p.tolerancePx === 1 && p.segments > 0 && p.segments < plan.moves / 4,
    `opens with a preview: ${p && p.segments} segments and ${p && p.dots} dots for ${plan.moves} moves, tolerance ${p && p.tolerancePx} px = ${p && p.toleranceMm.toFixed(4)} mm`);
  const frames = () => tab.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  await frames();
  check(await tab.evaluate(() => window.nckitReport.fullPathShown()), "the full path replaced the preview after the first frame");
  check(state.moves === plan.moves && state.drawn === plan.moves, `drawn segments and dots ${state.drawn} = moves ${state.moves} = nckit plan's ${plan.moves}`);

  const canvas = await tab.$(".view3d canvas");
  const shot = async () => decode(await canvas.screenshot({ type: "png" }));
  const full = await shot();
  await tab.evaluate(() => window.nckitReport.showPreview(true));
  await frames();
  const preview = await shot();
  await tab.evaluate(() => window.nckitReport.showPreview(false));
  await frames();
  const { width, height } = full;
  const a = inked(preview);
  const b = inked(full);
  const fromPreview = strayFraction(a, b, width, height, 2);
  const fromFull = strayFraction(b, a, width, height, 2);
  check(fromPreview < 0.001 && fromFull < 0.001,
    `preview and full path within 2 px of each other: ${(100 * fromPreview).toFixed(3)} % of the preview's inked pixels and ${(100 * fromFull).toFixed(3)} % of the full path's have none of the other within 2 px`);

  // A click in the middle of the path picks a move there (the full path's picking).
  const m = Math.floor(plan.moves / 2);
  const at = await tab.evaluate((m) => window.nckitReport.segmentScreenPoint(m), m);
  await tab.mouse.click(at.x, at.y);
  const got = await tab.evaluate((x, y) => {
    const r = window.nckitReport;
    return { move: r.selectedMove, px: r.selectedMove >= 0 ? r.distanceToMove(r.selectedMove, x, y) : Infinity, line: r.markedLine() };
  }, at.x, at.y);
  check(got.move >= 0 && got.px <= 6 && got.line > 0, `click on move ${m + 1}: picks move ${got.move + 1}, drawn ${got.px.toFixed(1)} px from the pointer, line ${got.line} marked`);
} finally {
  await browser.close();
}
console.log(failures ? `${failures} failed` : "all passed");
process.exit(failures ? 1 : 0);
