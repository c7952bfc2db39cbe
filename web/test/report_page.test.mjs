// Browser test of nckit's pages: makes each with nckit, opens it in Debian's chromium and checks
// what a user sees. Usage (from the source folder; CTest passes these):
//   node web/test/report_page.test.mjs --nckit BIN --dir OUTDIR --specs pages.json [--only NAME] [--update]
// A spec: {"name", "make": [nckit args; "{page}" is the page], "plan": [nckit plan args] or null,
//          "reference": "docs/images/NAME.png"}; "{dir}" in any argument is OUTDIR.
import { execFileSync } from "node:child_process";
import { existsSync, mkdirSync, readFileSync, writeFileSync, statSync } from "node:fs";
import { resolve } from "node:path";
import { launch, openPage } from "./browser.mjs";
import { decode, differingFraction, hasColorNear, inkedNear, nonBackgroundFraction } from "./pixels.mjs";

const args = process.argv.slice(2);
const opt = (name) => (args.includes(name) ? args[args.indexOf(name) + 1] : undefined);
const nckit = resolve(opt("--nckit"));
const dir = resolve(opt("--dir"));
const only = opt("--only");
const update = args.includes("--update");
const specs = JSON.parse(readFileSync(opt("--specs"), "utf8")).filter((s) => !only || s.name === only);
// Pixels may differ by SwiftShader's rounding and text antialiasing; a change of layout, colour
// or geometry moves far more than this.
const SCREENSHOT_TOLERANCE = 0.01;
const MAGENTA = [255, 0, 255];
const DOT = [20, 20, 20]; // the dark rim of a dot

mkdirSync(dir, { recursive: true });
let failures = 0;
let passes = 0;

async function frames(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

async function testPage(browser, spec) {
  const pagePath = `${dir}/${spec.name}.html`;
  const fill = (a) => a.replaceAll("{dir}", dir).replaceAll("{page}", pagePath);
  const check = (ok, what) => {
    console.log(`${ok ? "ok  " : "FAIL"} ${spec.name}: ${what}`);
    if (ok) passes++;
    else failures++;
  };
  execFileSync(nckit, spec.make.map(fill), { stdio: ["ignore", "ignore", "inherit"] });
  check(existsSync(pagePath), `nckit ${spec.make[0]} wrote the page (${(statSync(pagePath).size / 1e6).toFixed(2)} MB)`);
  const plan = spec.plan ? JSON.parse(execFileSync(nckit, spec.plan.map(fill), { encoding: "utf8" })) : null;

  const { page, errors, readyMs } = await openPage(browser, pagePath);
  check(errors.length === 0, `loads with no console error (${readyMs} ms)${errors.length ? ": " + errors.join(" | ") : ""}`);
  const state = await page.evaluate(() => {
    const r = window.nckitReport;
    return { moves: r.moves, drawn: r.drawnSegments, charts: r.charts, cycle: r.cycleTimeText ? r.cycleTimeText() : null };
  });
  const shot = await page.screenshot({ type: "png" });
  writeFileSync(`${dir}/${spec.name}.png`, shot);

  if (plan) {
    check(state.cycle === plan.cycle_time_s.toFixed(6), `cycle time shown ${state.cycle} s = nckit plan --json's ${plan.cycle_time_s}`);
    check(state.moves === plan.moves, `moves in the page ${state.moves} = nckit plan's ${plan.moves}`);
    check(state.drawn === plan.moves, `drawn segments ${state.drawn} = moves ${plan.moves}`);
    const canvas = await page.$(".view3d canvas");
    await canvas.scrollIntoView();
    await frames(page);
    const box = await canvas.boundingBox();
    const inked = nonBackgroundFraction(decode(await canvas.screenshot({ type: "png" })));
    check(inked > 0.002, `3D view not blank (${(100 * inked).toFixed(2)} % of its pixels drawn)`);

    // Click moves in the 3D view: the move under the pointer is picked (where moves overlap on
    // screen, any of them) and the code pane marks its line.
    const candidates = [...new Set([0, 1, 2, 3, 4, 5].map((k) => Math.floor(((k + 0.5) * state.moves) / 6)))];
    let exact = 0;
    let clicked = 0;
    for (const m of candidates) {
      const p = await page.evaluate((m) => window.nckitReport.segmentScreenPoint(m), m);
      if (!(p.x > box.x + 2 && p.y > box.y + 2 && p.x < box.x + box.width - 2 && p.y < box.y + box.height - 2)) continue;
      await page.mouse.click(p.x, p.y);
      const got = await page.evaluate(
        (x, y) => {
          const r = window.nckitReport;
          const m = r.selectedMove;
          return { move: m, marked: r.markedLine(), own: m >= 0 ? r.lineOfMove(m)[1] : -1, px: m >= 0 ? r.distanceToMove(m, x, y) : Infinity };
        },
        p.x,
        p.y,
      );
      clicked++;
      if (got.move === m) exact++;
      check(got.move >= 0 && got.px <= 6 && got.marked === got.own,
        `click on move ${m + 1}: picks move ${got.move + 1}, drawn ${got.px.toFixed(1)} px from the pointer; the code pane marks its line ${got.marked}`);
    }
    // On a dense page (thousands of moves in a few hundred pixels) every pixel holds
    // several moves: any of them is a right answer, checked above.
    check(clicked >= 3 && (exact >= 1 || state.moves > 2000), `${clicked} moves clicked, ${exact} picked exactly (the others overlap on screen)`);

    // Click lines in the code pane: the line's first move is selected and drawn in magenta.
    for (const m of candidates.slice(0, 3)) {
      const [file, line] = await page.evaluate((m) => window.nckitReport.lineOfMove(m), m);
      const expected = await page.evaluate((f, l) => window.nckitReport.firstMoveOf(f, l), file, line);
      await page.evaluate((f, l) => window.nckitReport.showLine(f, l), file, line);
      await frames(page);
      const row = await page.$(`.code-line[data-line="${line}"]`);
      await row.scrollIntoView();
      const rb = await row.boundingBox();
      await page.mouse.click(rb.x + rb.width / 2, rb.y + rb.height / 2);
      await canvas.scrollIntoView();
      await frames(page);
      const now = await canvas.boundingBox();
      const selected = await page.evaluate(() => window.nckitReport.selectedMove);
      const p = await page.evaluate((m) => window.nckitReport.segmentScreenPoint(m), selected);
      const png = decode(await canvas.screenshot({ type: "png" }));
      const lit = hasColorNear(png, p.x - now.x, p.y - now.y, MAGENTA, 3, 40);
      check(selected === expected && lit, `click on line ${line}: selects move ${selected + 1} (its first move: ${expected + 1}), drawn in magenta there: ${lit}`);
    }

    // Moves drawn as dots (no length of their own: a move to where the tool stands, or one the
    // transitions of its two corners ate whole): each is visible where the page says it is, a
    // click on it selects it (over the lines through it) and the code pane marks its line.
    const dots = await page.evaluate(() => window.nckitReport.dotMoves());
    const rimmed = await page.evaluate(() => window.nckitReport.dotsRimmed);
    if (spec.dots !== undefined) check(dots.length === spec.dots, `${dots.length} move(s) drawn as dots (expected ${spec.dots})`);
    for (const m of dots.slice(0, 8)) {
      await page.evaluate(() => window.nckitReport.select(-1));
      await frames(page);
      const now = await canvas.boundingBox();
      const p = await page.evaluate((m) => window.nckitReport.segmentScreenPoint(m), m);
      const before = decode(await canvas.screenshot({ type: "png" }));
      // Something is drawn there; on the page made for dots (few, so each has a dark rim;
      // many, as in a fine raster, are small and in the path's colours) the dot's own rim.
      const seen = rimmed && spec.dots !== undefined ? hasColorNear(before, p.x - now.x, p.y - now.y, DOT, 3, 30) : inkedNear(before, p.x - now.x, p.y - now.y, 1);
      await page.mouse.click(p.x, p.y);
      await frames(page);
      const got = await page.evaluate(
        (x, y) => {
          const r = window.nckitReport;
          const m = r.selectedMove;
          return { move: m, marked: r.markedLine(), own: m >= 0 ? r.lineOfMove(m)[1] : -1, px: m >= 0 ? r.distanceToMove(m, x, y) : Infinity };
        },
        p.x,
        p.y,
      );
      const after = decode(await canvas.screenshot({ type: "png" }));
      const lit = hasColorNear(after, p.x - now.x, p.y - now.y, MAGENTA, 2, 40);
      // Dots of several moves at one place (a loop to the same point) overlap: any of them.
      check(seen && (got.move === m || got.px <= 1.5) && got.marked === got.own && lit,
        `dot of move ${m + 1}: drawn ${seen}, a click selects move ${got.move + 1} (drawn ${got.px.toFixed(1)} px from it), the code pane marks its line ${got.marked}, drawn in magenta ${lit}`);
    }

    // The slider places the tool where `nckit plan --trace` has it at the slider's time.
    const period = await page.evaluate(() => window.nckitReport.samplePeriod);
    const count = await page.evaluate(() => window.nckitReport.sampleCount);
    const k = Math.floor(count / 3);
    const slider = await page.$(".time-slider");
    await page.evaluate((k) => (document.querySelector(".time-slider").value = String(k - 1)), k);
    await slider.focus();
    await page.keyboard.press("ArrowRight");
    const tool = await page.evaluate(() => window.nckitReport.toolAt);
    const tracePath = `${dir}/${spec.name}.trace.csv`;
    execFileSync(nckit, [...spec.plan.filter((a) => a !== "--json").map(fill), "--trace", tracePath, "--period", String(period)]);
    const rows = readFileSync(tracePath, "utf8").trim().split("\n");
    const head = rows[0].split(",");
    const row = rows[1 + tool.index].split(",").map(Number);
    let worst = Math.abs(row[0] - tool.t);
    for (const [a, v] of Object.entries(tool.position)) worst = Math.max(worst, Math.abs(row[head.indexOf(a)] - v));
    check(tool.index === k && worst < 1e-9,
      `slider at step ${k}: the tool at t = ${tool.t.toFixed(6)} s is where nckit plan --trace has it (largest difference ${worst.toExponential(1)})`);

    // The axis charts are drawn once they come near the screen: scrolled to, there are four
    // (speed, velocity, acceleration, jerk) and the first is not blank.
    const before = await page.evaluate(() => window.nckitReport.chartsDrawn());
    await (await page.$(".charts")).scrollIntoView();
    await page.waitForFunction(() => window.nckitReport.chartsDrawn() > 0, { timeout: 120000, polling: 50 });
    await frames(page);
    const drawnCharts = await page.evaluate(() => window.nckitReport.chartsDrawn());
    const chartInk = nonBackgroundFraction(decode(await (await page.$(".charts canvas")).screenshot({ type: "png" })));
    check(drawnCharts === 4 && chartInk > 0.005,
      `axis charts: ${before} drawn before they were scrolled to, ${drawnCharts} after; the first not blank (${(100 * chartInk).toFixed(2)} % of its pixels drawn)`);
  } else {
    check(state.charts > 0, `${state.charts} process chart(s)`);
    const inked = nonBackgroundFraction(decode(await (await page.$(".process-charts canvas")).screenshot({ type: "png" })));
    check(inked > 0.005, `first chart not blank (${(100 * inked).toFixed(2)} % of its pixels drawn)`);
  }

  // Against the reviewed screenshot of the page as it opens.
  const reference = resolve(spec.reference);
  if (update || !existsSync(reference)) {
    writeFileSync(reference, shot);
    check(update, `reference ${spec.reference} written`);
  } else {
    const diff = differingFraction(decode(shot), decode(readFileSync(reference)));
    check(diff <= SCREENSHOT_TOLERANCE,
      `screenshot matches ${spec.reference}: ${(100 * diff).toFixed(3)} % of pixels differ (at most ${100 * SCREENSHOT_TOLERANCE} %)`);
  }
  await page.close();
}

const browser = await launch();
try {
  for (const spec of specs) await testPage(browser, spec);
} finally {
  await browser.close();
}
console.log(`${passes} passed, ${failures} failed`);
process.exit(failures || !specs.length ? 1 : 0);
