// PNG pixels for the tests: how much of an image is not background, and how two images differ.
import { PNG } from "pngjs";

export function decode(buffer) {
  return PNG.sync.read(Buffer.from(buffer));
}

//! Fraction of pixels farther than `tolerance` (max over RGB) from the colour at (0, 0).
export function nonBackgroundFraction(png, tolerance = 24) {
  const d = png.data;
  const bg = [d[0], d[1], d[2]];
  let count = 0;
  for (let i = 0; i < d.length; i += 4) {
    if (Math.max(Math.abs(d[i] - bg[0]), Math.abs(d[i + 1] - bg[1]), Math.abs(d[i + 2] - bg[2])) > tolerance) count++;
  }
  return count / (png.width * png.height);
}

//! Fraction of pixels whose colours differ by more than `tolerance` in some channel; 1 when the
//! sizes differ.
export function differingFraction(a, b, tolerance = 48) {
  if (a.width !== b.width || a.height !== b.height) return 1;
  let count = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    if (Math.max(Math.abs(a.data[i] - b.data[i]), Math.abs(a.data[i + 1] - b.data[i + 1]), Math.abs(a.data[i + 2] - b.data[i + 2])) > tolerance) count++;
  }
  return count / (a.width * a.height);
}

//! Whether a pixel near (x, y) (within r) is close to rgb.
export function hasColorNear(png, x, y, rgb, r = 4, tolerance = 60) {
  for (let dy = -r; dy <= r; dy++) {
    for (let dx = -r; dx <= r; dx++) {
      const px = Math.round(x + dx), py = Math.round(y + dy);
      if (px < 0 || py < 0 || px >= png.width || py >= png.height) continue;
      const i = 4 * (py * png.width + px);
      if (Math.max(Math.abs(png.data[i] - rgb[0]), Math.abs(png.data[i + 1] - rgb[1]), Math.abs(png.data[i + 2] - rgb[2])) <= tolerance) return true;
    }
  }
  return false;
}

//! Whether a pixel near (x, y) (within r) differs from the background (the colour at (0, 0)).
export function inkedNear(png, x, y, r = 1, tolerance = 24) {
  const d = png.data;
  return !hasColorNear(png, x, y, [d[0], d[1], d[2]], 0, tolerance) || [-r, r].some((k) => !hasColorNear(png, x + k, y, [d[0], d[1], d[2]], 0, tolerance) || !hasColorNear(png, x, y + k, [d[0], d[1], d[2]], 0, tolerance));
}
