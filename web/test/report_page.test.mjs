// Browser test of one report page: makes it with nckit, opens it in Debian's chromium and checks
// what a user sees. Usage (from the source folder; CTest passes these):
//   node web/test/report_page.test.mjs --nckit BIN --dir OUTDIR --spec JSON [--update]
// spec: {"name", "make": [nckit args, "{page}" for the page], "plan": [nckit plan args] or null,
//        "reference": "docs/images/NAME.png"}; "{dir}" in any argument is OUTDIR.
import { execFileSync } from "node:child_process";
import { existsSync, mkdirSync, readFileSync, writeFileSync, statSync } from "node:fs";
import { resolve } from "node:path";
import { launch, openPage } from "./browser.mjs";
import { decode, differingFraction, hasColorNear, nonBackgroundFraction } from "./pixels.mjs";

const args = process.argv.slice(2);
const opt = (name) => args[args.indexOf(name) + 1];
const nckit = resolve(opt("--nckit"));
const dir = resolve(opt("--dir"));
const spec = JSON.parse(opt("--spec"));
const update = args.includes("--update");
// Pixels may differ by SwiftShader's rounding and font hinting; a layout or colour change moves
// far more than this.
const SCREENSHOT_TOLERANCE = 0.01;

mkdirSync(dir, { recursive: true });
const pagePath = `${dir}/${spec.name}.html`;
const fill = (a) => a.replaceAll("{dir}", dir).replaceAll("{page}", pagePath);
const failures = [];
function check(ok, what) {
  console.log(`${ok ? "ok  " : "FAIL"} ${spec.name}: ${what}`);
  if (!ok) failures.push(what);
}

execFileSync(nckit, spec.make.map(fill), { stdio: ["ignore", "ignore", "inherit"] });
check(existsSync(pagePath), `nckit ${spec.make[0]} wrote ${pagePath} (${(statSync(pagePath).size / 1e6).toFixed(2)} MB)`);
const plan = spec.plan ? JSON.parse(execFileSync(nckit, spec.plan.map(fill), { encoding: "utf8" })) : null;

const browser = await launch();
try {
  const { page, errors, readyMs } = await openPage(browser, pagePath);
  check(errors.length === 0, `no console error while loading (${readyMs} ms)${errors.length ? ": " + errors.join(" | ") : ""}`);
  const state = await page.evaluate(() => ({
    kind: window.nckitReport.kind,
    moves: window.nckitReport.moves,
    drawn: window.nckitReport.drawnSegments,
    charts: window.nckitReport.charts,
    cycle: window.nckitReport.cycleTimeText ? window.nckitReport.cycleTimeText() : null,
  }));

  const shot = await page.screenshot({ type: "png" });
  writeFileSync(`${dir}/${spec.name}.png`, shot);

  if (plan) {
    check(state.cycle === plan.cycle_time_s.toFixed(6), `cycle time shown ${state.cycle} s = nckit plan --json ${plan.cycle_time_s}`);
    check(state.moves === plan.moves, `moves in the page ${state.moves} = nckit plan ${plan.moves}`);
    check(state.drawn === plan.moves, `drawn segments ${state.drawn} = moves ${plan.moves}`);
    const canvas = await page.$("canvas");
    const canvasPng = decode(await canvas.screenshot({ type: "png" }));
    const box = await canvas.boundingBox();
    const inked = nonBackgroundFraction(canvasPng);
    check(inked > 0.002, `3D view not blank (${(100 * inked).toFixed(2)} % of its pixels drawn)`);

    // Click moves in the 3D view: the code pane must mark the line of the move picked.
    const candidates = [];
    for (let k = 0; k < 6; k++) candidates.push(Math.floor(((k + 0.5) * state.moves) / 6));
    let exact = 0;
    let clicked = 0;
    for (const m of candidates) {
      const p = await page.evaluate((m) => window.nckitReport.segmentScreenPoint(m), m);
      if (p.x < box.x + 2 || p.y < box.y + 2 || p.x > box.x + box.width - 2 || p.y > box.y + box.height - 2) continue;
      await page.mouse.click(p.x, p.y);
      const got = await page.evaluate(() => {
        const r = window.nckitReport;
        return { move: r.selectedMove, line: r.selectedLine, marked: r.markedLine(), own: r.selectedMove >= 0 ? r.lineOfMove(r.selectedMove)[1] : -1 };
      });
      clicked++;
      if (got.move === m) exact++;
      check(got.move >= 0 && got.marked === got.own, `click on move ${m + 1} picks move ${got.move + 1}, code pane marks its line ${got.marked}`);
    }
    check(clicked > 0 && exact >= Math.ceil(clicked / 2), `${exact} of ${clicked} clicks picked exactly the move clicked`);

    // Click lines in the code pane: their move is selected and drawn in magenta.
    for (const m of candidates.slice(0, 3)) {
      const [file, line] = await page.evaluate((m) => window.nckitReport.lineOfMove(m), m);
      const expected = await page.evaluate((f, l) => window.nckitReport.firstMoveOf(f, l), file, line);
      await page.evaluate((f, l) => window.nckitReport.showLine(f, l), file, line);
      const row = await page.$(`.code-line[data-line="${line}"]`);
      await row.click();
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      const selected = await page.evaluate(() => window.nckitReport.selectedMove);
      const p = await page.evaluate((m) => window.nckitReport.segmentScreenPoint(m), selected);
      const png = decode(await canvas.screenshot({ type: "png" }));
      const lit = hasColorNear(png, p.x - box.x, p.y - box.y, [255, 0, 255]);
      check(selected === expected && lit, `click on line ${line} selects move ${selected + 1} (expected ${expected + 1}), drawn in magenta: ${lit}`);
    }

    // The slider places the tool where `nckit plan --trace` has it at that time.
    const period = await page.evaluate(() => window.nckitReport.samplePeriod);
    const count = await page.evaluate(() => window.nckitReport.sampleCount);
    const k = Math.floor(count / 3);
    const slider = await page.$(".time-slider");
    await slider.focus();
    await page.evaluate((k) => {
      const s = document.querySelector(".time-slider");
      s.value = String(k - 1);
    }, k);
    await page.keyboard.press("ArrowRight");
    const tool = await page.evaluate(() => window.nckitReport.toolAt);
    const tracePath = `${dir}/${spec.name}.trace.csv`;
    execFileSync(nckit, [...spec.plan.filter((a) => a !== "--json").map(fill), "--trace", tracePath, "--period", String(period)]);
    const rows = readFileSync(tracePath, "utf8").trim().split("\n");
    const head = rows[0].split(",");
    const row = rows[1 + tool.index].split(",").map(Number);
    let worst = Math.abs(row[0] - tool.t);
    for (const [a, v] of Object.entries(tool.position)) worst = Math.max(worst, Math.abs(row[head.indexOf(a)] - v));
    check(tool.index === k && worst < 1e-9, `slider step ${k}: tool at t=${tool.t.toFixed(6)} s where nckit plan --trace has it (largest difference ${worst.toExponential(2)})`);
  } else {
    check(state.charts > 0, `${state.charts} process chart(s) drawn`);
  }

  // Against the reviewed screenshot.
  const reference = resolve(spec.reference);
  if (update || !existsSync(reference)) {
    writeFileSync(reference, shot);
    check(update, `reference ${spec.reference} written`);
  } else {
    const diff = differingFraction(decode(shot), decode(readFileSync(reference)));
    check(diff <= SCREENSHOT_TOLERANCE, `screenshot matches ${spec.reference} (${(100 * diff).toFixed(3)} % of pixels differ, at most ${100 * SCREENSHOT_TOLERANCE} %)`);
  }
} finally {
  await browser.close();
}
console.log(`${failures.length ? "FAILED" : "passed"}: ${spec.name}`);
process.exit(failures.length ? 1 : 0);
