// Shared by the browser tests and the benchmark: Debian's chromium, headless, through
// puppeteer-core (which never downloads a browser of its own).
import puppeteer from "puppeteer-core";
import { existsSync } from "node:fs";

export function chromiumPath() {
  for (const p of [process.env.CHROMIUM, "/usr/bin/chromium", "/usr/bin/chromium-browser"]) {
    if (p && existsSync(p)) return p;
  }
  throw new Error("chromium not found: run scripts/deps.sh (Debian package chromium)");
}

export async function launch() {
  return puppeteer.launch({
    executablePath: chromiumPath(),
    headless: true,
    // --no-sandbox: tests run as root in CI, where chromium's sandbox cannot start.
    // SwiftShader: WebGL on the CPU, the same pixels on every machine without a GPU.
    args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-gpu-sandbox",
      "--font-render-hinting=none", "--hide-scrollbars"],
    defaultViewport: { width: 1200, height: 820, deviceScaleFactor: 1 },
    timeout: 60000,
  });
}

//! Opens a page, recording every console error and uncaught exception.
export async function openPage(browser, file) {
  const page = await browser.newPage();
  const errors = [];
  page.on("console", (m) => {
    if (m.type() === "error") errors.push("console: " + m.text());
  });
  page.on("pageerror", (e) => errors.push("page: " + e.message));
  page.on("requestfailed", (r) => errors.push("request failed: " + r.url().slice(0, 80)));
  const t0 = Date.now();
  await page.goto("file://" + file, { waitUntil: "load", timeout: 120000 });
  await page.waitForFunction(() => window.nckitReport && window.nckitReport.ready, { timeout: 120000, polling: 50 });
  return { page, errors, readyMs: Date.now() - t0 };
}
