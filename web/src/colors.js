// Speed colours: a perceptually ordered ramp (dark blue → green → yellow → red), so slow places
// stand out without a legend lookup.
const stops = [
  [0.0, [0.19, 0.07, 0.23]],
  [0.15, [0.27, 0.35, 0.87]],
  [0.35, [0.1, 0.75, 0.85]],
  [0.55, [0.35, 0.95, 0.35]],
  [0.75, [0.98, 0.8, 0.2]],
  [0.9, [0.95, 0.4, 0.1]],
  [1.0, [0.7, 0.05, 0.02]],
];

export function speedColor(f, out, at) {
  f = Math.min(1, Math.max(0, f));
  let i = 1;
  while (i < stops.length - 1 && stops[i][0] < f) i++;
  const [f0, c0] = stops[i - 1];
  const [f1, c1] = stops[i];
  const w = (f - f0) / (f1 - f0 || 1);
  out[at] = c0[0] + w * (c1[0] - c0[0]);
  out[at + 1] = c0[1] + w * (c1[1] - c0[1]);
  out[at + 2] = c0[2] + w * (c1[2] - c0[2]);
}

export function cssColor(f) {
  const c = [0, 0, 0];
  speedColor(f, c, 0);
  return `rgb(${Math.round(c[0] * 255)},${Math.round(c[1] * 255)},${Math.round(c[2] * 255)})`;
}

export const axisColors = ["#e6194b", "#3cb44b", "#4363d8", "#f58231", "#911eb4", "#46a0a0", "#a0a046", "#808080", "#000080"];
