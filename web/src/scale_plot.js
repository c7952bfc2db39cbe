// Drawings to scale (a section, the unrolled bore) on a plain canvas: the same length per pixel
// on both axes, NaN breaking a series into pieces, a few labelled ticks.
import { axisColors } from "./colors.js";

function ticks(lo, hi, count) {
  const raw = (hi - lo) / count;
  const mag = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 5, 10].map((f) => f * mag).find((s) => s >= raw);
  const out = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) out.push(+v.toPrecision(12));
  return out;
}

export function scalePlot(box, chart, blob, width) {
  const series = chart.series.map((s) => ({ name: s.name, x: blob(s.x), y: blob(s.y) }));
  let xmin = Infinity, xmax = -Infinity, ymin = Infinity, ymax = -Infinity;
  for (const s of series) {
    for (let k = 0; k < s.x.length; k++) {
      if (Number.isNaN(s.x[k]) || Number.isNaN(s.y[k])) continue;
      xmin = Math.min(xmin, s.x[k]), xmax = Math.max(xmax, s.x[k]);
      ymin = Math.min(ymin, s.y[k]), ymax = Math.max(ymax, s.y[k]);
    }
  }
  const margin = { left: 60, right: 16, top: 10, bottom: 44 };
  const pad = 0.03 * Math.max(xmax - xmin, ymax - ymin, 1e-9);
  xmin -= pad, xmax += pad, ymin -= pad, ymax += pad;
  const plotW = width - margin.left - margin.right;
  // Length per pixel, the same on both axes: the drawing fits the width and at most 520 px.
  const unit = Math.max((xmax - xmin) / plotW, (ymax - ymin) / 520);
  const plotH = Math.max(120, (ymax - ymin) / unit);
  const height = plotH + margin.top + margin.bottom;
  const canvas = document.createElement("canvas");
  canvas.width = width;
  canvas.height = height;
  box.appendChild(canvas);
  const g = canvas.getContext("2d");
  g.fillStyle = "#fff";
  g.fillRect(0, 0, width, height);
  const cy = (ymin + ymax) / 2;
  const cx = (xmin + xmax) / 2;
  const X = (x) => margin.left + plotW / 2 + (x - cx) / unit;
  const Y = (y) => margin.top + plotH / 2 - (y - cy) / unit;
  g.font = "11px 'DejaVu Sans', sans-serif";
  g.strokeStyle = "#e3e3e3";
  g.fillStyle = "#333";
  g.lineWidth = 1;
  g.textAlign = "center";
  for (const v of ticks(cx - (plotW / 2) * unit, cx + (plotW / 2) * unit, 8)) {
    g.beginPath(), g.moveTo(X(v), margin.top), g.lineTo(X(v), margin.top + plotH), g.stroke();
    g.fillText(String(v), X(v), margin.top + plotH + 14);
  }
  g.textAlign = "right";
  const yLo = cy - (plotH / 2) * unit, yHi = cy + (plotH / 2) * unit;
  for (const v of ticks(yLo, yHi, 6)) {
    g.beginPath(), g.moveTo(margin.left, Y(v)), g.lineTo(margin.left + plotW, Y(v)), g.stroke();
    g.fillText(String(v), margin.left - 4, Y(v) + 4);
  }
  g.textAlign = "center";
  g.fillText(chart.x_label, margin.left + plotW / 2, height - 8);
  g.save();
  g.translate(12, margin.top + plotH / 2);
  g.rotate(-Math.PI / 2);
  g.fillText(chart.y_label, 0, 0);
  g.restore();
  g.save();
  g.beginPath();
  g.rect(margin.left, margin.top, plotW, plotH);
  g.clip();
  series.forEach((s, i) => {
    g.strokeStyle = axisColors[i % axisColors.length];
    g.lineWidth = 1.5;
    g.beginPath();
    let pen = false;
    for (let k = 0; k < s.x.length; k++) {
      if (Number.isNaN(s.x[k]) || Number.isNaN(s.y[k])) {
        pen = false;
        continue;
      }
      if (pen) g.lineTo(X(s.x[k]), Y(s.y[k]));
      else g.moveTo(X(s.x[k]), Y(s.y[k]));
      pen = true;
    }
    g.stroke();
  });
  g.restore();
  const legend = document.createElement("div");
  legend.className = "scale-legend";
  legend.innerHTML = series.map((s, i) => `<span style="color:${axisColors[i % axisColors.length]}">━ </span>${s.name}`).join(" &nbsp; ");
  box.appendChild(legend);
}
